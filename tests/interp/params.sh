#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# params.sh RS274 TMPDIR - parameter file round trip (gcode.md 4.2): indices already in
# the file and the persistent ranges are written back ascending as "%d\t%f", others are
# not; the old file becomes FILE.bak; the values are there at the next start (G92
# offsets applied again); a file out of order is an error naming file and line.
set -eu
rs274=$1
dir=$2/params
mkdir -p "$dir"
cd "$dir"
printf '31\t1.0\n100\t2.5\n5161\t0.0\n' > test.var
cat > set.ngc <<'P'
#100 = 7.25
#200 = 3
#5161 = 1.5
G10 L2 P2 X3 Y-4
G0 X10
G92 X1
M2
P
"$rs274" -p test.var set.ngc > /dev/null
fail() { echo "params.sh: $*" >&2; exit 1; }
[ -f test.var.bak ] || fail "no test.var.bak"
grep -q "^100	7.250000$" test.var || fail "#100 not written back"
grep -q "^31	1.000000$" test.var || fail "#31 (in the old file) not written back"
grep -q "^200	" test.var && fail "#200 (not persistent, not in the file) written"
grep -q "^5161	1.500000$" test.var || fail "#5161 not written"
grep -q "^5241	3.000000$" test.var || fail "G55 X offset #5241 not written"
grep -q "^5242	-4.000000$" test.var || fail "G55 Y offset #5242 not written"
grep -q "^5210	1.000000$" test.var || fail "#5210 not written"
grep -q "^5211	9.000000$" test.var || fail "G92 offset #5211 not written"
sort -n -c test.var || fail "not in ascending order"
[ "$(wc -l < test.var)" -eq 121 ] || fail "expected 121 lines, got $(wc -l < test.var)"
cat > use.ngc <<'P'
(DEBUG, %.2f#100 %.2f#5161 %.2f#5241 %.2f#5211)
G0 X0
M2
P
out=$("$rs274" -p test.var use.ngc)
echo "$out" | grep -q 'MESSAGE("7.25 1.50 3.00 9.00")' || fail "values not read back: $out"
echo "$out" | grep -q 'STRAIGHT_TRAVERSE(9.0000, 0.0000, 0.0000)' || fail "G92 offset not restored: $out"
printf '5\t1\n4\t2\n' > bad.var
if "$rs274" -n -p bad.var use.ngc > /dev/null 2> err; then fail "out-of-order file accepted"; fi
grep -qx "bad.var:2: Parameter file out of order" err || fail "bad error: $(cat err)"
