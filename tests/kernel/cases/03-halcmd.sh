# halcmd and halrun in the kernel flavor, through emc_module_helper: loadrt errors
# carry the module's own message (from /proc/rtapi/messages) worded as in the
# simulated flavor, save comp keeps the loadrt arguments, and halcmd's session stays
# loaded until "halrun -U" unloads everything (issue 3).
check() { if ! eval "$1"; then echo "FAILED: $1"; exit 1; fi; }
export HAL_FLAVOR=kernel

out=$(halrun -k -f <<'HAL' 2>&1
loadrt threads name1=fast period1=10
loadrt and2 count=100001
loadrt and2 bogus=1
loadrt nosuch
loadrt and2 names=a,b
loadrt and2
loadrt threads name1=t period1=1000000
save comp
unloadrt and2
unloadrt and2
HAL
) || true	# halrun exits 1 after these errors; this case checks them itself
echo "$out"
check 'echo "$out" | grep -qF "<stdin>:1: thread '"'fast'"': period 10 ns is too short (minimum 1000); threads: rtapi_app_main failed: Invalid argument (-22)"'
check 'echo "$out" | grep -qF "<stdin>:2: and2: count=100001 is out of range"'
check 'echo "$out" | grep -qF "<stdin>:3: and2: unknown parameter '"'bogus'"'"'
check 'echo "$out" | grep -qF "<stdin>:4: nosuch: no such realtime module (nosuch.ko is not in the module directory)"'
check 'echo "$out" | grep -qF "<stdin>:6: and2: already loaded"'
check 'echo "$out" | grep -qxF "loadrt and2 names=a,b"'
check 'echo "$out" | grep -qxF "loadrt threads name1=t period1=1000000"'
check 'echo "$out" | grep -qF "<stdin>:10: and2: not loaded"'
# halrun tore everything down
check '! test -e /proc/rtapi'
check '[ "$(lsmod | wc -l)" -le 1 ]'

# halcmd leaves its session loaded; a second halrun refuses; halrun -U ends it
halcmd loadrt threads name1=t period1=1000000
halcmd loadrt siggen
halcmd addf siggen.0.update t
halcmd start
sleep 1
check '[ "$(halcmd getp t.tmax)" -gt 0 ]'
check 'halcmd show thread | grep -q siggen.0.update'
check '! halrun -f /dev/null 2>/dev/null'
check 'lsmod | grep -q "^siggen "'
halrun -U
check '! test -e /proc/rtapi'
check '[ "$(lsmod | wc -l)" -le 1 ]'
# a forced flavor that does not exist
check '! halcmd --flavor=rtai show 2>/dev/null'
