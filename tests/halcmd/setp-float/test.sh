cat > "$TEST_TMPDIR/f.hal" <<'HAL'
loadrt siggen
setp siggen.0.offset nan
setp siggen.0.offset inf
setp siggen.0.offset -Infinity
setp siggen.0.offset 1e999
setp siggen.0.offset 1e-999
getp siggen.0.offset
setp siggen.0.offset 1.7976931348623157e308
getp siggen.0.offset
newsig f float
sets f 1e999
sets f 0x1p4
gets f
HAL
cd "$TEST_TMPDIR" && halrun -k -f f.hal
echo "exit $?"
