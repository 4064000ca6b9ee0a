#!/bin/sh
# run-kernel-tests.sh - kernel-flavor tests: builds the modules against Debian's
# linux-headers-<ver>-amd64 and static halcmd/halrun/halsampler/halstreamer/
# emc_module_helper (build/static), packs them with busybox, the HAL-level tests
# (tests/*/*/) and tests/kernel/cases into an initramfs, boots /boot/vmlinuz-<ver>
# in qemu (TCG, no KVM needed; with an LPT at 0x378 and a second 16550 at 0x2f8 for
# cases/40-devices.sh), runs the cases inside (10-hal-suite runs the whole
# HAL-level suite in the kernel flavor) and reports from the serial console.
# Usage: run-kernel-tests.sh [KERNEL_RELEASE...]   (default: newest installed non-rt
#        -amd64; e.g. 6.1.0-56-rt-amd64 for the PREEMPT_RT kernel). Several kernels
#        are tested in parallel VMs (7.5 min for both Debian kernels on 2 cores, 11 min
#        one after the other), each one's report printed when all are done.
# Python 3 and the hal module go into the VM (tests/python run there); KTEST_PYTHON=0 leaves them out.
# While iterating: KTEST_HAL_DIRS="hal_input serport" packs only those HAL test dirs,
# KTEST_CASES="10 40" runs only the cases whose names start so (e.g. 10-hal-suite).
# Needs: scripts/kernel-test-deps. Exit 0 when every case passed.
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
here=$root/tests/kernel
static=${KTEST_STATIC_BUILD:-$root/build/static}
vm_moddir=/lib/hal/modules	# compiled into the static tools and helper

# Static tools: the VM has no libc. Same sources as build/, linked -static, with the
# VM's module directory compiled into emc_module_helper and hal::kmod.
build_static() {
	echo "== building static tools ($static)"
	libdir=$(gcc -print-multiarch 2>/dev/null || echo x86_64-linux-gnu)
	mkdir -p "$static"
	# -Wno-error=restrict: GCC 12 at -O3 reports a false -Wrestrict inside libstdc++'s
	# string operator+ (GCC bug 105329); it stays a warning here, every other one an error.
	{ cmake -S "$root" -B "$static" -DCMAKE_BUILD_TYPE=Release -DCMAKE_EXE_LINKER_FLAGS=-static \
		-DCMAKE_CXX_FLAGS=-Wno-error=restrict \
		"-DREADLINE_LIBRARY=/usr/lib/$libdir/libreadline.a;/usr/lib/$libdir/libtinfo.a" \
		-DHAL_KMOD_INSTALL_DIR=$vm_moddir -DCMAKE_INSTALL_PREFIX=/usr -DHAL_HALMETER_GTK=OFF &&
	  cmake --build "$static" -j"$(nproc)" --target halcmd halrun realtime halsampler halstreamer emc_module_helper \
		thread_cost dispatch_cost $([ "${KTEST_PYTHON:-1}" = 0 ] || echo pyhal)
	} >"$static.log" 2>&1 || { cat "$static.log" >&2; exit 1; }
	# userspace components for tests/usercomp, halmeter, shuttlexpress, hal_input, gs2_vfd
	# (halmeter without GTK, which cannot link statically; hal_input and gs2_vfd/gs2_sim
	# need libudev/libmodbus, which Debian has only as shared libraries: they are linked
	# dynamically and their libraries go into the VM) motmod's motcmd, and the test devices' helper
	cmake --build "$static" -j"$(nproc)" --target hal_testcomp halmeter shuttlexpress motcmd hal_testdev \
		hal_input gs2_vfd gs2_sim >>"$static.log" 2>&1 ||
		{ cat "$static.log" >&2; exit 1; }
}

if [ $# -gt 1 ]; then
	build_static	# once, before the kernels' runs share it
	mkdir -p "$root/build/kmod-test"
	pids=
	for k in "$@"; do
		KTEST_STATIC_READY=1 "$0" "$k" >"$root/build/kmod-test/$k.report" 2>&1 &
		pids="$pids $!"
	done
	rc=0
	for p in $pids; do wait "$p" || rc=1; done
	for k in "$@"; do echo "==== $k"; cat "$root/build/kmod-test/$k.report"; done
	exit $rc
fi
kver=${1:-$(ls /boot | sed -n 's/^vmlinuz-\(.*-amd64\)$/\1/p' | grep -v -- -rt- | sort -V | tail -n 1)}
[ -n "$kver" ] || { echo "no /boot/vmlinuz-*-amd64: run scripts/kernel-test-deps" >&2; exit 2; }
kdir=/usr/src/linux-headers-$kver
[ -d "$kdir" ] || { echo "no $kdir: run scripts/kernel-test-deps" >&2; exit 2; }
out=${KTEST_BUILD:-$root/build/kmod-test/$kver}
# KTEST_BENCH=1: run the benchmark cases (bench-cases/) instead of the tests
cases=$here/cases
if [ -n "${KTEST_BENCH:-}" ]; then
	cases=$here/bench-cases
	out=$out-bench
fi
timeout_s=${KTEST_TIMEOUT:-2700}
start=$(date +%s)

mkdir -p "$out"
echo "== building modules for $kver"
# KTEST_MANIFEST: build and test only the modules listed there (default: all)
make -s -f "$root/kernel/Makefile.kmod" KDIR="$kdir" KMOD_BUILD="$out/modules" \
	KMOD_TEST_MODULES="$here/fmt_selftest.c $here/rtapi_conformance.c" ${KTEST_MANIFEST:+KMOD_MANIFEST="$KTEST_MANIFEST"} ${KMOD_CFLAGS:+KCFLAGS="$KMOD_CFLAGS"} >"$out.build.log" 2>&1 ||
	{ mkdir -p "$out"; cat "$out.build.log" >&2; exit 1; }
# the FP rule on the machine code: no FP/SIMD register outside *_fp objects
echo "== checking floating point in the modules (kernel/kmod-fp-check.sh)"
"$root/kernel/kmod-fp-check.sh" "$out/modules" || exit 1

[ -n "${KTEST_STATIC_READY:-}" ] || build_static

echo "== building the initramfs"
rm -rf "$out/initramfs"
ird=$out/initramfs
mkdir -p "$ird/bin" "$ird$vm_moddir/$kver" "$ird/tests/cases" "$ird/tests/hal" \
	"$ird/proc" "$ird/sys" "$ird/dev" "$ird/tmp"
cp /bin/busybox "$ird/bin/busybox"
file -L /bin/busybox | grep -q 'statically linked' ||
	{ echo "/bin/busybox is not static: install busybox-static" >&2; exit 2; }
for ko in $(find "$out/modules" -name '*.ko'); do
	strip --strip-debug -o "$ird$vm_moddir/$kver/${ko##*/}" "$ko"
done
for tool in halcmd halrun realtime halsampler halstreamer emc_module_helper; do
	strip -o "$ird/bin/$tool" "$static/bin/$tool"
done
for tool in hal_testcomp halmeter shuttlexpress motcmd hal_testdev hal_input gs2_vfd gs2_sim; do
	strip -o "$ird/bin/$tool" "$static/bin/$tool"
done
# the shared libraries of the dynamic ones, at their paths (with ld.so)
ldd "$static/bin/hal_input" "$static/bin/gs2_vfd" "$static/bin/gs2_sim" 2>/dev/null |
	awk '/=> \// { print $3 } /^\t\/.*ld-linux/ { print $1 }' | sort -u |
	while read -r lib; do
		mkdir -p "$ird${lib%/*}"
		[ -e "$ird$lib" ] || cp -L "$lib" "$ird$lib"
	done
# the kernel's modules for the virtual input devices of cases/40-devices.sh: evdev,
# uinput, hid, uhid, hid-generic (Debian builds them as modules)
mkdir -p "$ird/lib/testdev-modules"
for m in input/evdev input/misc/uinput hid/hid hid/uhid hid/hid-generic; do
	cp "/lib/modules/$kver/kernel/drivers/$m.ko" "$ird/lib/testdev-modules/" ||
		{ echo "no /lib/modules/$kver/kernel/drivers/$m.ko: install linux-image-$kver" >&2; exit 2; }
done
# the HAL-level tests: every tests/<component>/<case>/ (not unit/, not kernel/), or
# only the directories named in KTEST_HAL_DIRS (e.g. "and2 halcmd")
for d in "$root"/tests/*/; do
	case ${d%/} in */unit|*/kernel) continue ;; esac
	[ -z "${KTEST_HAL_DIRS:-}" ] || case " $KTEST_HAL_DIRS " in *" $(basename "$d") "*) ;; *) continue ;; esac
	cp -r "${d%/}" "$ird/tests/hal/"
done
cp "$here/run-hal-tests-vm.sh" "$ird/tests/"
# Python (unless KTEST_PYTHON=0) for the tests marked needs-python (tests/python): Debian's
# interpreter with its shared libraries, a trimmed stdlib and the hal module of the
# static build (+36 MB unpacked, +14 MB in the gzip -1 initramfs)
[ "${KTEST_PYTHON:-1}" = 0 ] || "$here/vm-python.sh" "$static" "$ird"
cc -static -O2 -Wall -I"$root/kernel/rtapi" -I"$root/kernel/hal" \
	-o "$out/initramfs/tests/hal_segcheck" "$here/hal_segcheck.c"
cc -static -O2 -Wall -Werror -I"$root/kernel/rtapi" -I"$root/kernel/hal" -I"$root/kernel/components" \
	-o "$out/initramfs/tests/hal_exploit" "$here/hal_exploit.c"
cp "$here/init.sh" "$ird/init"
# Accounts (busybox su): group hal with the member haluser (uid 1000); nobody (65534)
# is in no group of ours. 06-helper-group makes the helper 4750 root:hal.
mkdir -p "$ird/etc"
[ -e "$ird/etc/passwd" ] || printf '%s\n' 'root:x:0:0:root:/:/bin/sh' \
	'haluser:x:1000:1000:hal member:/home/haluser:/bin/sh' 'nobody:x:65534:65534:nobody:/:/bin/sh' >"$ird/etc/passwd"
[ -e "$ird/etc/group" ] || printf '%s\n' 'root:x:0:' 'hal:x:990:haluser' 'haluser:x:1000:' \
	'nogroup:x:65534:' >"$ird/etc/group"
for c in "$cases"/*.sh; do
	[ -z "${KTEST_CASES:-}" ] || case " $KTEST_CASES " in *" $(basename "$c" | cut -d- -f1) "*) ;; *) continue ;; esac
	cp "$c" "$ird/tests/cases/"
done
if [ -n "${KTEST_BENCH:-}" ]; then	# the standard workloads, generated here (bash)
	gen=$root/bench/gen-workload.sh
	mkdir -p "$ird/bench"
	for n in 1000 4000 16000; do "$gen" load $n >"$ird/bench/load-$n.hal"; done
	"$gen" funct 1000 >"$ird/bench/funct-1000.hal"
	"$gen" sample 8 >"$ird/bench/sample-8.hal"
	strip -o "$ird/bin/thread_cost" "$static/bin/thread_cost"
	strip -o "$ird/bin/dispatch_cost" "$static/bin/dispatch_cost"
fi
chmod +x "$ird/init"
# root's files, writable by root only, whoever builds: the helper uses only such modules
chmod -R go-w "$ird"
(cd "$ird" && find . | cpio -o -H newc -R 0:0 --quiet | gzip -1) >"$out/initramfs.cpio.gz"

echo "== booting $kver in qemu (TCG)"
log=$out/console.log
timeout "$timeout_s" qemu-system-x86_64 -machine q35 -accel tcg -cpu max -m 768 -smp 2 \
	-nographic -no-reboot -kernel "/boot/vmlinuz-$kver" -initrd "$out/initramfs.cpio.gz" \
	-parallel null -serial mon:stdio -serial null \
	-append "console=ttyS0 edd=off panic=-1 oops=panic rdinit=/init loglevel=4" \
	</dev/null >"$log" 2>&1 || true
tr -d '\r' <"$log" >"$log.txt"

grep -E '^(KTEST|FAILED:|HALTEST|\| |HAL tests|BENCH)' "$log.txt" || true
echo "($kver: $(($(date +%s) - start)) s)"
done_line=$(grep '^KTEST-DONE' "$log.txt" || true)
if [ -z "$done_line" ]; then
	echo "kernel tests did not finish (crash or timeout); console: $log.txt" >&2
	tail -n 40 "$log.txt" >&2
	echo "0 passed, 1 failed"
	exit 1
fi
set -- $done_line
if grep -qE 'BUG:|WARNING:|Oops|Call Trace' "$log.txt"; then
	echo "kernel reported a problem; console: $log.txt" >&2
	grep -nE -A20 'BUG:|WARNING:|Oops' "$log.txt" | head -n 60 >&2
	echo "$2 passed, $(($3 + 1)) failed"
	exit 1
fi
echo "$2 passed, $3 failed"
[ "$3" = 0 ]
