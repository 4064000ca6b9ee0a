# Load rtapi, hal_lib, and2 and a thread; check /proc/rtapi and the HAL segment seen
# from userspace; unload everything and check that nothing is left.
M=$PATH_MOD
check() { if ! eval "$1"; then echo "FAILED: $1"; exit 1; fi; }

insmod $M/rtapi.ko
check 'test -c /dev/rtapi'
check 'test -r /proc/rtapi/modules'
insmod $M/hal_lib.ko
check 'grep -q hal_lib /proc/rtapi/modules'
check 'grep -q 0x48414c32 /proc/rtapi/shmem'
insmod $M/and2.ko
insmod $M/threads.ko name1=t period1=1000000
cat /proc/rtapi/modules /proc/rtapi/tasks /proc/rtapi/shmem
out=$(hal_segcheck)
echo "$out"
check 'echo "$out" | grep -q "magic=ok"'
check 'echo "$out" | grep -q "comps=2 "'	# and2.0's component and threads
check 'echo "$out" | grep -q "threads=1 "'
check 'echo "$out" | grep -q "functs=1 "'
check '[ "$(grep -c running /proc/rtapi/tasks)" = 1 ]'
sleep 1
cycles=$(awk '$6 == "running" { print $7 }' /proc/rtapi/tasks)
echo "cycles after 1 s: $cycles"
check '[ "$cycles" -gt 100 ]'	# 1 ms period; qemu TCG timing is loose
rmmod threads
# threads(9): a thread outlives the module that made them, until hal_lib goes
check '[ "$(grep -c running /proc/rtapi/tasks)" = 1 ]'
rmmod and2
out=$(hal_segcheck)
check 'echo "$out" | grep -q "comps=0 "'
rmmod hal_lib
check '[ "$(grep -c "^[0-9]" /proc/rtapi/tasks)" = 0 ]'
check '! grep -q 0x48414c32 /proc/rtapi/shmem'
rmmod rtapi
check '! test -e /proc/rtapi'
check '! test -e /dev/rtapi'
check '[ "$(lsmod | wc -l)" -le 1 ]'
