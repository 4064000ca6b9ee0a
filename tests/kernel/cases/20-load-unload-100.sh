# Every component module, loaded and unloaded 100 times with rtapi and hal_lib under
# them: afterwards /proc/rtapi lists no module, task or shared memory, and the kernel
# has none of our modules left (issue 3: no leak across load/unload cycles).
M=$PATH_MOD
check() { if ! eval "$1"; then echo "FAILED: $1"; exit 1; fi; }

# arguments a module needs to load (the rest load with their defaults)
args_of() {
	case $1 in
	threads) echo "name1=t1 period1=1000000 name2=t2 period2=2000000" ;;
	sampler|streamer) echo "cfg=fbsu depth=64" ;;
	stepgen) echo "step_type=0,1" ;;
	pwmgen) echo "output_type=0" ;;
	*) echo "" ;;
	esac
}

comps=
for ko in "$M"/*.ko; do
	name=${ko##*/}; name=${name%.ko}
	case $name in rtapi|hal_lib|fmt_selftest) ;; *) comps="$comps $name" ;; esac
done
echo "modules:$comps"
i=0
while [ $i -lt 100 ]; do
	insmod $M/rtapi.ko
	insmod $M/hal_lib.ko
	for c in $comps; do
		# shellcheck disable=SC2046
		insmod $M/$c.ko $(args_of $c) || { echo "FAILED: round $i: insmod $c $(args_of $c)"; exit 1; }
	done
	[ $i = 0 ] && cat /proc/rtapi/modules /proc/rtapi/tasks /proc/rtapi/shmem
	for c in $comps; do rmmod $c; done
	rmmod hal_lib
	check '[ "$(grep -c "^[0-9]" /proc/rtapi/modules)" = 0 ]'
	check '[ "$(grep -c "^[0-9]" /proc/rtapi/tasks)" = 0 ]'
	check '[ "$(grep -c "^[0-9]" /proc/rtapi/shmem)" = 0 ]'
	rmmod rtapi
	i=$((i + 1))
done
check '! test -e /proc/rtapi'
check '[ "$(lsmod | wc -l)" -le 1 ]'
echo "100 rounds of rtapi, hal_lib and$comps: nothing left"
