. ../lib.sh
halcmd loadrt trivkins || exit 1
kinstest_start 9
setpos 1 2 3 4 5 6 7 8 9
setjoints 0.1 -0.2 0.3 4 5 6 7 8 9
settle
show kinstest.type
show kinstest.joint.0.out kinstest.joint.1.out kinstest.joint.2.out kinstest.joint.3.out kinstest.joint.4.out kinstest.joint.5.out kinstest.joint.6.out kinstest.joint.7.out kinstest.joint.8.out
show kinstest.pos.x.out kinstest.pos.y.out kinstest.pos.z.out kinstest.pos.a.out kinstest.pos.b.out kinstest.pos.c.out kinstest.pos.u.out kinstest.pos.v.out kinstest.pos.w.out
halrun -U
