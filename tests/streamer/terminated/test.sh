# SIGTERM ends halstreamer with exit status 1 while it waits for input and while
# it waits for room in a full FIFO; end of input gives 0.
cat > "$TEST_TMPDIR/kill.sh" <<'SH'
sleep 2 | halstreamer &
pid=$!
sleep 0.3
kill -TERM $pid
wait $pid
echo "waiting for input: exit $?"
seq 1 10 | halstreamer &
pid=$!
sleep 0.3
kill -TERM $pid
wait $pid
echo "waiting for room: exit $?"
SH
cat > "$TEST_TMPDIR/test.hal" <<HAL
loadrt streamer depth=2 cfg=u
loadusr -w sh $TEST_TMPDIR/kill.sh
HAL
halrun -f "$TEST_TMPDIR/test.hal"
echo "halrun exit $?"
