#!/bin/sh
# run-hal-tests-vm.sh TESTS_DIR - the HAL-level tests inside the kernel-test VM, in
# the kernel flavor: tests/run-hal-tests.sh's rules (test.hal or test.sh, expected or
# checkresult, expected-status, skip-flavor-kernel, needs-devices) in POSIX sh for busybox, one test
# at a time (the kernel has one HAL). Prints "HALTEST PASS|FAIL|SKIP <dir>" per test
# (PASS and FAIL with its seconds), "| " + the diff or reason under a failure, and a
# summary line; exit 1 on a failure.
tests=${1:?usage: run-hal-tests-vm.sh TESTS_DIR}
timeout_s=${HAL_TEST_TIMEOUT:-120}
export HAL_FLAVOR=kernel HAL_TEST_FLAVOR=kernel
work=$(mktemp -d)
pass=0 fail=0 skip=0

for t in $(find "$tests" \( -name test.hal -o -name test.sh \) -type f | sort); do
	dir=${t%/*}
	rel=${dir#"$tests"/}
	# HAL_TEST_DEVICES_ONLY=1 (cases/40-devices.sh, as root): only the needs-devices tests
	[ -z "${HAL_TEST_DEVICES_ONLY:-}" ] || [ -e "$dir/needs-devices" ] || continue
	if [ -e "$dir/skip-flavor-kernel" ]; then
		echo "HALTEST SKIP $rel"; skip=$((skip + 1)); continue
	fi
	missing=
	for dev in $(cat "$dir/needs-devices" 2>/dev/null); do
		[ -w "$dev" ] || missing=$dev
	done
	if [ -n "$missing" ]; then
		echo "HALTEST SKIP $rel (needs a writable $missing: run by cases/40-devices.sh)"
		skip=$((skip + 1)); continue
	fi
	if [ -e "$dir/needs-python" ] && ! command -v python3 >/dev/null 2>&1; then
		echo "HALTEST SKIP $rel (no python3 in the VM: built with KTEST_PYTHON=0)"; skip=$((skip + 1)); continue
	fi
	rm -rf "$work/tmp"; mkdir -p "$work/tmp"
	t0=$(cut -d' ' -f1 /proc/uptime)
	limit=$timeout_s	# a test's own timeout-seconds, as tests/run-hal-tests.sh takes it
	[ -f "$dir/timeout-seconds" ] && limit=$(cat "$dir/timeout-seconds")
	(
		cd "$dir" || exit 99
		export TEST_TMPDIR="$work/tmp"
		if [ -f test.hal ]; then
			exec timeout "$limit" halrun -f test.hal
		else
			exec timeout "$limit" sh test.sh
		fi
	) </dev/null >"$work/result" 2>&1
	rc=$?
	# 'show thread' lists missed periods only when a thread missed some: that depends on
	# the machine (always in qemu), not on the test, so it stays out of the comparison
	sed -i '/^ *missed periods (overruns): [0-9]*$/d' "$work/result"
	# whatever the test left behind (failed teardown, timeout) must not leak
	timeout 30 halrun -U >/dev/null 2>&1 </dev/null
	if [ $rc -eq 124 ] || [ $rc -eq 143 ]; then
		echo "timed out after ${limit} s" >"$work/log"; ok=1
	elif [ -x "$dir/checkresult" ]; then
		(cd "$dir" && ./checkresult "$work/result") >"$work/log" 2>&1; ok=$?
	elif [ -f "$dir/expected" ]; then
		diff -u "$dir/expected" "$work/result" >"$work/log" 2>&1; ok=$?
	else
		echo "neither expected nor an executable checkresult" >"$work/log"; ok=1
	fi
	if [ $ok -eq 0 ] && [ -f "$dir/expected-status" ] && [ "$(cat "$dir/expected-status")" != "$rc" ]; then
		echo "exit status $rc, expected $(cat "$dir/expected-status")" >"$work/log"; ok=1
	fi
	# nothing may stay loaded between tests: fail the test and clean up by hand
	if [ -e /proc/rtapi ]; then
		{ echo "left behind after halrun -U:"; lsmod; } >"$work/log"; ok=1
		# (through the helper: this runs as a 'hal' group member, not root)
		for m in $(lsmod | awk 'NR > 1 && $1 != "rtapi" && $1 != "hal_lib" { print $1 }'); do
			emc_module_helper remove "$m"
		done
		emc_module_helper remove hal_lib 2>/dev/null; emc_module_helper remove rtapi 2>/dev/null
	fi
	# (seconds with one decimal: which tests the VM's time goes to)
	took=$(awk -v a="$t0" -v b="$(cut -d' ' -f1 /proc/uptime)" 'BEGIN { printf "%.1f", b - a }')
	if [ $ok -eq 0 ]; then
		echo "HALTEST PASS $rel ($took s)"; pass=$((pass + 1))
	else
		echo "HALTEST FAIL $rel ($took s)"; fail=$((fail + 1))
		sed 's/^/| /' "$work/log" | head -n 40
		echo "| --- output:"
		sed 's/^/| /' "$work/result" | head -n 40
	fi
done
rm -rf "$work"
echo "HAL tests (kernel): $pass passed, $fail failed, $skip skipped"
[ $fail -eq 0 ]
