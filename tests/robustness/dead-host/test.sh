. ../lib.sh
halcmd loadrt and2
halcmd loadrt threads name1=t period1=1000000
kill_and_wait "$(rtapi_app_pid)"
for cmd in "show comp" "setp and2.0.in0 1" "unloadrt and2" "loadrt threads"; do
	halcmd $cmd 2>&1 | sed "s/RTAPI_INSTANCE=$RTAPI_INSTANCE/RTAPI_INSTANCE=X/"
done
halrun -f /dev/null 2>&1 | sed "s/RTAPI_INSTANCE=$RTAPI_INSTANCE/RTAPI_INSTANCE=X/"
echo "halrun -U:"
halrun -U
halcmd loadrt and2
halcmd list comp
