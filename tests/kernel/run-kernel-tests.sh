#!/bin/sh
# run-kernel-tests.sh - kernel-flavor tests: builds the modules against Debian's
# linux-headers-<ver>-amd64, packs them with busybox and the static test tools into
# an initramfs, boots /boot/vmlinuz-<ver> in qemu (TCG, no KVM needed), runs
# tests/kernel/cases/*.sh inside and reports from the serial console.
# Usage: run-kernel-tests.sh [KERNEL_RELEASE]   (default: newest installed non-rt -amd64;
#        e.g. 6.1.0-56-rt-amd64 for the PREEMPT_RT kernel)
# Needs: scripts/kernel-test-deps. Exit 0 when every case passed.
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
here=$root/tests/kernel
kver=${1:-$(ls /boot | sed -n 's/^vmlinuz-\(.*-amd64\)$/\1/p' | grep -v -- -rt- | sort -V | tail -n 1)}
[ -n "$kver" ] || { echo "no /boot/vmlinuz-*-amd64: run scripts/kernel-test-deps" >&2; exit 2; }
kdir=/usr/src/linux-headers-$kver
[ -d "$kdir" ] || { echo "no $kdir: run scripts/kernel-test-deps" >&2; exit 2; }
out=${KTEST_BUILD:-$root/build/kmod-test/$kver}
timeout_s=${KTEST_TIMEOUT:-300}

mkdir -p "$out"
echo "== building modules for $kver"
make -s -f "$root/kernel/Makefile.kmod" KDIR="$kdir" KMOD_BUILD="$out/modules" ${KMOD_CFLAGS:+KCFLAGS="$KMOD_CFLAGS"} >"$out.build.log" 2>&1 ||
	{ mkdir -p "$out"; cat "$out.build.log" >&2; exit 1; }

echo "== building the initramfs"
rm -rf "$out/initramfs"
mkdir -p "$out/initramfs/bin" "$out/initramfs/lib/rtmod" "$out/initramfs/tests/cases" \
	"$out/initramfs/proc" "$out/initramfs/sys" "$out/initramfs/dev"
cp /bin/busybox "$out/initramfs/bin/busybox"
file -L /bin/busybox | grep -q 'statically linked' ||
	{ echo "/bin/busybox is not static: install busybox-static" >&2; exit 2; }
for ko in $(find "$out/modules" -name '*.ko'); do
	strip --strip-debug -o "$out/initramfs/lib/rtmod/${ko##*/}" "$ko"
done
cc -static -O2 -Wall -I"$root/kernel/rtapi" -I"$root/kernel/hal" \
	-o "$out/initramfs/tests/hal_segcheck" "$here/hal_segcheck.c"
cp "$here/init.sh" "$out/initramfs/init"
cp "$here"/cases/*.sh "$out/initramfs/tests/cases/"
chmod +x "$out/initramfs/init"
(cd "$out/initramfs" && find . | cpio -o -H newc --quiet | gzip -1) >"$out/initramfs.cpio.gz"

echo "== booting $kver in qemu (TCG)"
log=$out/console.log
timeout "$timeout_s" qemu-system-x86_64 -machine q35 -accel tcg -cpu max -m 512 -smp 2 \
	-nographic -no-reboot -kernel "/boot/vmlinuz-$kver" -initrd "$out/initramfs.cpio.gz" \
	-append "console=ttyS0 edd=off panic=-1 oops=panic rdinit=/init loglevel=4" \
	</dev/null >"$log" 2>&1 || true
tr -d '\r' <"$log" >"$log.txt"

grep -E '^(KTEST|FAILED:)' "$log.txt" || true
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
