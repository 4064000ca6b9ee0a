#!/bin/sh
# vm-python.sh STATIC_BUILD INITRAMFS_DIR - puts python3 into the kernel-test VM's
# initramfs: Debian's interpreter as /bin/python3 (its stdlib where it was built to
# look, /usr/lib/python3.X), the shared libraries it and the kept extension modules need (with
# ld.so at its usual path), the stdlib without what no test imports (tests, IDLE,
# tkinter, distutils, build config, extensions needing more libraries), and the
# 'hal' module from STATIC_BUILD where halcmd/halrun put it on PYTHONPATH (/bin/..).
set -eu
static=$1 ird=$2
py=$(readlink -f /usr/bin/python3)
ver=${py##*/}				# python3.11
stdlib=/usr/lib/$ver
mod=$(find "$static/lib" -path '*dist-packages/hal.*.so' | head -n 1)
[ -n "$mod" ] || { echo "vm-python: no hal module in $static/lib" >&2; exit 1; }

# copy_libs FILE...: the shared libraries the files need, at the same paths
copy_libs() {
	ldd "$@" 2>/dev/null | awk '/=> \// { print $3 } /^\t\/.*ld-linux/ { print $1 }' | sort -u |
	while read -r lib; do
		mkdir -p "$ird${lib%/*}"
		[ -e "$ird$lib" ] || cp -L "$lib" "$ird$lib"
	done
}

mkdir -p "$ird/usr/lib/$ver" "$ird/lib64"
cp "$py" "$ird/bin/python3"
(cd "$stdlib" && tar cf - --exclude=./test --exclude=./idlelib --exclude=./tkinter \
	--exclude=./turtledemo --exclude=./ensurepip --exclude=./lib2to3 --exclude=./pydoc_data \
	--exclude=./distutils --exclude='./config-*' --exclude=./site-packages \
	--exclude=./dist-packages --exclude=./lib-dynload --exclude='./*/tests' \
	--exclude='./*/test' .) | tar xf - -C "$ird/usr/lib/$ver"
# extension modules that need nothing beyond libc/libm/libz (no ssl, sqlite, curses...)
mkdir -p "$ird/usr/lib/$ver/lib-dynload"
for so in "$stdlib"/lib-dynload/*.so; do
	case ${so##*/} in _test*|xx*|_ctypes_test*) continue ;; esac
	extra=$(ldd "$so" | awk '/=> \// { print $1 }' | grep -vE '^(libc|libm|libz)\.so' || true)
	[ -z "$extra" ] && cp "$so" "$ird/usr/lib/$ver/lib-dynload/"
done
dest=$ird/lib/python3/dist-packages
mkdir -p "$dest"
cp "$mod" "$dest/"
strip --strip-unneeded "$dest/${mod##*/}"
copy_libs "$py" "$ird/usr/lib/$ver"/lib-dynload/*.so "$dest/${mod##*/}"
