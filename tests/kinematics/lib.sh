# lib.sh - sourced by the kinematics cases' test.sh (cwd: the case directory).
# kinstest_start [JOINTS]: a 1 ms thread running kinstest.update (load the
# kinematics module first); kinstest_load: the same, not started yet. settle: wait (up to 10 s) for two more updates, so the
# outputs reflect the inputs set before. show PIN...: one "PIN VALUE" line each.
phase=
kinstest_load() {
	halcmd loadrt threads name1=t period1=1000000 || exit 1
	halcmd loadrt kinstest joints=${1:-9} || exit 1
	halcmd addf kinstest.update t || exit 1
}
kinstest_start() {
	kinstest_load "$@"
	halcmd start || exit 1
}
settle() {
	target=$(($(halcmd getp kinstest.cycles) + 2))
	i=0
	while [ "$(halcmd getp kinstest.cycles)" -lt $target ] && [ $i -lt 400 ]; do
		sleep 0.025
		i=$((i + 1))
	done
}
show() {
	for p in "$@"; do
		echo "$phase$p $(halcmd getp "$p")"
	done
}
# setpos X Y Z [A B C U V W]: the inverse's input pose
setpos() {
	for l in x y z a b c u v w; do
		[ $# -gt 0 ] || break
		halcmd setp kinstest.pos.$l.in "$1"
		shift
	done
}
# setjoints J0 J1 ...: the forward's input joints
setjoints() {
	n=0
	for v in "$@"; do
		halcmd setp kinstest.joint.$n.in "$v"
		n=$((n + 1))
	done
}
