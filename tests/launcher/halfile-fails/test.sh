# A failing HAL file aborts start-up: halcmd names FILE:LINE, the launcher names the
# file and its [HAL]HALFILE line, exits 1, and cleans up (io stopped, no HAL segment,
# no process, no lock file). Task and the later file never start.
. ../common.sh
emc m.ini > "$T/out" 2>&1 < /dev/null
echo "exit $?"
sed "s|$PWD|.|g" "$T/out"
probe_log
left
