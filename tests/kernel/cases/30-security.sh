# Issue 9 (docs/kernel-security.md): who may do what in the kernel flavor.
#  - uid 65534 (not in group 'hal') cannot open /dev/rtapi nor run the helper;
#  - a 'hal' member cannot write any kernel-visible pointer, offset or size
#    (hal_exploit tries each class; nothing may be EXPLOITED, no oops);
#  - a killed holder of the HAL mutex is recovered, with a message naming it;
#  - a module whose function is on a running thread cannot be unloaded under it;
#  - two loadrt's at once, 100 times, leave each module its own components and memory.
check() { if ! eval "$1"; then echo "FAILED: $1"; exit 1; fi; }
asu() { su haluser -s /bin/sh -c "cd /home/haluser && PATH=$PATH HAL_FLAVOR=kernel $1"; }
oops() { dmesg | grep -E 'Oops|general protection|BUG:|Call Trace' ; }

asu 'halcmd loadrt threads name1=t period1=1000000 && halcmd loadrt siggen && halcmd loadrt sampler cfg=ff depth=64 && halcmd net s siggen.0.sine sampler.0.pin.0 && halcmd addf siggen.0.update t && halcmd addf sampler.0 t && halcmd start'
check 'test "$(stat -c %a:%g /dev/rtapi)" = 660:990'
# (busybox's setpriv cannot change ids: su to nobody, uid 65534 in no group of ours)
check '! su -s /bin/sh nobody -c "exec 3</dev/rtapi" 2>/dev/null'
check '! su -s /bin/sh nobody -c "/bin/emc_module_helper remove siggen" 2>/dev/null'
check 'lsmod | grep -q "^siggen"'
rc=0; out=$(su -s /bin/sh nobody -c "HAL_FLAVOR=kernel PATH=$PATH halcmd show comp" 2>&1) || rc=$?
echo "  as uid 65534: halcmd show comp: exit $rc: $out"
check '[ $rc != 0 ]'

rc=0; out=$(asu 'hal_exploit 0x48534d00') || rc=$?
echo "$out" | sed 's/^/  /'
check '[ $rc = 0 ]'
check '! echo "$out" | grep -q EXPLOITED'
check 'echo "$out" | grep -q "REFUSED write to a thread list entry"'
check 'echo "$out" | grep -q "REFUSED write to a kernel component.s pin pointer slot"'
check 'echo "$out" | grep -q "REFUSED pin_new aimed at a kernel pin pointer slot"'
check 'echo "$out" | grep -q "REFUSED write to a dispatch slot.s code address"'
check 'echo "$out" | grep -q "REFUSED write to a thread.s dispatch table offset"'
check '[ -z "$(oops)" ]'
# the HAL still works after all that
c1=$(asu 'halcmd -s show thread' | wc -l)
check 'asu "halcmd setp siggen.0.amplitude 2"'
check 'asu "halcmd getp siggen.0.amplitude" | grep -qx 2'

# a killed holder of the HAL mutex
asu 'hal_exploit hold' >/tmp/hold.out &
sleep 1
check 'grep -q holding /tmp/hold.out'
kill -9 $(pidof hal_exploit)
sleep 1
check 'timeout 20 su haluser -s /bin/sh -c "HAL_FLAVOR=kernel halcmd show comp" >/dev/null'
check 'dmesg | grep -q "went away holding the HAL mutex: released"'

# unloading a module whose function is running: refused, never freed under the thread
check '! rmmod siggen 2>/dev/null'
check 'lsmod | grep -q "^siggen"'
check 'asu "halcmd unloadrt siggen"'
check '! lsmod | grep -q "^siggen"'
sleep 1
check 'asu "halcmd -s show thread" | grep -q sampler.0'
check '[ -z "$(oops)" ]'
asu 'halrun -U'

# two loadrt's at once, 100 times: each module keeps its own components and memory
M=$PATH_MOD
insmod $M/rtapi.ko; insmod $M/hal_lib.ko
base=$(hal_segcheck)
i=0
while [ $i -lt 100 ]; do
	insmod $M/and2.ko count=3 & insmod $M/or2.ko count=2 & wait
	check 'hal_segcheck | grep -q "comps=2 pins=20 "'
	rmmod and2
	check 'hal_segcheck | grep -q "comps=1 pins=8 params=2 "'
	rmmod or2
	check '[ "$(hal_segcheck)" = "$base" ]'
	i=$((i + 1))
done
rmmod hal_lib; rmmod rtapi
check '[ -z "$(oops)" ]'
echo "security: all checks passed"
