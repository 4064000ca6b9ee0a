. ../lib.sh
halcmd loadrt trivkins coordinates=xyyz kinstype=b || exit 1
kinstest_start 4
setpos 1 2 3
setjoints 1 2 2.5 3
settle
show kinstest.type kinstest.switchable kinstest.fwd.result kinstest.inv.result
show kinstest.joint.0.out kinstest.joint.1.out kinstest.joint.2.out kinstest.joint.3.out
show kinstest.pos.x.out kinstest.pos.y.out kinstest.pos.z.out kinstest.pos.a.out kinstest.pos.b.out kinstest.pos.c.out
halcmd setp kinstest.switch-type 1
settle
show kinstest.switch-result
halrun -U
