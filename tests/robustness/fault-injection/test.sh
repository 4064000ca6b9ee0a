# Fault injection: a halcmd killed anywhere in a big file (holding the HAL lock or
# not, in the middle of a loadrt or a net), or the realtime host killed during a run.
. ../lib.sh
rounds=${FAULT_ROUNDS:-100}
big="$TEST_TMPDIR/big.hal"
{
	echo "loadrt threads name1=t period1=1000000"
	echo "loadrt and2 count=400"
	i=0
	while [ $i -lt 399 ]; do
		echo "net s$i and2.$i.out and2.$((i + 1)).in0"
		echo "setp and2.$i.in1 1"
		echo "addf and2.$i t"
		i=$((i + 1))
	done
	echo "start"
} > "$big"
# a pseudo-random delay in ms from a seed (sh has no $RANDOM): 0..599
delay_ms() { echo $(( ($1 * 7919 + 104729) % 600 )); }

recovered=0
round=1
while [ $round -le "$rounds" ]; do
	halrun -U >/dev/null 2>&1
	halcmd -f "$big" >/dev/null 2>&1 &
	victim=$!
	ms=$(delay_ms $round)
	sleep "$(printf '%d.%03d' $((ms / 1000)) $((ms % 1000)))"
	if [ $((round % 10)) -eq 0 ]; then
		host=$(rtapi_app_pid) && kill_and_wait "$host"
	fi
	kill_and_wait "$victim"
	wait "$victim" 2>/dev/null
	# The next command: works, or names the way out; never hangs.
	out=$(timeout 30 halcmd show comp 2>&1)
	status=$?
	ok=no
	if [ $status -eq 0 ]; then
		ok=yes
	elif [ $status -ne 124 ] && echo "$out" | grep -q "halrun -U"; then
		ok=yes
	fi
	# ... and after the clean-up it says, everything works again.
	if [ $ok = yes ]; then
		timeout 30 halrun -U >/dev/null 2>&1
		if ! timeout 30 halcmd loadrt and2 || ! timeout 30 halcmd net x and2.0.out and2.0.in0; then
			ok=no
		fi
	fi
	if [ $ok = yes ]; then
		recovered=$((recovered + 1))
	else
		echo "round $round (kill after $ms ms): status $status: $out"
	fi
	round=$((round + 1))
done
halrun -U
echo "recovered $recovered/$rounds"
