# A module whose rtapi_app_main fails must leave no component, task or module behind;
# module parameters reach the component (names=, count=).
M=$PATH_MOD
check() { if ! eval "$1"; then echo "FAILED: $1"; exit 1; fi; }

insmod $M/rtapi.ko
insmod $M/hal_lib.ko
check '! insmod $M/and2.ko count=100001 2>/dev/null'	# (count=0 means the default count)
check 'hal_segcheck | grep -q "comps=0 "'
check '! lsmod | grep -q "^and2 "'
insmod $M/and2.ko names=first,second
check 'hal_segcheck | grep -q "comps=1 "'
check 'hal_segcheck | grep -q "functs=2 "'
rmmod and2
check 'hal_segcheck | grep -q "comps=0 pins=0 params=0 sigs=0 functs=0 "'
check '! insmod $M/threads.ko name1=fast period1=10 2>/dev/null'	# below the 1 us minimum
# the module's own message reaches /proc/rtapi/messages, for halcmd to show
check 'grep -q "period 10 ns is too short" /proc/rtapi/messages'
check 'grep -q "threads: rtapi_app_main failed (-22)" /proc/rtapi/messages' 
check '[ "$(grep -c "^[0-9]" /proc/rtapi/tasks)" = 0 ]'
check 'hal_segcheck | grep -q "threads=0 "'
# two threads, the second slower: two SCHED_FIFO tasks, rate-monotonic priorities
insmod $M/threads.ko name1=fast period1=1000000 name2=slow period2=2000000 fp2=0
cat /proc/rtapi/tasks
check '[ "$(grep -c running /proc/rtapi/tasks)" = 2 ]'
check 'grep -q "^[0-9].* 98 *1 *1000000 " /proc/rtapi/tasks'
check 'grep -q "^[0-9].* 97 *0 *2000000 " /proc/rtapi/tasks'
rmmod threads
# the threads stay (threads(9)) until hal_lib goes; then the clock period is free again
check '[ "$(grep -c running /proc/rtapi/tasks)" = 2 ]'
rmmod hal_lib
check '[ "$(grep -c "^[0-9]" /proc/rtapi/tasks)" = 0 ]'
insmod $M/hal_lib.ko
insmod $M/threads.ko name1=other period1=500000
check 'grep -q "clock period: 500000 ns" /proc/rtapi/tasks'
rmmod threads
rmmod hal_lib
rmmod rtapi
