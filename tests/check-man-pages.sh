#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# check-man-pages.sh BUILD_DIR: every program `make install` puts in PREFIX/bin has
# a section-1 manual page beside it (lintian's no-manual-page, caught before the
# packages are built). Installs into a scratch prefix (DESTDIR), lists the programs.
set -eu
build=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
DESTDIR=$tmp cmake --install "$build" --prefix /p > "$tmp/install.log" 2>&1 ||
	{ tail -5 "$tmp/install.log"; echo "check-man-pages: cmake --install failed"; exit 1; }
missing=0
for prog in "$tmp"/p/bin/*; do
	name=$(basename "$prog")
	if [ ! -e "$tmp/p/share/man/man1/$name.1" ]; then
		echo "no manual page for $name (docs/man1/$name.1)"
		missing=$((missing + 1))
	fi
done
n=$(ls "$tmp"/p/bin | wc -l)
[ "$n" -gt 20 ] || { echo "check-man-pages: only $n programs installed"; exit 1; }
echo "$n programs, $missing without a manual page"
[ $missing -eq 0 ]
