# The RTAPI conformance suite (tests/kernel/rtapi_conformance.c, also run as
# GoogleTest in the simulated flavor) in the kernel flavor: insmod runs every case and
# fails if one fails; each result is a line in /proc/rtapi/messages.
M=$PATH_MOD
check() { if ! eval "$1"; then echo "FAILED: $1"; exit 1; fi; }
insmod $M/rtapi.ko
insmod $M/hal_lib.ko	# rtapi_app.h's module glue uses hal_lib
rc=0
insmod $M/rtapi_conformance.ko || rc=$?
grep rtapi_conformance: /proc/rtapi/messages
check '[ "$rc" = 0 ]'
check 'grep -q "rtapi_conformance: 9 passed, 0 failed" /proc/rtapi/messages'
check '[ "$(grep -c "rtapi_conformance: PASS" /proc/rtapi/messages)" = 9 ]'
rmmod rtapi_conformance
rmmod hal_lib
rmmod rtapi
