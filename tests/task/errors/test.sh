# Interpreter errors reach every client with file and line: a program with an
# error on line 3 (run by one client while two others watch) and a bad MDI line.
# Garbage from a client does not disturb the others.
. ../lib.sh
task_start
{
machine_ready
bus watch 4 > "$T/w1" &
w1=$!
bus watch 4 > "$T/w2" &
w2=$!
sleep 0.3
bus mode auto || exit 1
bus open "$PWD/bad.ngc" || exit 1
bus run 2>/dev/null || exit 1
bus wait task.interp IDLE 10 2>/dev/null || exit 1
bus mode mdi 2>/dev/null || exit 1
bus mdi G1 X1 F100 G0
echo "mdi exit $?"
bus mode manual || exit 1
bus mdi G0 X0
echo "mdi in manual exit $?"
bus nonsense 2>&1
echo "exit $?"
bus status task.last_error | sed "s|$PWD/||"
wait $w1 $w2
for w in w1 w2; do
	echo "-- $w"
	sed "s|$PWD/||" "$T/$w"
done
} 2>&1 | sed "s|$PWD/||"
task_stop
