#!/bin/sh
# fp-check-test.sh [KERNEL_RELEASE...] - tests kernel/kmod-fp-check.sh itself: builds
# tests/kernel/fp-check/ against each kernel's headers (default: every Debian
# linux-headers-*-amd64 installed) and expects the check to fail on fpcheck_bad.ko
# (SSE-compiled init using a double), naming module, function and an SSE instruction,
# and to pass fpcheck_good.ko (the same code split by the rule). Exit 0 when both hold.
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
check=$root/kernel/kmod-fp-check.sh
[ $# -gt 0 ] || set -- $(ls -d /usr/src/linux-headers-*-amd64 2>/dev/null | sed 's|.*/linux-headers-||')
[ $# -gt 0 ] || { echo "fp-check-test: no linux-headers-*-amd64: run scripts/kernel-test-deps" >&2; exit 2; }
fail=0
for kver in "$@"; do
	out=$root/build/kmod-test/fp-check/$kver
	rm -rf "$out"
	mkdir -p "$out/bad" "$out/good"
	for d in bad good; do
		ln -s "$root/tests/kernel/fp-check/Kbuild" "$out/$d/Kbuild"
	done
	ln -s "$root/tests/kernel/fp-check/fpcheck_bad.c" "$out/bad/"
	ln -s "$root/tests/kernel/fp-check/fpcheck_good.c" "$out/good/fpcheck_good_main.c"
	ln -s "$root/tests/kernel/fp-check/fpcheck_good_fp.c" "$out/good/"
	for d in bad good; do
		make -s -C "/usr/src/linux-headers-$kver" M="$out/$d" CONFIG_DEBUG_INFO_BTF_MODULES= modules \
			>"$out/$d.log" 2>&1 || { cat "$out/$d.log" >&2; echo "fp-check-test: $kver: building $d failed" >&2; exit 1; }
	done
	if "$check" "$out/bad" >"$out/bad.check" 2>&1; then
		echo "FAILED: $kver: kmod-fp-check.sh passed fpcheck_bad.ko"; fail=1
	elif ! grep -Eq "^fpcheck_bad\.ko: (fpcheck_bad_init|init_module): '[a-z0-9]+ .*%xmm" "$out/bad.check"; then
		echo "FAILED: $kver: the report does not name fpcheck_bad.ko, its init and an xmm instruction:"
		cat "$out/bad.check"; fail=1
	else
		echo "ok: $kver: bad module refused: $(head -1 "$out/bad.check")"
	fi
	if ! "$check" "$out/good" >"$out/good.check" 2>&1; then
		echo "FAILED: $kver: kmod-fp-check.sh refused fpcheck_good.ko:"; cat "$out/good.check"; fail=1
	else
		echo "ok: $kver: split module passes"
	fi
done
[ "$fail" = 0 ]
