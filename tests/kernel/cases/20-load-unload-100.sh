# Load/unload cycles with rtapi and hal_lib under the components: afterwards
# /proc/rtapi lists no module, task or shared memory, and the kernel has none of our
# modules left (issue 3: no leak across load/unload cycles). 100 rounds of the core
# set (threads, and2, siggen, sampler, streamer: tasks, FP, FIFOs); every other
# module 3 rounds, which keeps this case to about a minute under qemu's TCG. A module
# that needs arguments args_of() does not know fails its init: that must leave
# nothing behind either, so it is listed, not a failure.
M=$PATH_MOD
check() { if ! eval "$1"; then echo "FAILED: $1"; exit 1; fi; }

# arguments a module needs to load (the rest load with their defaults)
args_of() {
	case $1 in
	threads) echo "name1=t1 period1=1000000 name2=t2 period2=2000000" ;;
	sampler|streamer) echo "cfg=fbsu depth=64" ;;
	stepgen) echo "step_type=0,1" ;;
	pwmgen) echo "output_type=0" ;;
	bldc) echo "cfg=qi6" ;;
	watchdog) echo "num_inputs=2" ;;
	weighted_sum) echo "wsum_sizes=2" ;;
	logic) echo "personality=0x102" ;;
	*) echo "" ;;
	esac
}

# cycle strict|lenient ROUNDS MODULES...: load rtapi, hal_lib and MODULES, unload
# them, check. lenient: a module whose init fails is noted in $refused.
refused=
cycle() {
	mode=$1 rounds=$2; shift 2
	i=0
	while [ $i -lt "$rounds" ]; do
		insmod $M/rtapi.ko
		insmod $M/hal_lib.ko
		loaded=
		for c in "$@"; do
			# shellcheck disable=SC2046
			if insmod $M/$c.ko $(args_of $c) 2>/dev/null; then
				loaded="$c $loaded"
			elif [ "$mode" = strict ]; then
				echo "FAILED: round $i: insmod $c $(args_of $c)"; exit 1
			else
				case " $refused " in *" $c "*) ;; *) refused="$refused $c" ;; esac
			fi
		done
		[ $i = 0 ] && [ "$rounds" -gt 3 ] && cat /proc/rtapi/modules /proc/rtapi/tasks /proc/rtapi/shmem
		for c in $loaded; do rmmod $c; done
		rmmod hal_lib
		check '[ "$(grep -c "^[0-9]" /proc/rtapi/modules)" = 0 ]'
		check '[ "$(grep -c "^[0-9]" /proc/rtapi/tasks)" = 0 ]'
		check '[ "$(grep -c "^[0-9]" /proc/rtapi/shmem)" = 0 ]'
		rmmod rtapi
		i=$((i + 1))
	done
	check '! test -e /proc/rtapi'
	check '[ "$(lsmod | wc -l)" -le 1 ]'
}

core="threads and2 siggen sampler streamer"
others=
for ko in "$M"/*.ko; do
	name=${ko##*/}; name=${name%.ko}
	case " rtapi hal_lib fmt_selftest rtapi_conformance $core " in *" $name "*) ;; *) others="$others $name" ;; esac
done
cycle strict 100 $core
echo "100 rounds of rtapi, hal_lib and $core: nothing left"
# shellcheck disable=SC2086
cycle lenient 3 $others
echo "3 rounds of rtapi, hal_lib and$others: nothing left"
[ -z "$refused" ] || echo "(init failed without arguments, left nothing:$refused)"
