# realtime start|stop|restart|status, as LinuxCNC scripts call it around halcmd
realtime status > "$TEST_TMPDIR/st"; echo "status $?"; sed "s/ (.*flavor)//" "$TEST_TMPDIR/st"
realtime start; echo "start $?"
realtime start; echo "start again $?"
realtime status > /dev/null; echo "status $?"
halcmd loadrt and2
halcmd list comp
realtime restart; echo "restart $?"
halcmd list comp
realtime stop; echo "stop $?"
realtime status > /dev/null; echo "status $?"
realtime bogus 2>&1 | head -1; realtime bogus > /dev/null 2>&1; echo "bogus $?"
