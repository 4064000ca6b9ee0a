# 1,000 lines of random bytes (NUL and all, before HELLO: unknown commands, no reply)
# and a 100,000-byte line on one connection while another stays logged in: the server
# survives, the garbage connection still logs in afterwards, the other still works.
. ../lib.sh
machine_start
rsh_start
rsh <<'END'
@2 hello EMC watcher 1.0
@2 set echo off
!garbage 1000 12345
!long 100000
!garbage 1000 999
hello EMC tester 1.0
get plat
@2 get estop
@2 get plat
quit
@2 quit
END
echo "$(rsh_alive)"
rsh <<'END'
hello EMC again 1.0
quit
END
machine_stop
