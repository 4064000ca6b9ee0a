#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# latency-test [SECONDS]: thread wake-up error of a 50 us and a 1 ms HAL thread,
# measured by timedelta(9) in each thread: min/avg/max of (time since the previous
# run - period), in ns. Meant for real hardware: run it with HAL_FLAVOR=kernel on a
# PREEMPT_RT machine with the modules installed, or as is for the simulated flavor.
# Prints figures; never fails on them. Inside qemu the numbers are meaningless.
set -u
secs=${1:-10}
export RTAPI_INSTANCE="${RTAPI_INSTANCE:-latency-$$}"
trap 'halrun -U >/dev/null 2>&1' EXIT
halcmd -f <<'HAL' || exit 1
loadrt threads name1=fast period1=50000 name2=slow period2=1000000
loadrt timedelta names=lat-fast,lat-slow
addf lat-fast fast
addf lat-slow slow
start
HAL
sleep 1
halcmd setp lat-fast.reset 1; halcmd setp lat-slow.reset 1
halcmd setp lat-fast.reset 0; halcmd setp lat-slow.reset 0
sleep "$secs"
echo "thread wake-up error over $secs s, flavor ${HAL_FLAVOR:-auto} (ns; negative = early)"
for t in fast:50000 slow:1000000; do
	name=${t%%:*} period=${t#*:}
	min=$(halcmd getp lat-$name.min) max=$(halcmd getp lat-$name.max)
	avg=$(halcmd getp lat-$name.avg-err)
	printf "%-5s %8d ns period: min %8d  avg %10.1f  max %8d\n" "$name" "$period" \
		$((min - period)) "$avg" $((max - period))
done
