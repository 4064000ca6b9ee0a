. ../lib.sh
halcmd loadrt genserkins || exit 1
kinstest_start 9
setjoints 10 -20 30 15 25 -40 1 2 3
settle
show kinstest.pos.x.out kinstest.pos.y.out kinstest.pos.z.out kinstest.pos.a.out kinstest.pos.b.out kinstest.pos.c.out kinstest.pos.u.out kinstest.pos.v.out kinstest.pos.w.out
setpos 245.557888 114.378344 -299.999467 -158.069396 27.656272 39.874614 1 2 3
setjoints 8 -18 28 13 22 -37
settle
show kinstest.joint.0.out kinstest.joint.1.out kinstest.joint.2.out kinstest.joint.3.out kinstest.joint.4.out kinstest.joint.5.out kinstest.joint.6.out kinstest.joint.7.out kinstest.joint.8.out kinstest.inv.result genserkins.ALPHA-1
echo "iterations: $(($(halcmd getp genserkins.last-iterations) > 0 && $(halcmd getp genserkins.last-iterations) < 10))"
halcmd setp genserkins.max-iterations 0
settle
show kinstest.inv.result
halrun -U
