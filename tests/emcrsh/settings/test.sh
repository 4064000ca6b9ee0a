# The connection's and the server's own subcommands: HELLO, echo, verbose, enable and
# its permission rule, config, comm_mode/comm_prot, inifile, plat, ini, debug,
# set_wait/wait/timeout/update, error (a refused SET's reason) and the operator
# messages, time, the unit conversions, help, NAK forms, unknown commands, shutdown
# refused without enable, quit. emcrsh keeps running.
. ../lib.sh
machine_start
rsh_start
rsh <<'END' | sed -e "s|$T|T|g" -e 's/^TIME [0-9]*\.[0-9]\{6\}\\r\\n$/TIME <seconds>\\r\\n/'
get echo
set echo off
hello EMC tester
hello wrong tester 1.0
hello EMC tester 1.0
get echo
set echo off
get echo
get verbose
set verbose on
get verbose
get enable
set mode mdi
set enable emctoo
set enable EMCTOO
get enable
get config
set config anything
get comm_mode
set comm_mode binary
get comm_mode
set comm_mode morse
set comm_mode ascii
get comm_prot
set comm_prot 1.1
get comm_prot
set comm_prot 9
get inifile
get plat
set plat x
get ini MAX_VELOCITY AXIS_X
get ini NO_SUCH_KEY AXIS_X
get ini MAX_VELOCITY
set debug 2
get debug
set debug 0
set debug lots
get set_wait
set set_wait done
get set_wait
set set_wait none
get set_wait
set set_wait sometimes
set set_wait received
get timeout
set timeout 30
get set_timeout
set set_timeout 0
get timeout
set timeout soon
set update none
set update auto
set update maybe
get update
set wait done
set wait later
get wait
get error
set mdi g0 x1
get error
get error
get operator_display
get operator_text
get time
set time 5
get linear_unit_conversion
set linear_unit_conversion inch
get display_linear_units
set linear_unit_conversion auto
get display_linear_units
get angular_unit_conversion
set angular_unit_conversion grad
get display_angular_units
set angular_unit_conversion auto
help set
get nonsense
get
fly me to the moon
set
set nonsense 1
set enable off
get enable
set mode mdi
shutdown
quit
END
rsh_alive
machine_stop
