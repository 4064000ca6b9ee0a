#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# task-bench.sh [BUILD] - task's sustained queue throughput into motion: a simulated
# three-axis mill (trivkins, 1 ms servo thread), io and milltask from a scratch INI;
# a generated program of N short G1 moves (0.1 mm at 6 m/min: the planner uses one
# segment per 1 ms period, as fast as motion takes commands) runs in AUTO. Prints
# segments per second from RUN to the program's end, and the smallest motion queue
# depth seen mid-run (0 = the planner starved). Figures only; never fails on them.
set -u
build=$(cd "${1:-build}" && pwd)
here=$(cd "$(dirname "$0")" && pwd)
export PATH="$build/bin:$PATH"
export RTAPI_INSTANCE="taskbench-$$"
n=${TASK_BENCH_SEGMENTS:-5000}
tmp=$(mktemp -d)
trap 'halcmd unloadusr iocontrol >/dev/null 2>&1; halcmd unloadusr inihal >/dev/null 2>&1; halrun -U >/dev/null 2>&1; rm -rf "$tmp"' EXIT
cp "$here/../tests/task/common/sim.ini" "$here/../tests/task/common/sim.tbl" "$tmp"/
sed -i 's/^CYCLE_TIME = 0.010$/CYCLE_TIME = 0.001/' "$tmp/sim.ini"
bus() { emcbus -bus "$tmp/bus.sock" "$@"; }
awk -v n="$n" 'BEGIN { print "G21 G90 G64 P0.01"; print "G0 X0 Y0 Z0"; print "F6000"
	for (i = 1; i <= n; i++) { x = (i % 2000) * 0.1; y = int(i / 2000) * 0.1
		printf "G1 X%.1f Y%.1f\n", x, y }
	print "M2" }' > "$tmp/prog.ngc"
halrun -U >/dev/null 2>&1
{ halcmd -f "$here/../tests/task/common/machine.hal" &&
  halcmd loadusr -Wn iocontrol io -ini "$tmp/sim.ini" -bus "$tmp/bus.sock" &&
  halcmd net estop-loop iocontrol.0.user-enable-out iocontrol.0.emc-enable-in &&
  halcmd start &&
  halcmd loadusr -Wn inihal milltask -ini "$tmp/sim.ini" -bus "$tmp/bus.sock" &&
  bus wait task.motion_ready 1 10 && bus wait io.connected 1 10 &&
  bus state estop_reset && bus state on && bus mode manual && bus home -1 &&
  bus wait traj.all_homed 1 10 && bus mode auto && bus open "$tmp/prog.ngc"; } >/dev/null ||
	{ echo "task-bench: set-up failed"; exit 1; }
t0=$(date +%s.%N)
bus run || exit 1
min=100000
while :; do
	set -- $(bus status task.interp traj.queue task.motion_line)
	[ "$1" = IDLE ] && break
	# mid-run: after the first lines, before the last ones were sent
	if [ "$3" -gt 100 ] && [ "$3" -lt $((n - 100)) ] && [ "$2" -lt "$min" ]; then min=$2; fi
	sleep 0.05
done
t1=$(date +%s.%N)
awk -v n="$n" -v t0="$t0" -v t1="$t1" -v min="$min" 'BEGIN {
	printf "task -> motion: %d segments in %.2f s = %.0f segments/s (planner demand 1000/s); smallest motion queue mid-run %d\n",
		n, t1 - t0, n / (t1 - t0), min }'
