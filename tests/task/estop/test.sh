# Estop from HAL: during a long MDI move the external chain opens
# (iocontrol.0.emc-enable-in FALSE): motion stops and is disabled, task goes to
# ESTOP, the MDI command fails, and both watching clients get the error.
. ../lib.sh
task_start chain.hal
machine_ready
bus watch 6 > "$T/w1" &
w1=$!
bus watch 6 > "$T/w2" &
w2=$!
bus -t 20 mdi G1 X100 F600 > "$T/mdi.out" 2>&1 &
mdi=$!
sleep 1
halcmd sets ext-ok 0 || exit 1
wait $mdi
echo "mdi exit $?"
sed 's/^emcbus: .*: //' "$T/mdi.out" | sort -u
bus wait task.state ESTOP 5 || exit 1
a=$(halcmd getp joint.0.pos-cmd)
sleep 0.3
b=$(halcmd getp joint.0.pos-cmd)
[ "$a" = "$b" ] && echo "X holds" || echo "X moved from $a to $b"
awk -v x="$a" 'BEGIN { print (x > 1 && x < 100) ? "stopped short of 100" : "stopped at " x }'
bus status task.state traj.enabled io.estop user-enable-out 2>/dev/null
echo "user-enable-out $(halcmd getp iocontrol.0.user-enable-out)"
echo "-- a reset is refused while the chain is open"
bus state estop_reset
echo "exit $?"
echo "-- closed again: reset and on"
halcmd sets ext-ok 1 || exit 1
bus state estop_reset || exit 1
bus state on || exit 1
bus status task.state
wait $w1 $w2
echo "-- watcher 1"
grep -c 'ERROR emergency stop: iocontrol.0.emc-enable-in is FALSE' "$T/w1"
echo "-- watcher 2"
grep -c 'ERROR emergency stop: iocontrol.0.emc-enable-in is FALSE' "$T/w2"
task_stop
