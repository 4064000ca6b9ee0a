# lib.sh - the simulated machine of the motion-homing tests (sourced by each test.sh).
# homing_machine N [ALIAS]: trivkins + motmod with N joints on a 1 ms servo thread;
# joint j looped back (motor-pos-cmd -> motor-pos-fb); comp.j is joint j's home
# switch, TRUE while the motor position is above comp.j.in0 (the test sets it); a
# sampler records every joint's home-state, then every motor-pos-cmd. ALIAS=emc2
# wires the switches through the EMC2 names (axis.N.home-sw-in).
homing_machine() {
	n=$1
	cfg=$(printf 's%.0s' $(seq 1 "$n"))$(printf 'f%.0s' $(seq 1 "$n"))
	sw=joint
	[ "${2:-}" = emc2 ] && sw=axis
	{
		echo "loadrt trivkins coordinates=$(echo xyzabcuvw | cut -c1-"$n")"
		echo "loadrt motmod servo_period_nsec=1000000 num_joints=$n"
		echo "loadrt comp count=$n"
		echo "loadrt sampler depth=40000 cfg=$cfg"
		j=0
		while [ "$j" -lt "$n" ]; do
			echo "net m$j joint.$j.motor-pos-cmd => joint.$j.motor-pos-fb comp.$j.in1 sampler.0.pin.$((n + j))"
			echo "net sw$j comp.$j.out => $sw.$j.home-sw-in"
			echo "net st$j joint.$j.home-state => sampler.0.pin.$j"
			echo "addf comp.$j servo-thread"
			j=$((j + 1))
		done
		echo "addf motion-command-handler servo-thread"
		echo "addf motion-controller servo-thread"
		echo "addf sampler.0 servo-thread"
	} | halcmd -f || exit 1
}

# joint_limits J: soft limits -10..10, 5 u/s, 50 u/s^2
joint_limits() {
	motcmd set-joint-limits "$1" -10 10 && motcmd set-joint-vel "$1" 5 &&
		motcmd set-joint-acc "$1" 50 || exit 1
}

# stop_and_sample FILE: stop the thread, write every sample taken to FILE
stop_and_sample() {
	halcmd stop
	halsampler -n "$(halcmd getp sampler.0.curr-depth)" > "$1"
}

# states FILE COLUMN: the home-state sequence in that column (1 = joint 0), repeats merged
states() {
	awk -v c="$2" '{ print $c }' "$1" | uniq | tr '\n' ' ' | sed 's/ $//'
	echo
}

# first_index FILE COLUMN VALUE: first sample number where the column has VALUE
first_index() {
	awk -v c="$2" -v v="$3" '$c == v { print NR; exit }' "$1"
}

# last_index_not FILE COLUMN VALUE: last sample number where the column is not VALUE
last_index_not() {
	awk -v c="$2" -v v="$3" '$c != v { n = NR } END { print n }' "$1"
}

# pos PIN DIGITS: a float pin rounded
pos() {
	printf "%s %.${2}f\n" "$1" "$(halcmd getp "$1")"
}
