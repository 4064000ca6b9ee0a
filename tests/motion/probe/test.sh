# Probing (motion.md 13, 7.1 PROBE): motion.probe-input is TRUE while X > comp.0.in0.
# A probe move stops at the trip (decelerating) with the world feedback of the trip
# period in status (probed-pos); G38.3/G38.5 end without an error when no contact
# comes, G38.2/G38.4 with motion.md's messages; a probe already in the target state
# refuses the move; a trip during a non-probe move aborts it, during jogs stops them.
. ../lib.sh
. ../../helpers/wait-getp.sh
motion_load 3
halcmd loadrt comp count=1 || exit 1
halcmd addf comp.0 servo-thread || exit 1
halcmd net xfb joint.0.pos-fb comp.0.in1 || exit 1
halcmd net probe comp.0.out motion.probe-input || exit 1
halcmd setp comp.0.in0 5 || exit 1
halcmd start || exit 1
motion_config 3 10 100
x() { halcmd getp joint.0.pos-cmd; }
probe() { motcmd status | grep '^probe value'; }
probed_x() { printf '%.4f' "$(motcmd status | grep '^probed-pos' | cut -d' ' -f3)"; }
# inside LO HI VALUE: prints yes when LO <= VALUE <= HI
# probe_move ID TYPE X: a probe move along X, waited for, and the probe status
probe_move() {
	motcmd --id "$1" probe "$2" "$3" 0 0 10 100 || exit 1
	motcmd wait-inpos 5 || exit 1
	probe
}
inside() { awk -v lo="$1" -v hi="$2" -v v="$3" 'BEGIN { print (v + 0 >= lo + 0 && v + 0 <= hi + 0) ? "yes" : "no (" v ")" }'; }
motion_coord
echo "== G38.2 toward X 10, contact above X 5"
probe_move 1 0 10
echo "probed x in [5, 5.03]: $(inside 5 5.03 "$(probed_x)")"
echo "stopped within the stopping distance after it: $(inside 5.01 5.55 "$(x)")"
echo "queue depth $(motcmd status | sed -n 3p | cut -d' ' -f3)"
motcmd errors
echo "== G38.2 while the probe is tripped"
motcmd --id 2 probe 0 0 0 0 10 100
echo "status $?"
echo "== G38.4 (contact loss) toward X 0"
probe_move 3 2 0
echo "probed x in [4.97, 5]: $(inside 4.97 5 "$(probed_x)")"
echo "== G38.4 while the probe is not tripped"
motcmd --id 4 probe 2 0 0 0 10 100
echo "status $?"
echo "== G38.2 to X 3: no contact"
probe_move 5 0 3
echo "probed x $(probed_x)"
motcmd errors
echo "== G38.3 to X 2: no contact, no error"
probe_move 6 1 2
echo "probed x $(probed_x)"
motcmd errors
echo "== G38.4 to X 1 with the probe touching all along"
halcmd setp comp.0.in0 -100 || exit 1
wait_getp motion.probe-input TRUE || exit 1
probe_move 7 2 1
motcmd errors
echo "== G38.5 to X 0: no error"
probe_move 8 3 0
echo "X $(x)"
motcmd errors
echo "== a line through the contact at X 0.5"
halcmd setp comp.0.in0 0.5 || exit 1
wait_getp motion.probe-input FALSE || exit 1
motcmd --id 9 line 2 0 0 10 100 || exit 1
motcmd wait-inpos 5 || exit 1
echo "aborted before its end: $(inside 0.5 1.1 "$(x)")"
echo "queue depth $(motcmd status | sed -n 3p | cut -d' ' -f3)"
motcmd errors
echo "== a joint jog through the contact at X 1.5"
halcmd setp comp.0.in0 1.5 || exit 1
wait_getp motion.probe-input FALSE || exit 1
motcmd free || exit 1
motcmd wait-state free 5 || exit 1
motcmd jog-abs 0 3 10 || exit 1
motcmd wait-inpos 5 || exit 1
echo "stopped: $(inside 1.5 2.1 "$(x)")"
motcmd errors
echo "== a coordinate jog through the contact at X 2.5"
halcmd setp comp.0.in0 2.5 || exit 1
wait_getp motion.probe-input FALSE || exit 1
motcmd teleop || exit 1
motcmd wait-state teleop 5 || exit 1
motcmd jog-abs x 4 10 || exit 1
motcmd wait-inpos 5 || exit 1
echo "stopped: $(inside 2.5 3.1 "$(x)")"
motcmd errors
halrun -U
