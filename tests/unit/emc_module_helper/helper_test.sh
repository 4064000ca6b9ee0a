#!/bin/sh
# helper_test.sh HELPER MODULE_DIR CALLS_LOG - every refusal of emc_module_helper, and
# the finit_module/delete_module calls it makes when it accepts (the test build logs
# them to CALLS_LOG instead). Prints "N passed, N failed".
helper=$1 moddir=$2 calls=$3
pass=0 fail=0
rm -rf "$moddir" "$calls" "$calls.fail"

ok() { pass=$((pass + 1)); }
bad() { echo "FAIL: $*"; fail=$((fail + 1)); }

# refused NAME ARGS...: exit status 2, an error naming the reason, no system call
refused() {
	label=$1; shift
	rm -f "$calls"
	err=$("$helper" "$@" 2>&1 >/dev/null); rc=$?
	if [ "$rc" = 2 ] && [ -n "$err" ] && [ ! -e "$calls" ]; then ok
	else bad "$label: exit $rc, message '$err', called: $(cat "$calls" 2>/dev/null | tr '\n' ' ')"; fi
}

long_name=$(printf 'a%.0s' $(seq 32))
arg_1024="names=$(printf 'x%.0s' $(seq 1018))"
arg_1025="${arg_1024}x"
many=$(for i in $(seq 65); do printf 'p%d=1 ' "$i"; done)

refused "no arguments"
refused "verb only" insert
refused "unknown verb" load and2
refused "slash" insert ../and2
refused "dot dot" insert ..
refused "path" insert /tmp/and2
refused "suffix" insert and2.ko
refused "upper case" insert AND2
refused "empty name" insert ""
refused "too long name" insert "$long_name"
refused "not whitelisted" insert evil
refused "option injection" insert and2 -f
refused "empty param" insert and2 =1
refused "upper param" insert and2 Count=1
refused "non-printable" insert and2 "names=a$(printf '\t')b"
refused "newline" insert and2 "names=a
b"
refused "high byte" insert and2 "names=$(printf '\303\251')"
refused "over-long argument" insert and2 "$arg_1025"
# shellcheck disable=SC2086
refused "too many arguments" insert and2 $many
refused "remove with arguments" remove and2 count=1
refused "module file missing" insert and2 count=1

mkdir -p "$moddir/$(uname -r)"
: > "$moddir/$(uname -r)/and2.ko"
rm -f "$calls"
if "$helper" insert and2 count=2 'names="a b"' "$arg_1024" 2>/dev/null; then
	expect="finit_module $moddir/$(uname -r)/and2.ko count=2 names=\"a b\" $arg_1024"
	[ "$(cat "$calls")" = "$expect" ] && ok || bad "finit_module arguments: $(cat "$calls")"
else
	bad "accepted insert failed"
fi
rm -f "$calls"
"$helper" remove and2 2>/dev/null && [ "$(cat "$calls")" = "delete_module and2" ] && ok ||
	bad "remove: $(cat "$calls" 2>/dev/null)"
"$helper" insert rtapi 2>/dev/null; [ $? = 2 ] && ok || bad "rtapi.ko missing must be refused"
touch "$calls.fail"
err=$("$helper" insert and2 2>&1); rc=$?
[ "$rc" = 1 ] && [ "$err" = "emc_module_helper: cannot insert and2: Invalid argument" ] && ok ||
	bad "insert failure: exit $rc, '$err'"
err=$("$helper" remove and2 2>&1); rc=$?
[ "$rc" = 1 ] && [ "$err" = "emc_module_helper: cannot remove and2: Invalid argument" ] && ok ||
	bad "remove failure: exit $rc, '$err'"
rm -f "$calls.fail"

echo "$pass passed, $fail failed"
[ "$fail" = 0 ]
