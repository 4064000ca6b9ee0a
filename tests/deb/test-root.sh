#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# test-root.sh CACHE_DIR ROOT - makes ROOT a clean Debian 12 system (debootstrap
# minbase from Debian's mirror) with what the package test needs beyond our
# packages' own dependencies: dkms and both kernels' headers (the -amd64 and
# -rt-amd64 versions installed on this machine, as scripts/kernel-test-deps does),
# plus fresh apt lists so `apt-get install ./x.deb` can fetch anything else.
# The root is cached as CACHE_DIR/root-KEY.tar (KEY: the package list and the
# header versions), so reruns unpack it in seconds instead of bootstrapping.
set -eu
cache=$1 root=$2
mirror=${DEBIAN_MIRROR:-http://deb.debian.org/debian}
security=${DEBIAN_SECURITY_MIRROR:-http://deb.debian.org/debian-security}
kstd=$(ls -d /usr/src/linux-headers-*-amd64 | sed 's|.*/linux-headers-||' | grep -v -- -rt- | sort -V | tail -n 1)
krt=$(ls -d /usr/src/linux-headers-*-rt-amd64 | sed 's|.*/linux-headers-||' | sort -V | tail -n 1)
[ -n "$kstd" ] && [ -n "$krt" ] || { echo "test-root: no -amd64/-rt-amd64 headers: run KERNEL_TEST_RT=1 scripts/kernel-test-deps" >&2; exit 2; }
pkgs="dkms gcc make libc6-dev pkgconf ccache linux-headers-$kstd linux-headers-$krt"
key=$(echo "bookworm $pkgs" | sha256sum | cut -c1-12)
tarball=$cache/root-$key.tar
mkdir -p "$cache"
if [ ! -f "$tarball" ]; then
	echo "== test-root: bootstrapping Debian 12 into $root (cached as $tarball)"
	rm -rf "$root"
	# a second try when the mirror dropped a download (make test runs this in CI)
	debootstrap --variant=minbase bookworm "$root" "$mirror" >"$cache/debootstrap.log" 2>&1 ||
		{ rm -rf "$root"; sleep 10; debootstrap --variant=minbase bookworm "$root" "$mirror" \
			>>"$cache/debootstrap.log" 2>&1; } ||
		{ tail -n 20 "$cache/debootstrap.log" >&2; exit 1; }
	cat >"$root/etc/apt/sources.list" <<LIST
deb $mirror bookworm main
deb $mirror bookworm-updates main
deb $security bookworm-security main
LIST
	# no daemons may start inside the root
	printf '#!/bin/sh\nexit 101\n' >"$root/usr/sbin/policy-rc.d"
	chmod +x "$root/usr/sbin/policy-rc.d"
	install_pkgs() {
		chroot "$root" apt-get update -qq >>"$cache/debootstrap.log" 2>&1
		# shellcheck disable=SC2086
		chroot "$root" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq \
			--no-install-recommends $pkgs >>"$cache/debootstrap.log" 2>&1
	}
	install_pkgs || { sleep 10; install_pkgs; } || { tail -n 20 "$cache/debootstrap.log" >&2; exit 1; }
	chroot "$root" apt-get clean
	tar -C "$root" -cf "$tarball.tmp" . && mv "$tarball.tmp" "$tarball"
	# older roots (other package lists) are of no more use
	find "$cache" -maxdepth 1 -name 'root-*.tar' ! -name "root-$key.tar" -delete
else
	rm -rf "$root"
	mkdir -p "$root"
	tar -C "$root" -xf "$tarball"
fi
echo "$kstd $krt" >"$root/kernels"
