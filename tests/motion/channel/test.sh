# The command channel refuses what a bad or hostile writer sends, and motion keeps
# running: an unknown command number, an out-of-range joint, a command number out of
# sequence (then the next writer continues from the echo), a second writer while the
# first one holds the channel; motcmd's own usage errors send nothing.
. ../lib.sh
motion_load 2
halcmd start || exit 1
motcmd raw 999
echo "status $?"
motcmd jog-cont 5 1
echo "status $?"
motcmd --force-number 1000 enable
echo "status $?"
motcmd enable
echo "status $?"
motcmd status | head -1 | cut -d' ' -f1-4
motcmd jog-cont 0 fast
echo "status $?"
motcmd --bogus
echo "status $?"
# a writer that holds the channel (claimed by its first command) while it waits
motcmd raw 5	# REVERSE: no reverse run
echo "reverse status $?"
motcmd raw 6	# FORWARD
echo "forward status $?"
printf 'free\nwait-state coord 3\n' >"$T/hold.cmd"
motcmd -f "$T/hold.cmd" >/dev/null &
holder=$!
i=0
while [ "$(motcmd status | sed -n 2p | cut -d' ' -f2)" != FREE ] && [ $i -lt 200 ]; do
	sleep 0.01
	i=$((i + 1))
done
motcmd disable >"$T/second.txt" 2>&1
echo "second writer status $?"
sed 's/pid [0-9]*/pid N/' "$T/second.txt"
wait $holder
motcmd disable
echo "after the holder: status $?"
halrun -U
