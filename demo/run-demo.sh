#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# make demo: the simulated three-axis mill (configs/sim/mill.ini) is started headless
# in the simulated-realtime flavor, homed through emcrsh (demo/drive-emcrsh.sh, or
# $DEMO_DRIVE), runs its sample program configs/sim/mill.ngc
# to the end while its joint positions are sampled every servo period, and is shut
# down; the samples are checked against the program's path (toolpath_check) and drawn
# (BUILD/demo/toolpath.png and .svg). Exit 0, or 1 with "demo: FAILED: ...".
# Usage: run-demo.sh [BUILD]   (default build)
set -u
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "${1:-build}" 2>/dev/null && pwd) || { echo "demo: FAILED: no build directory ${1:-build}" >&2; exit 1; }
PATH="$build/bin:$PATH"
export PATH
# its own RTAPI instance: the demo's HAL does not meet another one running
export RTAPI_INSTANCE="${RTAPI_INSTANCE:-demo$$}"
out=$build/demo
failed() {
	echo "demo: FAILED: $*" >&2
	echo "demo: logs in $out (emc.log: the launcher's output)" >&2
	exit 1
}
for prog in emc milltask io emcrsh rsh_client halsampler rs274 toolpath_check; do
	command -v $prog > /dev/null 2>&1 || failed "$prog is not built (make build)"
done

start=$(date +%s)
echo "demo: starting the simulated mill: emc configs/sim/mill.ini (headless, simulated flavor)"
echo "demo: through emcrsh: homing, then running configs/sim/mill.ngc while sampling joint.0-2.pos-fb"
"$here/mill-run.sh" "$out" || failed "the machine run did not complete (see the message above)"
echo "demo: the machine ran the program and shut down cleanly ($(($(date +%s) - start)) s)"

echo "demo: sampled joint positions against the program's path (rs274):"
toolpath_check check "$out/canon.txt" "$out/samples.txt" > "$out/check.txt"
rc=$?
sed 's/^/demo:   /' "$out/check.txt"
[ $rc -eq 0 ] || failed "the sampled path is not the program's path"

period=$(sed -n 's/^SERVO_PERIOD *= *\([0-9]*\).*/\1/p' "$out/cfg/mill.ini")
"$here/plot-toolpath.sh" "$out" "$(awk "BEGIN { print $period / 1e9 }")" || failed "cannot draw the toolpath"
echo "demo: the toolpath picture: $out/toolpath.png (and $out/toolpath.svg)"
