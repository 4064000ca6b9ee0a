#!/bin/sh
# kmod-fp-check.sh DIR... - the kernel flavor's floating-point rule, checked on the
# machine code: disassembles every NAME.ko under each DIR (a kbuild output directory,
# with the NAME.mod object lists kbuild writes) and fails if a function that is not
# FP code touches an FP/SIMD register or instruction. Exit 0 clean, 1 violations, 2 usage.
#
# FP code, precisely: the functions defined in a module's FP objects, which are
#   - objects named *_fp.o: components' realtime FP functions (hand-written *_fp.c,
#     and comp's FP part of a .comp, NAME_fp.o) and hal_lib's FP entry points
#     (hal_param_float_set, which receives a double), called only by FP code, that is
#     from inside an FPU section (a uses_fp thread or rtapi_fpu_begin/end);
#   - in rtapi.ko: rtapi_math*.o (called only by FP code), rtapi_format.o (called by
#     rtapi_print_kmod.c inside kernel_fpu_begin/end) and rtapi_print_entry_kmod.o
#     (the variadic print entries; their prologue saves SSE registers only when the
#     caller passed doubles, %al != 0, i.e. when the caller is FP code).
# Everything else - init/exit, HAL glue, integer realtime functions, hal_lib - runs
# outside FPU sections and must not touch %xmm/%ymm/%zmm/%mm/%st, x87 instructions
# (f*), or the MXCSR/EMMS instructions. A function name defined both in an FP object
# and in another object of the same module is reported too (it could not be told apart).
# Each offending function is one line: MODULE.ko: FUNCTION: 'FIRST INSTRUCTION' (and N more).
set -eu
[ $# -ge 1 ] || { echo "usage: kmod-fp-check.sh KBUILD_OUTPUT_DIR..." >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
bad=0 checked=0

text_symbols() {	# names of the functions defined in the objects given
	[ $# -eq 0 ] || nm --defined-only "$@" 2>/dev/null | awk 'NF == 3 && $2 ~ /^[tTW]$/ { print $3 }' | sort -u
}

for dir in "$@"; do
	[ -d "$dir" ] || { echo "kmod-fp-check: $dir: not a directory" >&2; exit 2; }
	for ko in $(find "$dir" -name '*.ko' | sort); do
		name=$(basename "$ko" .ko)
		mod=${ko%.ko}.mod
		[ -f "$mod" ] || { echo "kmod-fp-check: $ko: no $mod (not a kbuild output directory?)" >&2; exit 2; }
		fp_objs= other_objs=
		for o in $(cat "$mod"); do
			# kbuild lists objects by path (absolute, or relative to the output
			# directory); drivers' objects sit in subdirectories of it
			if [ ! -f "$o" ]; then
				if [ -f "$(dirname "$ko")/$o" ]; then o=$(dirname "$ko")/$o
				else o=$(dirname "$ko")/$(basename "$o"); fi
			fi
			case $name:$(basename "$o") in
			*:*_fp.o|rtapi:rtapi_math*.o|rtapi:rtapi_format.o|rtapi:rtapi_print_entry_kmod.o)
				fp_objs="$fp_objs $o";;
			*)	other_objs="$other_objs $o";;
			esac
		done
		# shellcheck disable=SC2086
		text_symbols $fp_objs >"$tmp/fp"
		# shellcheck disable=SC2086
		text_symbols $other_objs >"$tmp/other"
		for f in $(comm -12 "$tmp/fp" "$tmp/other"); do
			echo "$name.ko: $f: defined both in an FP object and in a non-FP one"
			bad=1
		done
		objdump -d --no-show-raw-insn "$ko" | awk -v mod="$name.ko" -v fpfile="$tmp/fp" '
			BEGIN { while ((getline l < fpfile) > 0) fp[l] = 1 }
			function report() {
				if (n) print mod ": " fn ": " first (n > 1 ? " (and " n - 1 " more)" : "")
				n = 0
			}
			/^[0-9a-f]+ <.*>:$/ { report(); fn = substr($2, 2, length($2) - 3); next }
			/^ *[0-9a-f]+:\t/ {
				if (fn in fp) next
				sub(/^ *[0-9a-f]+:\t/, "")
				split($0, w, /[ \t]+/)
				m = w[1]
				if ($0 ~ /%[xyz]mm[0-9]|%mm[0-7]|%st([^a-z]|$)/ || m ~ /^f[a-z0-9]+$/ ||
				    m ~ /^(ldmxcsr|stmxcsr|emms|fxsave|fxrstor)/) {
					gsub(/[ \t]+/, " ")
					sub(/ *#.*/, "")
					if (!n++) first = "\047" $0 "\047"
					found = 1
				}
			}
			END { report(); exit found ? 1 : 0 }' || bad=1
		checked=$((checked + 1))
	done
done
if [ "$checked" -eq 0 ]; then
	echo "kmod-fp-check: no .ko files under $*" >&2
	exit 2
fi
if [ "$bad" -ne 0 ]; then
	echo "kmod-fp-check: FP/SIMD registers used outside FP objects (see above; FP code belongs in *_fp.c)" >&2
	exit 1
fi
echo "kmod-fp-check: $checked modules clean"
