# halsampler FILENAME writes there; -n COUNT exits with status 0; sample-num set by setp.
cat > "$TEST_TMPDIR/setup.hal" <<HAL
loadrt threads name1=thread period1=1000000
loadrt streamer depth=8 cfg=u
loadrt sampler depth=8 cfg=u
net u streamer.0.pin.0 => sampler.0.pin.0
addf streamer.0 thread
addf sampler.0 thread
setp sampler.0.sample-num 100
loadusr -w halstreamer data
start
loadusr -w halsampler -t -n 2 $TEST_TMPDIR/out.txt
HAL
halrun -f "$TEST_TMPDIR/setup.hal"
echo "halrun exit $?"
cat "$TEST_TMPDIR/out.txt"
