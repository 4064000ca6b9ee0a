# The machine's subcommands, each SET's effect and each GET's reply: estop, machine,
# mode, jog (joint and axis, continuous and incremental, stop), home, joint_*,
# teleop_enable, positions, mist/flood/lube/lube_level (iocontrol's pins), spindle
# and brake (motion's pins), spindle_override, feed_override, tool, tool_offset and
# load_tool_table (the table file), override_limits, optional_stop, probe_value/
# probe_tripped/probe_clear, kinematics_type and the units. Between some lines the
# script waits for the machine (homing, a jog) with emcbus, and checks pins and files
# ("check: ..."): rsh_client runs those "!sh" lines in their place in the script.
. ../lib.sh
machine_start
rsh_start
# pause KEY VALUE SECONDS / check CMD: done by rsh_client in the script's order
pause() {
	echo "!sh emcbus -bus $BUS wait $* > /dev/null 2>&1 || echo 'check: wait $* failed'"
}
check() {
	echo "!sh echo \"check: $1 \$($2)\""
}
run() {
	echo "!sh $*"
}
printf 'T5 P5 D+3.000000 ;other table\n' > "$T/other.tbl"
{
	echo "hello EMC tester 1.0"
	echo "set echo off"
	echo "set enable EMCTOO"
	echo "set set_wait done"
	echo "get probe_value"
	echo "get estop"
	echo "get machine"
	echo "set machine on"
	echo "set estop off"
	echo "get estop"
	echo "set machine on"
	echo "get machine"
	echo "get mode"
	echo "get joint_homed"
	echo "set jog 1 -600"
	pause traj.jogging 1 10
	echo "set jog_stop 1"
	pause traj.jogging 0 10
	check "joint 1 jogged down:" "emcbus -bus $BUS status joint.1.pos_fb | sed 's/^-.*/yes/'"
	echo "set jog x 60"
	echo "set home -1"
	pause traj.all_homed 1 10
	pause traj.mode TELEOP 10
	echo "get joint_homed"
	echo "get joint_homed 2"
	echo "get teleop_enable"
	echo "set jog 0 60"
	echo "set teleop_enable off"
	pause traj.mode FREE 10
	echo "get teleop_enable"
	echo "set jog_incr 0 600 2.5"
	pause joint.0.pos_fb 2.500000 10
	echo "get joint_pos"
	echo "get joint_pos 0"
	echo "get joint_pos 3"
	echo "set teleop_enable on"
	pause traj.mode TELEOP 10
	echo "set jog_incr x -600 1"
	pause axis.x.pos_fb 1.500000 10
	echo "get abs_cmd_pos"
	echo "get abs_act_pos 0"
	echo "get rel_cmd_pos"
	echo "get rel_act_pos 1"
	echo "get pos_offset"
	echo "get pos_offset z"
	echo "get joint_limit"
	echo "get joint_limit 0"
	echo "get joint_fault"
	echo "get joint_type"
	echo "get joint_units"
	echo "get mist"
	echo "set mist on"
	echo "get mist"
	pause io.mist 1 10
	check iocontrol.0.coolant-mist "halcmd getp iocontrol.0.coolant-mist"
	echo "set mist off"
	echo "set flood on"
	echo "get flood"
	pause io.flood 1 10
	check iocontrol.0.coolant-flood "halcmd getp iocontrol.0.coolant-flood"
	echo "set flood off"
	echo "get flood"
	echo "get lube"
	echo "set lube off"
	echo "get lube"
	pause io.lube 0 10
	check iocontrol.0.lube "halcmd getp iocontrol.0.lube"
	echo "set lube on"
	run halcmd setp iocontrol.0.lube_level 0
	pause io.lube_level 0 10
	echo "get lube_level"
	run halcmd setp iocontrol.0.lube_level 1
	pause io.lube_level 1 10
	echo "get lube_level"
	echo "set lube_level ok"
	echo "get spindle"
	echo "set spindle forward"
	echo "get spindle"
	pause spindle.0.direction 1 10
	check spindle.0.speed-out "halcmd getp spindle.0.speed-out"
	echo "set spindle 0 reverse"
	echo "get spindle 0"
	pause spindle.0.direction -1 10
	check spindle.0.speed-out "halcmd getp spindle.0.speed-out"
	echo "set spindle increase"
	echo "set spindle constant"
	echo "set spindle off"
	echo "get spindle"
	echo "set spindle 1 forward"
	echo "get brake"
	echo "set brake on"
	echo "get brake"
	pause spindle.0.brake 1 10
	check spindle.0.brake "halcmd getp spindle.0.brake"
	echo "set brake 0 off"
	echo "get brake 0"
	echo "get spindle_override"
	echo "set spindle_override 80"
	echo "get spindle_override 0"
	echo "set spindle_override 0 100"
	echo "get feed_override"
	echo "set feed_override 50"
	echo "get feed_override"
	echo "set feed_override 500"
	echo "get feed_override"
	echo "set feed_override 100"
	echo "get tool"
	echo "get tool_offset"
	echo "set tool_offset 1 12.5 6"
	check "table:" "grep '^T1 ' $T/sim.tbl"
	echo "set load_tool_table $T/other.tbl"
	pause tool.count 1 10
	check tool.count "emcbus -bus $BUS status tool.count"
	echo "set load_tool_table $T/sim.tbl"
	echo "get override_limits"
	echo "set override_limits on"
	echo "get override_limits"
	echo "set override_limits off"
	echo "get override_limits"
	echo "get optional_stop"
	echo "set optional_stop 0"
	echo "get optional_stop"
	echo "set optional_stop 1"
	echo "get optional_stop"
	echo "get kinematics_type"
	run halcmd setp motion.probe-input 1
	pause traj.probe_val 1 10
	echo "get probe_value"
	echo "get probe_tripped"
	echo "set probe_clear"
	echo "get program_units"
	echo "get program_linear_units"
	echo "get program_angular_units"
	echo "get user_linear_units"
	echo "get user_angular_units"
	echo "get display_linear_units"
	echo "get display_angular_units"
	echo "set estop on"
	echo "get estop"
	echo "get machine"
	echo "set joint_pos 1"
	echo "quit"
} | rsh
machine_stop
