#!/bin/sh
# kmod-manifest.sh SRCROOT BUILDDIR [MANIFEST] - prints the components' kbuild lines
# from MANIFEST (default SRCROOT/modules.manifest) and links their sources into
# BUILDDIR (kernel/Makefile.kmod).
# A module whose only source is NAME.c is built from it directly; otherwise its
# objects are listed as NAME-y (NAME.c, the glue, is then compiled as NAME_main.o).
# Only *_fp.o objects are compiled with SSE (the fp column of modules.manifest).
set -eu
src=$1 build=$2 manifest=${3:-$1/modules.manifest}
hdirs=
awk '!/^[ \t]*(#|$)/ { print }' "$manifest" | while read -r name fp sources; do
	case $name in *[!a-z0-9_]*|'') echo "modules.manifest: bad module name '$name'" >&2; exit 1;; esac
	case $fp in fp|nofp) ;; *) echo "modules.manifest: $name: '$fp' is not fp or nofp" >&2; exit 1;; esac
	objs= csources= nfp=0
	for s in $sources; do
		# (no dirname/basename processes: thousands of forks made an unchanged
		# rebuild take minutes on a loaded machine)
		case $s in */*) d=${s%/*} ;; *) d=. ;; esac
		[ -d "$build/$d" ] || mkdir -p "$build/$d"
		case $s in
		*.comp)	# comp(1) output of the CMake build: build/gen/NAME.c (or $COMP_GEN_DIR)
			b=${s%.comp}; gen=${COMP_GEN_DIR:-$src/build/gen}/${b##*/}.c
			if [ ! -f "$gen" ]; then
				echo "modules.manifest: $name: $gen not found: run the CMake build first (it runs comp on $s)" >&2
				exit 1
			fi
			s=${s%.comp}.c
			ln -sfn "$gen" "$build/$s"
			if [ "$fp" = fp ]; then
				# comp's two translation units of one generated file (see gen_c.cpp)
				b=${s%.c}
				for part in main:GLUE fp:FP; do
					printf '#define __COMP_PART_%s\n#include "%s"\n' "${part#*:}" "${s##*/}" \
						>"$build/${b}_${part%%:*}.c.new"
					cmp -s "$build/${b}_${part%%:*}.c.new" "$build/${b}_${part%%:*}.c" &&
						rm "$build/${b}_${part%%:*}.c.new" ||
						mv "$build/${b}_${part%%:*}.c.new" "$build/${b}_${part%%:*}.c"
				done
				objs="$objs ${b}_main.o ${b}_fp.o" nfp=$((nfp + 1))
				csources="${csources:+$csources }${b}_main.c ${b}_fp.c"
				continue
			fi;;
		*/*)	# a path with a directory is relative to kernel/; the headers beside it
			# are linked too, so its #include "x.h" finds them in the build tree
			ln -sfn "$src/kernel/$s" "$build/$s"
			# (once per directory, all in one ln)
			case " $hdirs " in *" $d "*) ;; *)
				hdirs="$hdirs $d"
				set -- "$src/kernel/$d"/*.h
				[ -e "$1" ] && ln -sfn "$@" "$build/$d/";;
			esac;;
		*)	ln -sfn "$src/kernel/components/$s" "$build/$s";;
		esac
		case $s in *_fp.c) nfp=$((nfp + 1));; esac
		objs="$objs ${s%.c}.o"
		csources="${csources:+$csources }$s"
	done
	# fp: the module's FP code is in its *_fp.c sources (or a .comp's FP part), the only
	# objects compiled with SSE; nofp: it has none.
	if [ "$fp" = fp ] && [ "$nfp" = 0 ]; then
		echo "modules.manifest: $name: marked fp but has no *_fp.c source (FP code lives only there)" >&2
		exit 1
	fi
	if [ "$fp" = nofp ] && [ "$nfp" != 0 ]; then
		echo "modules.manifest: $name: marked nofp but has a *_fp.c source" >&2
		exit 1
	fi
	# kbuild: a module of several objects may not have one named like the module, so
	# its NAME.c (the glue) is compiled as NAME_main.o.
	case " $csources " in *" $name.c "*)
		if [ "$csources" != "$name.c" ]; then
			ln -sfn "$(readlink "$build/$name.c")" "$build/${name}_main.c"
			csources=$(echo " $csources " | sed "s| $name.c | ${name}_main.c |; s|^ ||; s| \$||")
			objs=$(echo " $objs " | sed "s| $name.o | ${name}_main.o |; s| *\$||")
		fi;;
	esac
	echo "obj-m += $name.o"
	if [ "$csources" != "$name.c" ]; then
		echo "$name-y :=$objs"
	fi
	for o in $objs; do
		case $o in *_fp.o) echo "\$(eval \$(call fp_object,$o))";; esac
	done
done
