# Several connections at once (rsh_client's "@N" lines), with a session limit of 3:
# enable moves to the connection that asks last (the other's SETs are NAKed, its
# SHUTDOWN refused); echo/verbose stay per connection; one connection's garbage,
# over-long line and QUIT leave the others' sessions alone; a fourth connection is
# closed at once while three are open, and accepted again after one has quit.
. ../lib.sh
machine_start
rsh_start -s 3
rsh <<'END'
hello EMC first 1.0
set enable EMCTOO
get enable
@2 hello EMC second 1.0
@2 set echo off
@2 get enable
@2 set verbose on
@2 set enable EMCTOO
@2 get enable
get enable
set estop off
@2 set set_wait done
@2 set estop off
get echo
@2 get echo
@3 get plat
@4 get plat
@3 !garbage 200 7
@3 !long 5000
@3 hello EMC third 1.0
@3 set enable off
@2 get enable
@2 set machine on
@2 get machine
shutdown
@3 quit
@5 hello EMC fifth 1.0
@5 set echo off
@5 get machine
@2 shutdown
END
rsh_exited
machine_stop
