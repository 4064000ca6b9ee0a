# The tool table round trip (G10 L1 rewrites the file through iocontrol, remarks
# kept; an edited file is reloaded with LOAD_TOOL_TABLE) and the parameter file kept
# across task runs (#500 set, task restarted, #500 read back).
. ../lib.sh
# numbered parameters outside the persistent ranges are kept when the file has them
printf '500\t0.000000\n' > "$T/sim.var"
task_start
machine_ready
bus mdi G10 L1 P1 Z12.5 || exit 1
bus wait tool.0 "T1 P1 Z+12.500000 D+6.000000 ;6 mm end mill" 5 || exit 1
echo "-- tool table after G10 L1 P1 Z12.5"
cat "$T/sim.tbl"
echo "T9 P9 Z1 ;added by hand" >> "$T/sim.tbl"
bus load_tool_table || exit 1
bus status tool.count tool.3
echo "-- parameter file"
bus mdi '#500=42.5' || exit 1
halcmd unloadusr inihal || exit 1
grep '^500' "$T/sim.var"
halcmd loadusr -Wn inihal milltask -ini "$INI" -bus "$BUS" || exit 1
bus wait task.motion_ready 1 10 || exit 1
bus wait io.connected 1 10 || exit 1
machine_ready
bus mdi '(DEBUG, value #500)' || exit 1
task_stop
