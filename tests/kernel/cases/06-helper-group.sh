# emc_module_helper installed 4750 root:hal: a user outside group hal cannot run it;
# a member (haluser) loads and unloads modules through it; and a member cannot smuggle
# a second parameter into one argument ("count=1 dyndbg=+p").
M=$PATH_MOD
check() { if ! eval "$1"; then echo "FAILED: $1"; exit 1; fi; }
loaded() { grep -q "^$1 " /proc/modules; }
H=/bin/emc_module_helper
chown root:hal $H
chmod 4750 $H
check '[ "$(stat -c "%a %U %G" $H)" = "4750 root hal" ]'

rc=0; su -s /bin/sh nobody -c "$H insert rtapi" || rc=$?
check '[ "$rc" = 126 ]'		# the shell could not execute it: Permission denied
check '! loaded rtapi'
rc=0; su -s /bin/sh nobody -c "$H remove rtapi" || rc=$?
check '[ "$rc" = 126 ]'

su -s /bin/sh haluser -c "$H insert rtapi && $H insert hal_lib && $H insert and2 count=2"
check 'loaded rtapi && loaded hal_lib && loaded and2'
rc=0; su -s /bin/sh haluser -c "$H insert or2 'count=1 dyndbg=+p'" 2>/tmp/helper.err || rc=$?
cat /tmp/helper.err
check '[ "$rc" = 2 ]'
check '! loaded or2'
check 'grep -q "is not a value of type int" /tmp/helper.err'
rc=0; su -s /bin/sh haluser -c "$H insert or2 dyndbg=+p" 2>/tmp/helper.err || rc=$?
check '[ "$rc" = 2 ] && ! loaded or2'
su -s /bin/sh haluser -c "$H remove and2 && $H remove hal_lib && $H remove rtapi"
check '! loaded and2 && ! loaded hal_lib && ! loaded rtapi'
