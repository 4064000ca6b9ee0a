# The same exact-period HAL three times: every run must print the same samples.
halrun -f interleave.hal > "$TEST_TMPDIR/run1" 2>&1 || { echo "run 1 failed"; cat "$TEST_TMPDIR/run1"; exit 1; }
cat "$TEST_TMPDIR/run1"
for n in 2 3; do
	halrun -f interleave.hal > "$TEST_TMPDIR/run$n" 2>&1 || { echo "run $n failed"; cat "$TEST_TMPDIR/run$n"; exit 1; }
	cmp -s "$TEST_TMPDIR/run1" "$TEST_TMPDIR/run$n" || { echo "run $n differs from run 1:"; diff "$TEST_TMPDIR/run1" "$TEST_TMPDIR/run$n"; exit 1; }
done
echo "3 runs identical"
