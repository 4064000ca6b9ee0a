#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# run.sh BUILD - what a new user's clone must do without anything outside it:
#   - nothing in the tree refers to ../shared (the project's notes are not part
#     of a clone);
#   - `make kmod` works in a fresh clone (CMake configure, comp's generated C,
#     kbuild against the standard kernel's headers);
#   - the clone's benchmark script runs with its own workload generator
#     (BENCH_QUICK=1, with BUILD's programs).
# The clone is of HEAD (commit first), kept in BUILD/fresh-clone so ccache
# makes reruns fast. Prints "N passed, M failed".
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
build=$(cd "${1:-build}" && pwd)
clone=$build/fresh-clone/hal
pass=0 fail=0
ok() { echo "ok   $1"; pass=$((pass + 1)); }
bad() { echo "FAIL $1"; fail=$((fail + 1)); }
start=$(date +%s)

rm -rf "$clone"
mkdir -p "$build/fresh-clone"
git clone -q --no-hardlinks "$root" "$clone" || { echo "cannot clone $root"; exit 1; }
echo "== fresh clone of $(git -C "$clone" log -1 --format='%h %s')"

if grep -rn --exclude-dir=.git --exclude-dir=fresh-clone '\.\./shared' "$clone"; then bad "no reference to ../shared"; else ok "no reference to ../shared"; fi

kdir=$(ls -d /usr/src/linux-headers-*-amd64 2>/dev/null | grep -v -- -rt- | sort -V | tail -n 1)
if [ -z "$kdir" ]; then
	bad "make kmod: no linux-headers-*-amd64 (scripts/kernel-test-deps)"
elif (cd "$clone" && CCACHE_BASEDIR=$clone make kmod KDIR="$kdir" JOBS="$(nproc)") >"$build/fresh-clone/kmod.log" 2>&1; then
	# every module of the manifest, the core's three (kernel/Kbuild) and the self-tests
	# make kmod builds with them (kernel/Makefile.kmod KMOD_WITH_SELFTESTS), no other
	find "$clone/build/kmod" -name '*.ko' | sed 's|.*/||; s|\.ko$||' | sort >"$build/fresh-clone/ko.got"
	{ awk '!/^[ \t]*(#|$)/ { print $1 }' "$clone/modules.manifest"
	  printf '%s\n' rtapi hal_lib rtapi_parport_linux fmt_selftest rtapi_conformance; } | sort >"$build/fresh-clone/ko.want"
	if diff "$build/fresh-clone/ko.want" "$build/fresh-clone/ko.got" >"$build/fresh-clone/ko.diff"; then
		ok "make kmod in a fresh clone ($(wc -l <"$build/fresh-clone/ko.got") modules)"
	else
		bad "make kmod in a fresh clone: the modules differ from the manifest's (< missing, > extra)"
		cat "$build/fresh-clone/ko.diff"
	fi
else
	bad "make kmod in a fresh clone"; tail -n 20 "$build/fresh-clone/kmod.log"
fi

out=$build/fresh-clone/bench.log
if BENCH_QUICK=1 "$clone/bench/run-bench.sh" "$build" >"$out" 2>&1 &&
	grep -q '^N=1600 ' "$out" && grep -q 'samples/s drained' "$out" &&
	! grep -qi 'no such file\|not found\|failed' "$out"; then
	ok "the clone's bench/run-bench.sh (BENCH_QUICK=1)"
else
	bad "the clone's bench/run-bench.sh"; cat "$out"
fi
echo "(fresh-clone test: $(($(date +%s) - start)) s)"
echo "$pass passed, $fail failed"
[ "$fail" = 0 ]
