# SIGTERM/SIGINT end halsampler cleanly with exit status 1 (no -n: it always
# fails when terminated); with -n it is also 1 when COUNT was not reached.
cat > "$TEST_TMPDIR/kill.sh" <<'SH'
for sig in TERM INT; do
	halsampler > "$TEST_TMPDIR/out" &
	pid=$!
	sleep 0.3
	kill -$sig $pid
	wait $pid
	echo "SIG$sig: exit $?"
done
halsampler -n 100000 > /dev/null &
pid=$!
sleep 0.3
kill -TERM $pid
wait $pid
echo "-n, SIGTERM: exit $?"
SH
cat > "$TEST_TMPDIR/test.hal" <<HAL
loadrt threads name1=thread period1=1000000
loadrt sampler depth=100 cfg=b
addf sampler.0 thread
start
loadusr -w sh $TEST_TMPDIR/kill.sh
HAL
halrun -f "$TEST_TMPDIR/test.hal"
echo "halrun exit $?"
