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
#        are built one after the other, then tested in parallel VMs, each one's report
#        printed when all are done.
# Python 3 and the hal module go into the VM (tests/python run there); KTEST_PYTHON=0 leaves them out.
# While iterating: KTEST_HAL_DIRS="hal_input serport" packs only those HAL test dirs,
# KTEST_CASES="10 40" runs only the cases whose names start so (e.g. 10-hal-suite).
# KTEST_STEP=build builds everything up to the initramfs and stops; KTEST_STEP=boot
# boots the initramfs built last (so the build runs before taking the qemu lock:
#   KTEST_STEP=build run-kernel-tests.sh K && flock LOCK env KTEST_STEP=boot run-kernel-tests.sh K).
# The modules are built where `make kmod` builds them for that kernel
# (build/kmod/<release>/, kbuild incremental: a rerun with no source change
# rebuilds nothing, and `make kmod` before or after shares the work); with
# KTEST_MANIFEST or KMOD_CFLAGS they go to build/kmod-test/<kver>/modules instead.
# Each step prints its time ("== ... (N s)").
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
	# dynamically and their libraries go into the VM) motmod's motcmd and the motion-tp path
	# check, the test devices' helper, task, io, the bus client, halui and the launcher,
	# the interpreter tool and the path check of tests/demo
	cmake --build "$static" -j"$(nproc)" --target hal_testcomp halmeter shuttlexpress motcmd motion_pathcheck \
		hal_testdev hal_input gs2_vfd gs2_sim milltask iocontrol_io emcbus halui emc launch_probe rs274_tool \
		toolpath_check emcrsh rsh_client >>"$static.log" 2>&1 ||
		{ cat "$static.log" >&2; exit 1; }
}

if [ $# -gt 1 ]; then
	# The builds one after the other (each one uses every core), then the VMs in parallel.
	rc=0
	mkdir -p "$root/build/kmod-test"
	if [ "${KTEST_STEP:-all}" != boot ]; then
		s0=$(date +%s)
		build_static	# once, before the kernels' runs share it
		echo "== static tools built ($(($(date +%s) - s0)) s)"
		for k in "$@"; do
			KTEST_STATIC_READY=1 KTEST_STEP=build "$0" "$k" >"$root/build/kmod-test/$k.report" 2>&1 || rc=1
		done
	else
		for k in "$@"; do : >"$root/build/kmod-test/$k.report"; done
	fi
	if [ $rc = 0 ] && [ "${KTEST_STEP:-all}" != build ]; then
		pids=
		for k in "$@"; do
			KTEST_STEP=boot "$0" "$k" >>"$root/build/kmod-test/$k.report" 2>&1 &
			pids="$pids $!"
		done
		for p in $pids; do wait "$p" || rc=1; done
	fi
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

step=${KTEST_STEP:-all}
case $step in all|build|boot) ;; *) echo "KTEST_STEP must be all, build or boot, not '$step'" >&2; exit 2 ;; esac
t0=$start
# took WHAT: the time since the last step
took() { t1=$(date +%s); echo "== $1 ($((t1 - t0)) s)"; t0=$t1; }

mkdir -p "$out"
if [ "$step" != boot ]; then
# The modules: make kmod's directory for this kernel (the self-test modules are part of
# make kmod's build too, so neither build undoes the other), unless a subset
# (KTEST_MANIFEST: only the modules listed there) or other flags are asked for.
kmod="make -s --no-print-directory -f $root/kernel/Makefile.kmod KDIR=$kdir"
if [ -n "${KTEST_MANIFEST:-}${KMOD_CFLAGS:-}" ]; then
	mods=$out/modules
else
	mods=$($kmod print-KMOD_BUILD)
fi
echo "== building modules for $kver in $mods"
# (-j: with several kernels, their builds run one after the other)
$kmod -j"${JOBS:-$(nproc)}" KMOD_BUILD="$mods" KMOD_WITH_SELFTESTS=1 \
	${KTEST_MANIFEST:+KMOD_MANIFEST="$KTEST_MANIFEST"} ${KMOD_CFLAGS:+KCFLAGS="$KMOD_CFLAGS"} >"$out.build.log" 2>&1 ||
	{ cat "$out.build.log" >&2; exit 1; }
took "modules built"
# the FP rule on the machine code: no FP/SIMD register outside *_fp objects
echo "== checking floating point in the modules (kernel/kmod-fp-check.sh)"
"$root/kernel/kmod-fp-check.sh" "$mods" || exit 1
# no recorded dependency on a kinematics module (modprobe motmod would load one)
"$root/kernel/kmod-deps-check.sh" "$mods" || exit 1
took "modules checked"

if [ -z "${KTEST_STATIC_READY:-}" ]; then build_static; took "static tools built"; fi

echo "== building the initramfs"
rm -rf "$out/initramfs"
ird=$out/initramfs
mkdir -p "$ird/bin" "$ird$vm_moddir/$kver" "$ird/tests/cases" "$ird/tests/hal" \
	"$ird/proc" "$ird/sys" "$ird/dev" "$ird/tmp"
cp /bin/busybox "$ird/bin/busybox"
file -L /bin/busybox | grep -q 'statically linked' ||
	{ echo "/bin/busybox is not static: install busybox-static" >&2; exit 2; }
for ko in $(find "$mods" -name '*.ko'); do
	strip --strip-debug -o "$ird$vm_moddir/$kver/${ko##*/}" "$ko"
done
for tool in halcmd halrun realtime halsampler halstreamer emc_module_helper; do
	strip -o "$ird/bin/$tool" "$static/bin/$tool"
done
for tool in hal_testcomp halmeter shuttlexpress motcmd motion_pathcheck hal_testdev hal_input gs2_vfd gs2_sim \
	milltask io emcbus halui emc launch_probe rs274 toolpath_check emcrsh rsh_client; do
	strip -o "$ird/bin/$tool" "$static/bin/$tool"
done
ln -sf io "$ird/bin/iocontrol"	# task, io, the bus client and halui for tests/task, tests/halui
ln -sf emcrsh "$ird/bin/linuxcncrsh"	# emcrsh's other name (tests/emcrsh)
# the launcher's HAL library and the simulated machines (tests/launcher, tests/configs)
mkdir -p "$ird/share/hal"
cp -r "$root/lib/hallib" "$ird/share/hal/"
cp -r "$root/configs" "$ird/tests/configs"	# where tests/configs/*/ find it (../../../configs)
cp -r "$root/demo" "$ird/tests/demo"	# the demo's machine run, for tests/demo (../../../demo)
# the shared libraries of the dynamic ones, at their paths (with ld.so)
ldd "$static/bin/hal_input" "$static/bin/gs2_vfd" "$static/bin/gs2_sim" 2>/dev/null |
	awk '/=> \// { print $3 } /^\t\/.*ld-linux/ { print $1 }' | sort -u |
	while read -r lib; do
		mkdir -p "$ird${lib%/*}"
		[ -e "$ird$lib" ] || cp -L "$lib" "$ird$lib"
	done
# the kernel's modules for the device tests of cases/40-devices.sh: evdev, uinput,
# hid, uhid, hid-generic for the virtual input devices, parport and parport_pc for
# hal_parport on a port Linux drives (Debian builds them as modules)
mkdir -p "$ird/lib/testdev-modules"
for m in input/evdev input/misc/uinput hid/hid hid/uhid hid/hid-generic parport/parport parport/parport_pc; do
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
took "initramfs built"
[ "$step" = build ] && exit 0
fi	# (not KTEST_STEP=boot)
[ -f "$out/initramfs.cpio.gz" ] || { echo "no $out/initramfs.cpio.gz: run with KTEST_STEP=build first" >&2; exit 2; }

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
