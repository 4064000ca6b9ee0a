. ../lib.sh
halcmd loadrt scarakins || exit 1
kinstest_start 6
setjoints 30 45 100 10 0 0
setpos 585.739829 100.937452 390 0 0 -5
halcmd setp kinstest.inv.iflags 1
settle
show kinstest.pos.x.out kinstest.pos.y.out kinstest.pos.z.out kinstest.pos.c.out kinstest.fwd.iflags kinstest.joint.0.out kinstest.joint.1.out kinstest.joint.2.out kinstest.joint.3.out
phase=elbow0:
halcmd setp kinstest.inv.iflags 0
settle
show kinstest.joint.0.out kinstest.joint.1.out
phase=identity:
halcmd setp kinstest.switch-type 1
settle
show kinstest.switch-result kinstest.joint.0.out kinstest.pos.x.out
phase=user:
halcmd setp kinstest.switch-type 2
settle
show kinstest.switch-result
halrun -U
