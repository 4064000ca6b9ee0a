. ../lib.sh
halcmd loadrt pumakins || exit 1
kinstest_start 6
setjoints 10 -20 30 15 25 -40
setpos 499.403719 -207.501834 -414.517994 155 0 -120
settle
show kinstest.pos.x.out kinstest.pos.y.out kinstest.pos.z.out kinstest.pos.a.out kinstest.pos.b.out kinstest.pos.c.out kinstest.fwd.iflags kinstest.joint.0.out kinstest.joint.1.out kinstest.joint.2.out kinstest.joint.3.out kinstest.joint.4.out kinstest.joint.5.out
phase=singular:
setjoints 0 0 0 12.5 0 0
setpos 350 70 -470 180 0 0
halcmd setp kinstest.inv.iflags 8
settle
show kinstest.fwd.iflags kinstest.pos.z.out kinstest.inv.fflags kinstest.joint.3.out
halrun -U
