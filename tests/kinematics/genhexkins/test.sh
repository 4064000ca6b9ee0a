. ../lib.sh
halcmd loadrt genhexkins || exit 1
kinstest_load 6
halcmd setp kinstest.home.z 20
halcmd start
setpos 1 2 20 5 -3 10
setjoints 29.609853 31.186948 26.903655 32.985476 28.709495 29.864053
settle
show kinstest.type kinstest.switchable kinstest.joint.0.out kinstest.joint.1.out kinstest.joint.2.out kinstest.joint.3.out kinstest.joint.4.out kinstest.joint.5.out kinstest.pos.x.out kinstest.pos.y.out kinstest.pos.z.out kinstest.pos.a.out kinstest.pos.b.out kinstest.pos.c.out kinstest.fwd.result genhexkins.fwd-kins-fail genhexkins.x genhexkins.c
echo "iterations within limit: $(($(halcmd getp genhexkins.max-iterations) <= 120))"
phase=fail:
halcmd setp kinstest.joint.3.in 0
settle
show kinstest.fwd.result genhexkins.fwd-kins-fail
halcmd setp kinstest.joint.3.in 32.985476
phase=identity:
halcmd setp kinstest.switch-type 1
settle
show kinstest.switch-result kinstest.joint.0.out kinstest.joint.5.out kinstest.pos.x.out
halrun -U
