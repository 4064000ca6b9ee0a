#!/bin/sh
# kmod-manifest.sh SRCROOT BUILDDIR [MANIFEST] - prints the components' kbuild lines
# from MANIFEST (default SRCROOT/modules.manifest) and links their sources into
# BUILDDIR (kernel/Makefile.kmod).
# A module whose only source is NAME.c is built from it directly; otherwise its
# objects are listed as NAME-y (a source may then not be called NAME.c).
set -eu
src=$1 build=$2 manifest=${3:-$1/modules.manifest}
awk '!/^[ \t]*(#|$)/ { print }' "$manifest" | while read -r name fp sources; do
	case $name in *[!a-z0-9_]*|'') echo "modules.manifest: bad module name '$name'" >&2; exit 1;; esac
	case $fp in fp|nofp) ;; *) echo "modules.manifest: $name: '$fp' is not fp or nofp" >&2; exit 1;; esac
	objs= csources=
	for s in $sources; do
		mkdir -p "$build/$(dirname "$s")"
		case $s in
		*.comp)	# comp(1) output of the CMake build: build/gen/NAME.c (or $COMP_GEN_DIR)
			gen=${COMP_GEN_DIR:-$src/build/gen}/$(basename "${s%.comp}").c
			if [ ! -f "$gen" ]; then
				echo "modules.manifest: $name: $gen not found: run the CMake build first (it runs comp on $s)" >&2
				exit 1
			fi
			s=${s%.comp}.c
			ln -sfn "$gen" "$build/$s";;
		*/*)	# a path with a directory is relative to kernel/; the headers beside it
			# are linked too, so its #include "x.h" finds them in the build tree
			ln -sfn "$src/kernel/$s" "$build/$s"
			for h in "$src/kernel/$(dirname "$s")"/*.h; do
				[ -e "$h" ] && ln -sfn "$h" "$build/$(dirname "$s")/"
			done;;
		*)	ln -sfn "$src/kernel/components/$s" "$build/$s";;
		esac
		objs="$objs ${s%.c}.o"
		csources="${csources:+$csources }$s"
	done
	echo "obj-m += $name.o"
	if [ "$csources" != "$name.c" ]; then
		case " $csources " in *" $name.c "*)
			echo "modules.manifest: $name: a multi-file module may not have a source $name.c" >&2
			exit 1;;
		esac
		echo "$name-y :=$objs"
	fi
	if [ "$fp" = fp ]; then
		# a module that has *_fp.c sources keeps its FP code there (HELPERS.md):
		# only those objects get SSE; otherwise every object does
		case " $objs " in *_fp.o\ *) only_fp=1;; *) only_fp=0;; esac
		for o in $objs; do
			case $only_fp:$o in
			1:*_fp.o|0:*) echo "\$(eval \$(call fp_object,$o))";;
			esac
		done
	fi
done
