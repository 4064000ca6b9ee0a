. ../lib.sh
halcmd loadrt rotatekins || exit 1
kinstest_start 9
setpos 2 1 0 0 0 30
setjoints 1.2320508075688772 1.8660254037844386 3 0 0 30 0 0 0
settle
show kinstest.type kinstest.joint.0.out kinstest.joint.1.out kinstest.joint.2.out kinstest.joint.3.out kinstest.joint.4.out kinstest.joint.5.out kinstest.pos.x.out kinstest.pos.y.out kinstest.pos.z.out kinstest.pos.c.out
phase=2:
setpos 10 -5 0 0 0 -45
settle
show kinstest.joint.0.out kinstest.joint.1.out
halrun -U
