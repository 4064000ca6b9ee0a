# The simulated mill (sim-mill.hal) loads unchanged, homes all joints through motcmd
# (Z first, then X and Y: each ends at its HOME with the switch at HOME_OFFSET), goes to
# teleop by itself, jogs an axis, and runs coordinated lines to their targets.
halcmd setexact_for_test_suite_only || exit 1
halcmd -f sim-mill.hal || exit 1
halcmd start || exit 1
show() {
	for j in 0 1 2; do
		printf 'joint %d pos-fb %.3f motor-offset %.2f homed %s home-state %s\n' $j \
			"$(halcmd getp joint.$j.pos-fb)" "$(halcmd getp joint.$j.motor-offset)" \
			"$(halcmd getp joint.$j.homed)" "$(halcmd getp joint.$j.home-state)"
	done
}
motcmd -f machine.cmd || exit 1
motcmd enable || exit 1
motcmd wait-state free 5 || exit 1
motcmd home all || exit 1
motcmd wait-homed 60 || exit 1
motcmd wait-state teleop 5 || exit 1
motcmd wait-inpos 10 || exit 1
echo "== homed"
show
motcmd status | head -1
echo "== teleop jog of X"
motcmd jog-incr x 2.5 10 || exit 1
motcmd wait-inpos 10 || exit 1
printf 'X %.4f\n' "$(halcmd getp axis.x.pos-cmd)"
echo "== coordinated lines"
motcmd coord || exit 1
motcmd wait-state coord 5 || exit 1
motcmd --id 10 line 20 -5 -2 15 150 || exit 1
motcmd --id 11 line 20 10 -2 15 150 || exit 1
motcmd wait-inpos 30 || exit 1
joints() {
	printf 'joints %.4f %.4f %.4f motors %.2f %.2f %.2f\n' "$(halcmd getp joint.0.pos-cmd)" \
		"$(halcmd getp joint.1.pos-cmd)" "$(halcmd getp joint.2.pos-cmd)" \
		"$(halcmd getp joint.0.motor-pos-cmd)" "$(halcmd getp joint.1.motor-pos-cmd)" \
		"$(halcmd getp joint.2.motor-pos-cmd)"
}
joints
motcmd --id 12 rapid 0 0 0 20 150 || exit 1
motcmd wait-inpos 30 || exit 1
joints
motcmd status | head -1
motcmd errors
halrun -U
