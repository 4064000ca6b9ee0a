#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# run-fuzz.sh BUILD SECONDS - run every libFuzzer target in BUILD (tests/fuzz built
# with clang) for SECONDS each, starting from seeds taken from the test files:
# .hal files for halcmd, .ini files, .comp sources, streamer inputs, and the small
# hand-written seeds in tests/fuzz/seeds/. New corpus entries and crash reproducers
# go to BUILD/corpus/ and BUILD/crashes/. Exit status 1 if any target found a crash.
# FUZZ_JOBS: targets run at a time (default: the number of cores).
set -u
build=${1:?usage: run-fuzz.sh BUILD SECONDS}
seconds=${2:?usage: run-fuzz.sh BUILD SECONDS}
src=$(cd "$(dirname "$0")/../.." && pwd)
corpus=$build/corpus
mkdir -p "$build/crashes"

# seed TARGET FILES...: copy test files into the target's corpus (once; the corpus
# keeps what earlier runs found).
seed() {
	t=$1
	shift
	mkdir -p "$corpus/$t"
	for f in "$@"; do
		[ -f "$f" ] || continue
		n=$(printf '%s' "$f" | cksum | cut -d' ' -f1)
		[ -e "$corpus/$t/seed-$n" ] || head -c 65536 "$f" > "$corpus/$t/seed-$n"
	done
}
seed fuzz_halcmd_line $(find "$src/tests" "$src/demo" -name '*.hal' 2>/dev/null | head -300)
seed fuzz_ini $(find "$src/tests" "$src/demo" -name '*.ini' 2>/dev/null) "$src"/tests/fuzz/seeds/ini/*
seed fuzz_values "$src/tests/fuzz/seeds/module_args/basic"
seed fuzz_module_args "$src"/tests/fuzz/seeds/module_args/*
seed fuzz_protocol "$src"/tests/fuzz/seeds/protocol/*
# The loadrt lines of the test files: their arguments for the module argument parser,
# as "load MOD ARGS" requests for the daemon's protocol (one seed per distinct line).
find "$src/tests" "$src/demo" -name '*.hal' -exec grep -h '^[[:space:]]*loadrt[[:space:]]' {} + 2>/dev/null |
	sed 's/^[[:space:]]*loadrt[[:space:]]*//; s/[[:space:]]*#.*//' | sort -u | head -200 |
	while IFS= read -r line; do
		n=$(printf '%s' "$line" | cksum | cut -d' ' -f1)
		[ -e "$corpus/fuzz_protocol/load-$n" ] || printf '\001load %s\n' "$line" > "$corpus/fuzz_protocol/load-$n"
		args=${line#* }
		[ "$args" = "$line" ] && continue
		[ -e "$corpus/fuzz_module_args/args-$n" ] || printf '%s' "$args" > "$corpus/fuzz_module_args/args-$n"
	done
seed fuzz_stream_line "$src"/tests/fuzz/seeds/stream_line/*
seed fuzz_comp "$src"/kernel/components/*.comp
seed fuzz_rs274 "$src"/tests/interp/programs/*.ngc "$src"/tests/interp/subs/*.ngc
for v in 0 1 TRUE false -7 0x7fffffff 4294967295 2.5 -1e-3 0x1p4 1e308 nan; do
	mkdir -p "$corpus/fuzz_values"
	printf '%s' "$v" > "$corpus/fuzz_values/v-$v"
done

# fuzz TARGET: one target for SECONDS; its verdict into BUILD/TARGET.status
fuzz() {
	t=$1 log=$build/$1.log
	if "$build/$t" -max_total_time="$seconds" -max_len=65536 -timeout=10 -rss_limit_mb=2048 \
		-artifact_prefix="$build/crashes/$t-" -print_final_stats=1 \
		"$corpus/$t" > "$log" 2>&1; then
		echo ok > "$build/$t.status"
	else
		echo failed > "$build/$t.status"
	fi
}

# FUZZ_JOBS targets at a time (default: the number of cores; each target is one
# process, so each still gets a core for its SECONDS)
jobs=${FUZZ_JOBS:-$(nproc 2>/dev/null || echo 1)}
targets="fuzz_halcmd_line fuzz_ini fuzz_values fuzz_module_args fuzz_protocol fuzz_stream_line fuzz_comp fuzz_rs274"
status=0
running=0
for t in $targets; do
	rm -f "$build/$t.status"
	if [ ! -x "$build/$t" ]; then
		echo "run-fuzz: $build/$t not built" >&2
		status=1
		continue
	fi
	fuzz "$t" &
	running=$((running + 1))
	if [ $running -ge "$jobs" ]; then wait; running=0; fi
done
wait
for t in $targets; do
	[ -x "$build/$t" ] || continue
	if [ "$(cat "$build/$t.status" 2>/dev/null)" = ok ]; then
		echo "run-fuzz: $t: $(grep -o 'stat::number_of_executed_units: *[0-9]*' "$build/$t.log" | grep -o '[0-9]*$') runs in ${seconds} s, no crash"
	else
		echo "run-fuzz: $t FAILED (reproducer in $build/crashes/):" >&2
		tail -40 "$build/$t.log" >&2
		status=1
	fi
done
exit $status
