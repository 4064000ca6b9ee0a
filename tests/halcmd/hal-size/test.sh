# HAL_SIZE applies to the session being started (rtapi_app's segment, or hal_lib.ko's
# hal_size in the kernel flavor); later tools attach to that segment as it is.
T=${TEST_TMPDIR:-/tmp}
total() { halcmd status mem | sed -n 's|.*used/total shared memory: *[0-9]*/||p'; }
refused() {   # VALUE: a fresh session with HAL_SIZE=VALUE is refused with the reason
	HAL_SIZE=$1 halcmd loadrt and2 > "$T/out" 2>&1
	echo "HAL_SIZE=$1: exit $?"
	grep -o "HAL_SIZE='$1' is not a segment size: bytes, or with a K, M or G suffix, from 64M to 1G" "$T/out" | head -n 1
}
halrun -U
HAL_SIZE=128M halcmd loadrt and2
echo "loadrt with HAL_SIZE=128M: $?"
echo "total: $(total)"
halcmd show comp and2 | grep -c and2
halrun -U
refused 12M
refused 64Mx
halcmd loadrt and2
echo "default: $? total $(total)"
halrun -U
