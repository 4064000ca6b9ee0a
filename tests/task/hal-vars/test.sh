# #<_hal[...]> and #<_ini[section]key> in programs task runs: a pin, a signal and a
# parameter read when the line is read (a changed signal gives the next line its
# new value), an INI value; an unknown name is an error naming it.
. ../lib.sh
task_start
machine_ready
halcmd newsig target float || exit 1
halcmd sets target 2.5 || exit 1
bus mdi '(DEBUG, enable #<_hal[motion.enable]> ini #<_ini[traj]max_linear_velocity> #<_ini[AXIS_Z]MIN_LIMIT>)' || exit 1
bus mdi '(DEBUG, param #<_hal[motion.debug-s32-0]> task #<_task>)' || exit 1
bus mdi 'G0 X#<_hal[target]>' || exit 1
joints
halcmd sets target -4 || exit 1
bus mdi 'G0 X[#<_hal[target]> * 2] Y#<_hal[joint.0.pos-cmd]>' || exit 1
joints
echo "-- in a program"
cat > "$T/p.ngc" <<'NGC'
o100 if [#<_hal[target]> LT 0]
  G1 Z#<_hal[target]> F600
o100 endif
G0 Y[#<_hal[joint.0.pos-cmd]> + 1]
M2
NGC
bus mode auto || exit 1
bus open "$T/p.ngc" || exit 1
bus run || exit 1
bus wait task.interp IDLE 10 || exit 1
joints
bus mode mdi || exit 1
echo "-- unknown name"
bus mdi '#1 = #<_hal[no.such.pin]>' > "$T/err" 2>&1
echo "exit $?"
sed 's/^emcbus: .*: //' "$T/err" | sort -u
task_stop
