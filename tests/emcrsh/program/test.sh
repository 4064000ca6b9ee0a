# Programs and MDI through emcrsh: mdi (moves, G92/G10 offsets seen in pos_offset and
# rel_*_pos with the unit conversions, G20 in program_units, a (MSG,...) in
# operator_display, an error line's reason in error), program_codes, probe,
# task_plan_init, open (relative to -d), run, pause, resume, step, abort, program,
# program_status, program_line; RUN with no program open opens the last one again.
. ../lib.sh
machine_start
cat > "$T/prog.ngc" <<'NGC'
G21 G90
G0 X0 Y0 Z0
G1 X2 F600
G1 X4 F60
G1 X6 F600
M2
NGC
rsh_start -d "$T"
# pause KEY VALUE SECONDS / check CMD: done by rsh_client in the script's order
pause() {
	echo "!sh emcbus -bus $BUS wait $* > /dev/null 2>&1 || echo 'check: wait $* failed'"
}
{
	echo "hello EMC tester 1.0"
	echo "set echo off"
	echo "set enable EMCTOO"
	echo "set set_wait done"
	echo "set estop off"
	echo "set machine on"
	echo "set home -1"
	pause traj.all_homed 1 10
	echo "get program"
	echo "get program_status"
	echo "get program_line"
	echo "set mdi g0 x1"
	echo "set mode mdi"
	echo "set mdi g0 x10 y5"
	echo "get abs_cmd_pos"
	echo "get program_codes"
	echo "set mdi g1 f300 s1200 x11"
	echo "get program_codes"
	echo "set mdi g92 x0"
	echo "get pos_offset"
	echo "get pos_offset x"
	echo "get rel_cmd_pos"
	echo "get rel_act_pos 0"
	echo "set linear_unit_conversion cm"
	echo "get pos_offset x"
	echo "set linear_unit_conversion auto"
	echo "set mdi g92.1"
	echo "set mdi g10 l2 p1 y2"
	echo "get pos_offset"
	echo "get rel_cmd_pos 1"
	echo "set mdi g10 l2 p1 y0"
	echo "set mdi g20"
	echo "get program_units"
	echo "get display_linear_units"
	echo "set mdi g21"
	echo "set mdi (msg,hello operator)"
	echo "get operator_display"
	echo "set mdi g1 x"
	echo "get error"
	echo "set mdi g0 x0 y0 z0"
	echo "set probe 0 0 -2"
	echo "get abs_cmd_pos"
	echo "get probe_tripped"
	echo "set mode auto"
	echo "set open prog.ngc"
	echo "get program"
	echo "get program_status"
	echo "set task_plan_init"
	echo "set run"
	pause task.motion_line 4 30
	echo "set pause"
	echo "get program_status"
	echo "get program_line"
	echo "set resume"
	echo "get program_status"
	echo "set abort"
	pause task.interp IDLE 30
	echo "get program_status"
	echo "get program_line"
	echo "set feed_override 100"
	echo "set step"
	pause task.interp PAUSED 30
	echo "get program_status"
	echo "set abort"
	pause task.interp IDLE 30
	echo "set run"
	pause axis.x.pos_cmd 6.000000 60
	pause task.interp IDLE 60
	echo "get program_status"
	echo "get abs_cmd_pos 0"
	echo "set mode mdi"
	echo "set mdi g0 x0"
	echo "set mode auto"
	echo "get program"
	pause task.interp IDLE 30
	echo "get program_status"
	echo "set run 5"
	pause axis.x.pos_cmd 6.000000 60
	pause task.interp IDLE 60
	echo "get abs_cmd_pos 0"
	echo "get error"
	echo "quit"
} | rsh | sed "s|$T|T|g"
machine_stop
