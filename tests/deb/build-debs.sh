#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# build-debs.sh OUTDIR - builds the Debian packages (debian/: debhelper, dh-dkms)
# from a copy of this tree's files (tracked and new, not ignored ones) in
# OUTDIR/src/hal-VERSION, so nothing is written outside OUTDIR; the .debs and
# .changes land in OUTDIR/src and are moved to OUTDIR, then lintian checks them
# (any warning or error fails). The copy keeps its path, so ccache makes
# rebuilds fast.
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
mkdir -p "$1"
out=$(cd "$1" && pwd)
version=$(cd "$root" && dpkg-parsechangelog -SVersion)
src=$out/src/hal-$version
start=$(date +%s)

echo "== copying the tree to $src"
mkdir -p "$src"
# files removed from the tree must not linger in the copy
(cd "$root" && git ls-files -co --exclude-standard) | sort >"$out/files.new"
if [ -f "$out/files.list" ]; then
	comm -23 "$out/files.list" "$out/files.new" | while read -r f; do rm -f "$src/$f"; done
fi
mv "$out/files.new" "$out/files.list"
(cd "$root" && tar -cf - -T "$out/files.list") | (cd "$src" && tar -xpf -)
rm -f "$out"/*.deb "$out"/*.changes "$out"/*.buildinfo

echo "== dpkg-buildpackage (log: $out/build.log)"
# Incremental: no clean before (-nc) keeps obj-*/ from the last run, but dh's
# stamps go, so every step runs again and make rebuilds what changed.
rm -f "$src"/debian/debhelper-build-stamp "$src"/debian/*.debhelper.log
rm -rf "$src"/debian/hal "$src"/debian/hal-dev "$src"/debian/hal-dkms "$src"/debian/tmp
(cd "$src" && DEB_BUILD_OPTIONS="parallel=$(nproc) ${DEB_BUILD_OPTIONS:-}" \
	dpkg-buildpackage -b -nc -us -uc) >"$out/build.log" 2>&1 ||
	{ tail -n 40 "$out/build.log" >&2; echo "build-debs: dpkg-buildpackage failed" >&2; exit 1; }
mv "$out"/src/*.deb "$out"/src/*.changes "$out"/src/*.buildinfo "$out/"
ls "$out"/*.deb

echo "== lintian"
lintian --fail-on error,warning --suppress-tags-from-file "$root/tests/deb/lintian-ignore" \
	"$out"/*.changes >"$out/lintian.log" 2>&1 || { cat "$out/lintian.log" >&2; echo "build-debs: lintian found problems" >&2; exit 1; }
cat "$out/lintian.log"
echo "lintian: no errors or warnings"
echo "(packages built and checked in $(($(date +%s) - start)) s)"
