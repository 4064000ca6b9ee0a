#!/bin/bash
# SPDX-License-Identifier: GPL-2.0-or-later
# run-hal-tests.sh - run the HAL-level tests: every directory under tests/ (except
# tests/unit) holding test.hal or test.sh. Each runs through halrun in its own
# RTAPI_INSTANCE, its stdout+stderr go to a "result" file that is compared with
# "expected" or handed to "./checkresult result". See tests/README.
set -u

usage() {
	cat <<'USAGE'
usage: tests/run-hal-tests.sh [--build DIR] [--flavor sim|kernel] [-j N] [-v] [FILTER ...]
  --build DIR    build tree whose bin/ holds halrun, halcmd, rtapi_app (default: build)
  --flavor F     sim (default) or kernel; a test dir with skip-flavor-F is skipped
  -j N           tests run in parallel (default: nproc)
  -v             show the result of passing tests too
  FILTER         run only tests whose path (relative to tests/) contains FILTER
USAGE
}

build=build
flavor=sim
jobs=$(nproc 2>/dev/null || echo 2)
verbose=0
filters=()
while [ $# -gt 0 ]; do
	case "$1" in
	--build) build=${2:?--build needs a directory}; shift 2 ;;
	--build=*) build=${1#--build=}; shift ;;
	--flavor) flavor=${2:?--flavor needs sim or kernel}; shift 2 ;;
	--flavor=*) flavor=${1#--flavor=}; shift ;;
	-j) jobs=${2:?-j needs a number}; shift 2 ;;
	-j*) jobs=${1#-j}; shift ;;
	-v) verbose=1; shift ;;
	-h|--help) usage; exit 0 ;;
	-*) echo "run-hal-tests: unknown option '$1'" >&2; usage >&2; exit 2 ;;
	*) filters+=("$1"); shift ;;
	esac
done
case "$flavor" in sim|kernel) ;; *) echo "run-hal-tests: flavor must be sim or kernel, not '$flavor'" >&2; exit 2 ;; esac
case "$jobs" in ''|*[!0-9]*|0) echo "run-hal-tests: -j needs a positive number, not '$jobs'" >&2; exit 2 ;; esac

tests_dir=$(cd "$(dirname "$0")" && pwd)
if ! build_abs=$(cd "$build" 2>/dev/null && pwd); then
	echo "run-hal-tests: build directory '$build' does not exist (build first, or give --build DIR)" >&2
	exit 2
fi
build=$build_abs
if [ ! -x "$build/bin/halrun" ]; then
	echo "run-hal-tests: $build/bin/halrun not found (build first)" >&2
	exit 2
fi
export PATH="$build/bin:$PATH"
export HAL_TEST_FLAVOR=$flavor
# halcmd, halrun and the ULAPI library follow HAL_FLAVOR (kernel|sim). The kernel
# flavor has one HAL per machine (rtapi.ko, hal_lib.ko; RTAPI_INSTANCE means
# nothing there), so its tests take turns. Inside the test VM, where there is no
# bash, tests/kernel/run-hal-tests-vm.sh applies the same rules.
export HAL_FLAVOR=$flavor
# Warnings (no SCHED_FIFO, missed periods on a loaded machine) depend on the machine,
# not on the test: keep them out of the compared output unless a test asks for them.
export RTAPI_MSG_LEVEL=${RTAPI_MSG_LEVEL:-ERR}
[ "$flavor" = kernel ] && jobs=1
timeout_s=${HAL_TEST_TIMEOUT:-120}
# A sanitizer build (make sanitize-test): a case that cannot run there has a file
# skip-sanitize saying why (tests/python: python3 would need the ASan runtime preloaded).
sanitize=0
grep -q '^HAL_SANITIZE:BOOL=ON$' "$build/CMakeCache.txt" 2>/dev/null && sanitize=1

mapfile -t all_dirs < <(find "$tests_dir" -path "$tests_dir/unit" -prune -o \
	\( -name test.hal -o -name test.sh \) -type f -printf '%h\n' | sort -u)
dirs=()
for d in "${all_dirs[@]}"; do
	rel=${d#"$tests_dir"/}
	if [ ${#filters[@]} -eq 0 ]; then
		dirs+=("$d")
		continue
	fi
	for f in "${filters[@]}"; do
		case "$rel" in *"$f"*) dirs+=("$d"); break ;; esac
	done
done
if [ ${#dirs[@]} -eq 0 ]; then
	echo "run-hal-tests: no tests found${filters:+ matching the filters}" >&2
	exit 1
fi
# The slowest tests (tests/slow-first, longest first) start first, so the parallel
# run does not end waiting for one long test started last.
slow=()
while read -r rel _; do
	case "$rel" in ''|'#'*) continue ;; esac
	for d in "${dirs[@]}"; do
		[ "$d" = "$tests_dir/$rel" ] && slow+=("$d") && break
	done
done < <(cat "$tests_dir/slow-first" 2>/dev/null)
if [ ${#slow[@]} -gt 0 ]; then
	rest=()
	for d in "${dirs[@]}"; do
		case " ${slow[*]} " in *" $d "*) ;; *) rest+=("$d") ;; esac
	done
	dirs=("${slow[@]}" "${rest[@]}")
fi

work=$(mktemp -d "${TMPDIR:-/tmp}/hal-tests.XXXXXX")
trap 'rm -rf "$work"' EXIT
# Instances must not collide with another runner on the same machine.
instance_base=$(( ($$ % 2000) * 1000 + 1000000 ))

# skipped OUT REL REASON: the test at REL is not run (status SKIP, one line)
skipped() {
	echo SKIP > "$1/status"
	echo "SKIP $2 ($3)"
}

# run_one INDEX DIR: writes $work/INDEX/{status,log,result}; prints one line.
run_one() {
	local idx=$1 dir=$2 out="$work/$1" rel=${2#"$tests_dir"/} rc ok
	mkdir -p "$out/tmp"
	local skip=
	[ -e "$dir/skip-flavor-$flavor" ] && skip="$dir/skip-flavor-$flavor"
	[ $sanitize -eq 1 ] && [ -e "$dir/skip-sanitize" ] && skip="$dir/skip-sanitize"
	if [ -n "$skip" ]; then
		# a skip must say why: an empty marker is a mistake, not a reason
		if [ ! -s "$skip" ]; then
			echo FAIL > "$out/status"
			echo "${skip##*/} is empty: write the reason in it" > "$out/log"
			echo "FAIL $rel (${skip##*/} has no reason)"
			return
		fi
		skipped "$out" "$rel" "$(head -n 1 "$skip")"
		return
	fi
	# needs-root: the test changes file owners or switches users (its first line: why)
	if [ -e "$dir/needs-root" ] && [ "$(id -u)" -ne 0 ]; then
		skipped "$out" "$rel" "needs root: $(head -n 1 "$dir/needs-root")"
		return
	fi
	# needs-devices: device nodes the test must be able to write (e.g. /dev/uinput)
	local dev
	for dev in $(cat "$dir/needs-devices" 2>/dev/null); do
		if [ ! -w "$dev" ]; then
			skipped "$out" "$rel" "needs a writable $dev"
			return
		fi
	done
	local instance=$(( instance_base + idx )) limit=$timeout_s t0=$SECONDS
	# a long test (tests/robustness/fault-injection) states its own bound
	[ -f "$dir/timeout-seconds" ] && limit=$(cat "$dir/timeout-seconds")
	(
		cd "$dir" || exit 99
		export RTAPI_INSTANCE=$instance TEST_TMPDIR="$out/tmp"
		if [ -f test.hal ]; then
			exec timeout "$limit" halrun -f test.hal
		else
			exec timeout "$limit" sh test.sh
		fi
	) < /dev/null > "$out/result" 2>&1
	rc=$?
	# 'show thread' lists missed periods only when a thread missed some: that depends on
	# the machine (always in qemu), not on the test, so it stays out of the comparison
	sed -i '/^ *missed periods (overruns): [0-9]*$/d' "$out/result"
	# Whatever the test left behind (failed teardown, timeout) must not leak.
	RTAPI_INSTANCE=$instance timeout 30 halrun -U > /dev/null 2>&1 < /dev/null
	if [ $rc -eq 124 ]; then
		echo "timed out after ${limit} s" > "$out/log"
		ok=1
	elif [ -x "$dir/checkresult" ]; then
		(cd "$dir" && ./checkresult "$out/result") > "$out/log" 2>&1
		ok=$?
	elif [ -f "$dir/expected" ]; then
		diff -u "$dir/expected" "$out/result" > "$out/log" 2>&1
		ok=$?
	else
		echo "neither expected nor an executable checkresult in $rel" > "$out/log"
		ok=1
	fi
	if [ $ok -eq 0 ] && [ -f "$dir/expected-status" ] && [ "$(cat "$dir/expected-status")" != "$rc" ]; then
		echo "exit status $rc, expected $(cat "$dir/expected-status")" > "$out/log"
		ok=1
	fi
	echo $((SECONDS - t0)) > "$out/seconds"
	if [ $ok -eq 0 ]; then
		echo PASS > "$out/status"
		echo "PASS $rel ($((SECONDS - t0)) s)"
	else
		echo FAIL > "$out/status"
		echo "FAIL $rel ($((SECONDS - t0)) s)"
	fi
}

running=0
for i in "${!dirs[@]}"; do
	run_one "$i" "${dirs[$i]}" &
	running=$((running + 1))
	if [ $running -ge "$jobs" ]; then
		wait -n
		running=$((running - 1))
	fi
done
wait

pass=0 fail=0 skip=0
for i in "${!dirs[@]}"; do
	rel=${dirs[$i]#"$tests_dir"/}
	status=$(cat "$work/$i/status" 2>/dev/null || echo FAIL)
	case "$status" in
	PASS) pass=$((pass + 1))
		if [ $verbose -eq 1 ]; then echo "--- $rel: result"; cat "$work/$i/result"; fi ;;
	SKIP) skip=$((skip + 1)) ;;
	*) fail=$((fail + 1))
		echo "--- FAIL $rel"
		cat "$work/$i/log" 2>/dev/null
		;;
	esac
done
echo "HAL tests ($flavor): $pass passed, $fail failed, $skip skipped"
[ $fail -eq 0 ]
