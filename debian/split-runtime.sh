#!/bin/sh
# split-runtime.sh TMP DEV RUNTIME - copies every file and link under TMP (what
# CMake installed) that the -dev package did not take into RUNTIME.
set -eu
tmp=$(cd "$1" && pwd) dev=$(cd "$2" && pwd)
mkdir -p "$3"
runtime=$(cd "$3" && pwd)
cd "$tmp"
find . \( -type f -o -type l \) | sort | while read -r f; do
	if [ -e "$dev/$f" ] || [ -L "$dev/$f" ]; then continue; fi
	mkdir -p "$runtime/$(dirname "$f")"
	cp -a "$f" "$runtime/$f"
done
