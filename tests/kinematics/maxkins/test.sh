. ../lib.sh
halcmd loadrt maxkins || exit 1
kinstest_start 9
setpos 1 0.5 -0.2 0 30 90
settle
show kinstest.joint.0.out kinstest.joint.1.out kinstest.joint.2.out maxkins.pivot-length
phase=fwd:
setjoints 0.167 -1 -0.2892270364197822 0 30 90 0 0 0
settle
show kinstest.pos.x.out kinstest.pos.y.out kinstest.pos.z.out kinstest.pos.b.out kinstest.pos.c.out
phase=conv:
setpos 1 0.5 -0.2 0 30 0
halcmd setp maxkins.conventional-directions 1
settle
show kinstest.joint.0.out
halrun -U
