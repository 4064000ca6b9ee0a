# Start-up order (ini-and-launch.md 3.2): io, halui, HAL files in order (LIB: and -H
# lookup), task, HALCMD lines, start, applications, the display; the display's exit
# ends the session with its status and everything is cleaned up.
. ../common.sh
export HALLIB_DIR=$PWD/lib
rm -f display.out
emc -H hdir m.ini > "$T/out" 2>&1 < /dev/null
echo "exit $?"
sed "s|$PWD|.|g" "$T/out"
cat display.out
rm -f display.out
echo "== started and stopped"
probe_log | sed -n '/^start/p'
probe_log | sed -n '/^stop/p' | head -2
probe_log | sed -n '/^stop/p' | tail -n +3 | sort
left
