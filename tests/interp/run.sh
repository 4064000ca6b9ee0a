#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# run.sh RS274 - the interpreter's tool-level tests (README.md here): every
# programs/NAME.ngc through `rs274 -n -i common.ini -t tool.tbl [NAME.args]`, stdout
# compared with NAME.expected (numbers within 2e-4) and exit status 0; every line of
# errors.txt as a program of its own that must fail with exactly "FILE:LINE: MESSAGE".
# Then the parameter file round trip (params.sh). Exit status 1 if any case failed.
set -u
rs274=$(cd "$(dirname "${1:?usage: run.sh RS274}")" && pwd)/$(basename "$1")
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/interp-tests.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0

for ngc in "$here"/programs/*.ngc; do
	name=$(basename "$ngc" .ngc)
	args=""
	[ -f "$here/programs/$name.args" ] && args=$(cat "$here/programs/$name.args")
	# shellcheck disable=SC2086 # args is a word list
	(cd "$here/programs" && "$rs274" -n -i ../common.ini -t ../tool.tbl $args "$name.ngc") \
		> "$tmp/out" 2> "$tmp/err"
	rc=$?
	if [ $rc -ne 0 ]; then
		echo "FAIL $name: exit status $rc: $(cat "$tmp/err")"
		fail=$((fail + 1))
	elif ! python3 "$here/compare.py" "$here/programs/$name.expected" "$tmp/out"; then
		echo "FAIL $name"
		fail=$((fail + 1))
	else
		pass=$((pass + 1))
	fi
done

# errors.txt: LINE<TAB>MESSAGE<TAB>PROGRAM (\n separates the program's lines)
n=0
while IFS='	' read -r line msg prog; do
	case "$line" in ''|'#'*) continue ;; esac
	n=$((n + 1))
	printf '%b\n' "$prog" > "$tmp/e$n.ngc"
	(cd "$tmp" && "$rs274" -n -i "$here/common.ini" -t "$here/tool.tbl" "e$n.ngc") > /dev/null 2> "$tmp/err"
	rc=$?
	want="e$n.ngc:$line: $msg"
	got=$(cat "$tmp/err")
	if [ $rc -ne 1 ] || [ "$got" != "$want" ]; then
		echo "FAIL error case $n ($prog): exit $rc"
		echo "  want: $want"
		echo "  got:  $got"
		fail=$((fail + 1))
	else
		pass=$((pass + 1))
	fi
done < "$here/errors.txt"

if sh "$here/params.sh" "$rs274" "$tmp"; then
	pass=$((pass + 1))
else
	echo "FAIL parameter file round trip"
	fail=$((fail + 1))
fi
echo "interp tests: $pass passed, $fail failed"
[ $fail -eq 0 ]
