# Doubles passed to rtapi_snprintf/rtapi_print_msg from FP code are printed right
# (the variadic entries are compiled with SSE; see rtapi_print_entry_kmod.c).
M=$PATH_MOD
check() { if ! eval "$1"; then echo "FAILED: $1"; exit 1; fi; }
insmod $M/rtapi.ko
insmod $M/hal_lib.ko	# fmt_selftest includes rtapi_app.h, whose glue uses hal_lib
insmod $M/fmt_selftest.ko
sleep 1
grep fmt_selftest /proc/rtapi/messages
check 'grep -q "fmt_selftest: 1.500 -2.25 1e+100 | 1.500 -2.25 1e+100" /proc/rtapi/messages'
rmmod fmt_selftest
rmmod hal_lib
rmmod rtapi
