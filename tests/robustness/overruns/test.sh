# RTAPI_MSG_LEVEL: the runner silences warnings for the other tests; this one checks them.
export RTAPI_MSG_LEVEL=WARN
# rtapi_app keeps the stderr of the halcmd that started it when asked to (as halrun does)
export RTAPI_APP_STDERR=keep
halcmd loadrt threads name1=fast period1=1000 2> "$TEST_TMPDIR/host.err"
halcmd start
sleep 2
n=$(halcmd getp fast.overruns)
[ "$n" -gt 0 ] && echo "fast.overruns counts missed periods" || echo "fast.overruns is '$n'"
halcmd show thread | grep -q "missed periods (overruns): [1-9]" && echo "show thread shows them"
halcmd stop
halrun -U
grep -q "^rtapi_app: thread 'fast' (period 1000 ns) missed [0-9]* periods* in the last 1000 ms" "$TEST_TMPDIR/host.err" &&
	echo "rtapi_app warned"
