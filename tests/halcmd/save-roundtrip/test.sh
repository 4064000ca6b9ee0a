halrun -f build.hal || echo "build failed"
halrun -f resave.hal > "$TEST_TMPDIR/stdout.hal" || echo "resave failed"
cmp "$TEST_TMPDIR/first.hal" "$TEST_TMPDIR/second.hal" && echo "save all: identical after a round trip"
# Plain "save" is "save all" without the unconnected pin values and signal values.
awk '/^# (unconnected pin values|signal values)$/ { skip = 1; next } /^#/ { skip = 0 } !skip' \
	"$TEST_TMPDIR/first.hal" | cmp - "$TEST_TMPDIR/stdout.hal" && echo "save = save all without pin and signal values"
cat "$TEST_TMPDIR/first.hal"
