# Backlash compensation adds exactly the backlash on reversal: motor-pos-cmd -
# pos-cmd is +backlash/2 after moving forward, -backlash/2 after moving back (so the
# motor travels the backlash more than the joint), reached within the comp filter's
# limits (half the joint's velocity and acceleration). A comp table replaces it.
. ../lib.sh
motion_load 1
motion_sample 0 backlash-filt
halcmd start || exit 1
motion_config 1 10 100
motcmd set-joint-backlash 0 0.2 || exit 1
motcmd enable || exit 1
show() {
	printf '%s: pos-cmd %.6f motor-pos-cmd %.6f backlash-filt %.6f\n' "$1" \
		"$(halcmd getp joint.0.pos-cmd)" "$(halcmd getp joint.0.motor-pos-cmd)" \
		"$(halcmd getp joint.0.backlash-filt)"
}
capture_start "$T/filt.txt"
motcmd jog-incr 0 1 5 || exit 1
motcmd wait-inpos 5 || exit 1
show forward
motcmd jog-incr 0 -1 5 || exit 1
motcmd wait-inpos 5 || exit 1
show back
capture_stop
echo "comp filter: $(motion_analyze 0.001 <"$T/filt.txt" | cut -d' ' -f1-4) (limits 5, 50)"
echo "== comp table"
cat >"$T/comp.txt" <<COMP
-10 -10.01 -9.98
0 0.02 -0.02
10 9.99 10.03
not a line: reading stops here
20 1 1
COMP
motcmd comp-file 0 "$T/comp.txt" 0 || exit 1
motcmd jog-abs 0 5 5 || exit 1
motcmd wait-inpos 5 || exit 1
show "forward to 5"
motcmd jog-abs 0 -5 5 || exit 1
motcmd wait-inpos 5 || exit 1
show "back to -5"
motcmd set-joint-comp 0 5 0 0
echo "out of order: $?"
motcmd errors
halrun -U
