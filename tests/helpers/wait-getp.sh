# wait-getp.sh - sourced by tests (sh, also busybox) whose realtime side answers a
# halcmd setp some periods later: wait for the effect instead of sleeping a fixed time
# that a loaded machine (the sanitizer run, qemu) can outlast.
#   wait_getp NAME VALUE [SECONDS]  polls `halcmd getp NAME` every 20 ms until it prints
#     VALUE; after SECONDS (default 10) prints "NAME is X, not VALUE, after S s" and
#     returns 1.
wait_getp() {
	wg_n=0
	wg_limit=$(( ${3:-10} * 50 ))
	while [ "$(halcmd getp "$1")" != "$2" ]; do
		wg_n=$((wg_n + 1))
		if [ $wg_n -gt $wg_limit ]; then
			echo "$1 is $(halcmd getp "$1"), not $2, after ${3:-10} s"
			return 1
		fi
		sleep 0.02
	done
}
