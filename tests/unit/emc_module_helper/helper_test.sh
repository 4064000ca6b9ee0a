#!/bin/sh
# helper_test.sh HELPER MODULE_DIR CALLS_LOG - every refusal of emc_module_helper, and
# the finit_module/delete_module calls it makes when it accepts (the test build logs
# them to CALLS_LOG instead): argument validation and quoting (one token, one
# parameter), the module file's checks, the personality. Prints "N passed, N failed".
# (The test build trusts files of the user running it where the real one wants root.)
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

rel=$moddir/$(uname -r)
mkdir -p "$rel"
chmod 755 "$moddir" "$rel"
# a stand-in module: what the helper reads of a .ko is its .modinfo parameter types
printf '\177ELF\0parmtype=count:int\0parmtype=names:array of charp\0parmtype=cfg:charp\0parmtype=debug:bool\0parmtype=levels:array of int\0parmtype=hal_loadrt_args:charp\0' \
	>"$rel/and2.ko"
chmod 644 "$rel/and2.ko"
rm -f "$calls"
if "$helper" insert and2 count=2 'names="a b"' "$arg_1024" 2>/dev/null; then
	expect="finit_module $rel/and2.ko count=2 names=\"a b\" $arg_1024"
	[ "$(cat "$calls")" = "$expect" ] && ok || bad "finit_module arguments: $(cat "$calls")"
else
	bad "accepted insert failed"
fi

# accepted ARGS... -- EXPECTED: the parameter string finit_module gets
accepted() {
	label=$1; shift
	args=
	while [ "$1" != -- ]; do args="$args$1
"; shift; done
	shift
	rm -f "$calls"
	err=$(printf '%s' "$args" | { IFS='
'; set -f; # shellcheck disable=SC2046
		"$helper" insert and2 $(cat) 2>&1; })
	got=$(sed "s|^finit_module $rel/and2.ko ||" "$calls" 2>/dev/null)
	[ "$got" = "$1" ] && ok || bad "$label: got '$got' (expected '$1') $err"
}
# one token per argument: a blank inside a value is quoted by the helper itself, so
# "count=1 dyndbg=+p" can never become two parameters (and is no int anyway)
accepted "blank in a string value" 'cfg=0x378 out 0x278 in' -- 'cfg="0x378 out 0x278 in"'
accepted "halcmd's quoted form" 'cfg="0x378 out 0x278 in"' -- 'cfg="0x378 out 0x278 in"'
accepted "'=' inside a value (hostmot2)" 'cfg=num_encoders=2 num_stepgens=4' -- 'cfg="num_encoders=2 num_stepgens=4"'
accepted "'=' first in a value" 'cfg==x' -- 'cfg==x'
accepted "empty value" 'cfg=' -- 'cfg=""'
accepted "flag" 'debug' -- 'debug'
accepted "hex, sign, arrays" 'count=0x10' 'levels=-1,+2,0x3' 'debug=y' -- 'count=0x10 levels=-1,+2,0x3 debug=y'
refused "injection through a blank" insert and2 'count=1 dyndbg=+p'
refused "injection, halcmd's quotes" insert and2 'count="1 dyndbg=+p"'
refused "a parameter the module lacks" insert and2 dyndbg=+p
refused "kernel's own async_probe" insert and2 async_probe
refused "double quote inside" insert and2 'cfg=a"b'
refused "unbalanced quotes" insert and2 'cfg="a b'
refused "quote games" insert and2 'cfg="a" count="2'
refused "carriage return" insert and2 "cfg=a$(printf '\r')b"
refused "vertical tab" insert and2 "cfg=a$(printf '\v')b"
refused "escape" insert and2 "cfg=a$(printf '\033')b"
refused "delete" insert and2 "cfg=a$(printf '\177')b"
refused "'=' games on an int" insert and2 'count==1'
refused "int with a letter" insert and2 'count=1x'
refused "array of int with blanks" insert and2 'levels=1, 2'
refused "empty int" insert and2 'count='
refused "param with a dash" insert and2 'hal-loadrt-args=x'

# the module file: not through a link, root's (here: the test user's), writable by no one else
ln -s and2.ko "$rel/or2.ko"
refused "module is a symbolic link" insert or2
rm "$rel/or2.ko"
cp "$rel/and2.ko" "$rel/or2.ko"
chmod 666 "$rel/or2.ko"
refused "module writable by others" insert or2
chmod 664 "$rel/or2.ko"
refused "module writable by the group" insert or2
rm "$rel/or2.ko"
mkdir "$rel/not.ko"
refused "module is a directory" insert not
rmdir "$rel/not.ko"
chmod 777 "$rel"
refused "release directory writable by others" insert and2 count=1
chmod 755 "$rel"
# a changed uname (personality UNAME26) does not redirect the module path
if setarch --help 2>/dev/null | grep -q uname-2.6; then
	rm -f "$calls"
	setarch "$(uname -m)" --uname-2.6 "$helper" insert and2 count=1 2>/dev/null
	[ "$(cat "$calls" 2>/dev/null)" = "finit_module $rel/and2.ko count=1" ] && ok ||
		bad "UNAME26: $(cat "$calls" 2>/dev/null)"
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
