# hal-cycles.sh - sourced by the load/unload tests (sh, also busybox).
#   hal_cycles N   runs N copies of the halcmd lines on stdin (one load/unload cycle)
#     as one halcmd -f, then prints what is left beside what was there before:
#     "components: ...", "functions: ..." and "memory: unchanged" (or both
#     "used/total" lines of halcmd status when HAL memory use differs).
hal_cycles() {
	cyc_dir=${TEST_TMPDIR:-$(mktemp -d)}
	cat > "$cyc_dir/cycle.hal"
	: > "$cyc_dir/cycles.hal"
	cyc_i=0
	while [ $cyc_i -lt "$1" ]; do
		cat "$cyc_dir/cycle.hal" >> "$cyc_dir/cycles.hal"
		cyc_i=$((cyc_i + 1))
	done
	cyc_before=$(halcmd status | grep "used/total")
	halcmd -f "$cyc_dir/cycles.hal" || return 1
	cyc_after=$(halcmd status | grep "used/total")
	echo "components: $(halcmd list comp)"
	echo "functions: $(halcmd list funct)"
	if [ "$cyc_before" = "$cyc_after" ]; then
		echo "memory: unchanged"
	else
		echo "memory: $cyc_before -> $cyc_after"
	fi
}
