# A program through halui: program.run (from MANUAL: halui switches to AUTO), pause
# (motion holds, is-paused), resume, stop; step from idle (from MDI mode: halui
# switches to AUTO) and step again; abort;
# optional-stop and block-delete switches; program.run with no program open is
# refused with a message.
. ../lib.sh
machine_start
machine_on
bus mode auto || exit 1
bus open "$PWD/../common/prog.ngc" || exit 1
press mode.manual
bus wait task.mode MANUAL 5 || exit 1
press program.run
wait_pin program.is-running TRUE
echo "run: mode $(bus status task.mode) idle $(pin program.is-idle) auto $(pin mode.is-auto)"
sleep 0.3
press program.pause
wait_pin program.is-paused TRUE
bus wait traj.current_vel 0.000000 5 || exit 1
a=$(halcmd getp joint.0.pos-cmd)
sleep 0.3
b=$(halcmd getp joint.0.pos-cmd)
[ "$a" = "$b" ] && echo "paused: X holds, running $(pin program.is-running)" || echo "paused: X moved from $a to $b"
press program.resume
wait_pin program.is-running TRUE
sleep 0.3
c=$(halcmd getp joint.0.pos-cmd)
awk -v b="$b" -v c="$c" 'BEGIN { print (c != b) ? "resumed: X moves on" : "resumed: X still at " b }'
press program.stop
wait_pin program.is-idle TRUE
bus wait traj.current_vel 0.000000 5 || exit 1
echo "stopped: interp $(bus status task.interp)"
press mode.mdi
bus wait task.mode MDI 5 || exit 1
bus mdi G0 X0 || exit 1
press program.step
wait_pin program.is-paused TRUE 10
echo "step 1 (G21 G90 G94): mode $(bus status task.mode) X $(printf %.3f "$(halcmd getp joint.0.pos-cmd)")"
press program.step
bus wait joint.0.pos_cmd 10.000000 10 || exit 1
wait_pin program.is-paused TRUE 10
echo "step 2 (G1 X10): X $(printf %.3f "$(halcmd getp joint.0.pos-cmd)") paused $(pin program.is-paused)"
press abort
wait_pin program.is-idle TRUE
press program.optional-stop.on
press program.block-delete.on
wait_pin program.block-delete.is-on TRUE
echo "switches on: task $(bus status task.optional_stop task.block_delete | tr '\n' ' ')pins $(pin program.optional-stop.is-on) $(pin program.block-delete.is-on)"
press program.optional-stop.off
press program.block-delete.off
wait_pin program.block-delete.is-on FALSE
echo "switches off: task $(bus status task.optional_stop task.block_delete | tr '\n' ' ')pins $(pin program.optional-stop.is-on) $(pin program.block-delete.is-on)"
bus close || exit 1
press program.run
sleep 0.2
echo "no program: interp $(bus status task.interp)"
machine_stop
