# T2 M6 through iocontrol's handshake: tool-prepare/tool-prepared looped back, then
# tool-change stays raised (task waiting) until HAL answers tool-changed; the tool
# is then in the spindle (tool-number, status) and M6 is done.
. ../lib.sh
task_start handshake.hal
machine_ready
bus -t 20 mdi T2 M6 > "$T/mdi.out" 2>&1 &
mdi=$!
n=0
while [ "$(halcmd getp iocontrol.0.tool-change)" != TRUE ] && [ $n -lt 100 ]; do sleep 0.05; n=$((n + 1)); done
echo "tool-change $(halcmd getp iocontrol.0.tool-change) prep-number $(halcmd getp iocontrol.0.tool-prep-number) prep-pocket $(halcmd getp iocontrol.0.tool-prep-pocket)"
sleep 0.2
bus status task.interp io.tool_in_spindle
halcmd sets tool-changed 1 || exit 1
wait $mdi
echo "mdi exit $?"
cat "$T/mdi.out"
halcmd sets tool-changed 0
echo "tool-change $(halcmd getp iocontrol.0.tool-change) tool-number $(halcmd getp iocontrol.0.tool-number) from-pocket $(halcmd getp iocontrol.0.tool-from-pocket)"
bus wait io.tool_in_spindle 2 5 || exit 1
bus status io.tool_in_spindle task.interp
# M61 Q7 sets the tool number without a change
bus mdi M61 Q7 || exit 1
echo "after M61 Q7: tool-number $(halcmd getp iocontrol.0.tool-number)"
task_stop
