. ../lib.sh
halcmd loadrt trivkins coordinates=XZ || exit 1
kinstest_load 2
halcmd setp kinstest.home.y 7
halcmd start
setpos 4 0 -2
setjoints 1.5 -3
settle
show kinstest.joint.0.out kinstest.joint.1.out kinstest.pos.x.out kinstest.pos.y.out kinstest.pos.z.out
halrun -U
