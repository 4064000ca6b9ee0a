# SIGTERM/SIGINT end halsampler cleanly with exit status 1 (no -n: it always
# fails when terminated); with -n it is also 1 when COUNT was not reached.
# The signal is sent once halsampler prints (its handlers are installed by then): a
# background job of sh starts with SIGINT ignored, so a SIGINT that came before the
# handler (a slow start, e.g. under the sanitizers) would be lost and the test hang.
cat > "$TEST_TMPDIR/kill.sh" <<'SH'
printing() { i=0; while [ ! -s "$1" ] && [ $i -lt 600 ]; do sleep 0.05; i=$((i + 1)); done; }
for sig in TERM INT; do
	: > "$TEST_TMPDIR/out"
	halsampler > "$TEST_TMPDIR/out" &
	pid=$!
	printing "$TEST_TMPDIR/out"
	kill -$sig $pid
	wait $pid
	echo "SIG$sig: exit $?"
done
halsampler -n 100000 > "$TEST_TMPDIR/out-n" &
pid=$!
printing "$TEST_TMPDIR/out-n"
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
