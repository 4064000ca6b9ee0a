. ../lib.sh
halcmd loadrt tripodkins || exit 1
kinstest_start 3
setpos 0.2 0.3 0.9
settle
show kinstest.type kinstest.joint.0.out kinstest.joint.1.out kinstest.joint.2.out kinstest.inv.fflags
halcmd setp tripodkins.Bx 10
halcmd setp tripodkins.Cx 5
halcmd setp tripodkins.Cy 8
setpos 5 4 -10
setjoints 11.874342087037917 11.874342087037917 10.770329614269007
settle
show kinstest.joint.0.out kinstest.joint.1.out kinstest.joint.2.out kinstest.inv.fflags kinstest.pos.x.out kinstest.pos.y.out kinstest.pos.z.out
halcmd setp kinstest.fwd.fflags 1
settle
show kinstest.pos.z.out
halcmd setp tripodkins.Cy 0
settle
show kinstest.fwd.result
halrun -U
