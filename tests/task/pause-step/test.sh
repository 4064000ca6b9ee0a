# STEP runs one block at a time (PAUSED in between); RESUME continues; PAUSE holds
# motion where it is; ABORT stops the program short of its end, interpreter IDLE.
. ../lib.sh
task_start
machine_ready
bus mode auto || exit 1
bus open "$PWD/prog.ngc" || exit 1
for n in 1 2 3 4; do
	bus step || exit 1
	bus wait task.interp PAUSED 10 || exit 1
	echo "step $n: $(joints)"
done
bus resume || exit 1
sleep 0.5
bus pause || exit 1
bus wait traj.current_vel 0.000000 5 || exit 1
bus status task.interp traj.paused
a=$(halcmd getp joint.0.pos-cmd)
sleep 0.3
b=$(halcmd getp joint.0.pos-cmd)
[ "$a" = "$b" ] && echo "paused: X holds" || echo "paused: X moved from $a to $b"
awk -v x="$a" 'BEGIN { print (x > 5 && x < 50) ? "paused between 5 and 50" : "paused at " x }'
bus resume || exit 1
sleep 0.3
bus abort || exit 1
bus wait task.interp IDLE 5 || exit 1
bus wait traj.current_vel 0.000000 5 || exit 1
a=$(halcmd getp joint.0.pos-cmd)
sleep 0.3
b=$(halcmd getp joint.0.pos-cmd)
[ "$a" = "$b" ] && echo "aborted: X holds" || echo "aborted: X moved from $a to $b"
awk -v x="$a" 'BEGIN { print (x > 5 && x < 50) ? "aborted short of 50" : "aborted at " x }'
bus status task.interp task.queue traj.queue
task_stop
