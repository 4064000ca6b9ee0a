#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# run-package-test.sh DEBDIR - installs the packages of DEBDIR (make deb) into a
# clean Debian 12 root (tests/deb/test-root.sh, cached under build/pkgtest/) and
# checks there, as a user would:
#   - the hal group, emc_module_helper 4750 root:hal, the udev rule, a man page
#     for every program, bash completion;
#   - halrun of a small HAL file, as a member of the hal group, output compared;
#   - an out-of-tree realtime component built with `pkg-config --cflags hal`
#     and one with comp --compile, both loaded;
#   - hal-dkms: built and installed for both kernels (-amd64, -rt-amd64) when
#     installed; `dkms build` for both; rebuilt by dkms's kernel hook after a
#     kernel (headers) upgrade.
# Needs root (chroot, mounts) and Debian's mirror. Prints "N passed, M failed".
set -eu
root_dir=$(cd "$(dirname "$0")/../.." && pwd)
debs=$(cd "${1:?usage: run-package-test.sh DEBDIR}" && pwd)
cache=${PKGTEST_CACHE:-$root_dir/build/pkgtest}
chroot_dir=$cache/root
start=$(date +%s)
[ "$(id -u)" = 0 ] || exec sudo -E "$0" "$@"
ls "$debs"/hal_*.deb "$debs"/hal-dkms_*.deb "$debs"/hal-dev_*.deb >/dev/null ||
	{ echo "run-package-test: no packages in $debs (make deb)" >&2; exit 2; }

umount_all() {
	for m in dev/shm ccache proc; do
		mountpoint -q "$chroot_dir/$m" && umount "$chroot_dir/$m"
	done
	return 0
}
trap umount_all EXIT
umount_all
"$root_dir/tests/deb/test-root.sh" "$cache" "$chroot_dir"
read -r kstd krt <"$chroot_dir/kernels"
mkdir -p "$chroot_dir/tmp/debs" "$chroot_dir/ccache" "$cache/ccache"
cp "$debs"/*.deb "$chroot_dir/tmp/debs/"
mount -t proc proc "$chroot_dir/proc"
mount -t tmpfs -o mode=1777 shm "$chroot_dir/dev/shm"
# ccache kept between runs: the modules' rebuilds after the first are cheap
mount --bind "$cache/ccache" "$chroot_dir/ccache"
cp "$root_dir/tests/deb/in-root.sh" "$chroot_dir/tmp/in-root.sh"
echo "== installing the packages and checking them (in $chroot_dir)"
rc=0
chroot "$chroot_dir" env -i PATH=/usr/lib/ccache:/usr/sbin:/usr/bin:/sbin:/bin \
	CCACHE_DIR=/ccache HOME=/root LANG=C.UTF-8 DEBIAN_FRONTEND=noninteractive \
	sh /tmp/in-root.sh "$kstd" "$krt" || rc=$?
echo "(package test: $(($(date +%s) - start)) s)"
exit $rc
