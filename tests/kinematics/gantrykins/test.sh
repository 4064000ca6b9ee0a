. ../lib.sh
halcmd loadrt gantrykins coordinates=XYYZ || exit 1
kinstest_start 4
setpos 1 2 3
setjoints 1 2 2.5 3
settle
show kinstest.type
for n in 0 1 2 3 4 8; do show gantrykins.joint-$n; done
show kinstest.joint.0.out kinstest.joint.1.out kinstest.joint.2.out kinstest.joint.3.out kinstest.pos.x.out kinstest.pos.y.out kinstest.pos.z.out
halcmd setp gantrykins.joint-3 0
settle
show kinstest.joint.3.out
halrun -U
