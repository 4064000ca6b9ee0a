#!/bin/sh
# dkms-source.sh SRCROOT DEST GENDIR - the tree DKMS builds from: the realtime
# sources (kernel/, with kbuild's Kbuild, Makefile.kmod and kmod-manifest.sh),
# modules.manifest, and the C that comp generated from the .comp sources
# (build/gen/, where kernel/kmod-manifest.sh looks), as the target machine has no
# comp. Drivers and components added under kernel/ come along by themselves.
set -eu
src=$1 dest=$2 gen=$3
[ -d "$gen" ] || { echo "dkms-source.sh: no generated sources in '$gen'" >&2; exit 1; }
mkdir -p "$dest/build/gen"
cp "$src/modules.manifest" "$dest/"
(cd "$src" && find kernel -type f ! -name CMakeLists.txt ! -name '*.o' ! -name '*.ko' | sort) |
	while read -r f; do
		mkdir -p "$dest/$(dirname "$f")"
		cp "$src/$f" "$dest/$f"
	done
cp "$gen"/*.c "$dest/build/gen/"
