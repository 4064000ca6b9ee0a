#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# mill-run.sh OUTDIR - the simulated mill runs its sample program while its joints are
# sampled (shared by make demo and tests/demo; POSIX sh, so it runs in the test VM's
# busybox too). Steps: configs/sim copied to OUTDIR/cfg (task writes its parameter
# file beside the INI); "emc -v mill.ini" started headless; the drive step homes it;
# sample.hal loaded and halsampler started; the drive step runs mill.ngc to its end;
# halsampler and the launcher stopped (SIGTERM: the launcher's full clean-up); then
# nothing of the HAL may be left. rs274 writes the program's canonical calls, from the
# position the machine started the program at.
# Writes OUTDIR/samples.txt (X Y Z per servo period), OUTDIR/canon.txt, OUTDIR/emc.log.
# The drive step is demo/drive-emcrsh.sh (through emcrsh, as a telnet user), or the
# program named by $DEMO_DRIVE (same arguments; demo/drive-emcbus.sh talks to task's
# bus directly). $DEMO_PROGRAM runs another G-code file instead of mill.ngc (the
# failure tests). Exit 0, or 1 with "mill-run: what failed" on stderr after cleaning up.
set -u
out=${1:?usage: mill-run.sh OUTDIR}
here=$(cd "$(dirname "$0")" && pwd)
. "$here/wait-output.sh"
drive=${DEMO_DRIVE:-$here/drive-emcrsh.sh}
mkdir -p "$out" || exit 1
out=$(cd "$out" && pwd)
cfg=$out/cfg
ini=$cfg/mill.ini
export EMC_LOCK_FILE="$out/emc.lock" EMC_RC_FILE="$out/emcrc"
emc_pid=
hs_pid=

stop_all() {
	[ -z "$hs_pid" ] || { kill -TERM "$hs_pid" 2>/dev/null; wait "$hs_pid"; }
	hs_pid=
	[ -z "$emc_pid" ] || { kill -TERM "$emc_pid" 2>/dev/null; wait "$emc_pid"; }
	emc_pid=
}
fail() {
	echo "mill-run: $*" >&2
	stop_all
	exit 1
}
trap 'fail "interrupted"' INT TERM

rm -rf "$cfg" "$out/samples.txt" "$out/canon.txt"
cp -r "$here/../configs/sim" "$cfg" || fail "cannot copy configs/sim to $cfg"
rm -f "$cfg"/*.var*	# a clean parameter file: no offsets left from another run

: > "$out/emc.log"	# exists before the wait below reads it
emc -v "$ini" > "$out/emc.log" 2>&1 < /dev/null &
emc_pid=$!
if ! wait_output "$out/emc.log" "$emc_pid" 60 '/running headless/p' > /dev/null; then
	sed 's/^/  emc: /' "$out/emc.log" >&2
	fail "the machine did not come up (emc $ini)"
fi

"$drive" home "$ini" || fail "homing failed"
halcmd -f "$here/sample.hal" || fail "cannot load the sampler (demo/sample.hal)"
halsampler -c 0 "$out/samples.txt" &
hs_pid=$!
program=${DEMO_PROGRAM:-$cfg/mill.ngc}
"$drive" run "$ini" "$program" || fail "running $(basename "$program") failed"
# a few samples at rest after the end
sleep 0.2
kill -TERM "$hs_pid"
wait "$hs_pid"
hs_pid=
kill -TERM "$emc_pid"
wait "$emc_pid"
rc=$?
emc_pid=
[ $rc -eq 0 ] || { sed 's/^/  emc: /' "$out/emc.log" >&2; fail "the launcher exited with status $rc"; }
if [ "${HAL_TEST_FLAVOR:-sim}" = kernel ]; then
	! grep -q '^hal_lib ' /proc/modules || fail "hal_lib is still loaded after the launcher's clean-up"
else
	left=$(ls /dev/shm | grep -c -- "-${RTAPI_INSTANCE:-0}-")
	[ "$left" -eq 0 ] || fail "$left shared memory segments left after the launcher's clean-up"
fi

# the path: the program from where the machine stood when it started (the first sample)
set -- $(sed -n 1p "$out/samples.txt")
[ $# -eq 3 ] || fail "no samples in $out/samples.txt"
{ echo "G53 G0 X$1 Y$2 Z$3"; cat "$program"; } | rs274 -i "$ini" -n - > "$out/canon.txt" ||
	fail "rs274 cannot run $(basename "$program")"
exit 0
