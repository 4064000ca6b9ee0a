# Configuration errors: one line naming FILE:LINE and the key, exit 1 (2 for usage),
# nothing started or left. A program that cannot start (io, task) aborts start-up.
. ../common.sh
export HALLIB_DIR=$PWD
try() {
	emc "$@" > "$T/out" 2>&1 < /dev/null
	echo "exit $?"
	sed -e "s|$PWD|.|g" -e "s|$T|TMP|g" "$T/out" | grep -v '^  '
}
echo "== usage"
try
try -x m.ini
try -t tpmod m.ini
try -l
try a.ini b.ini
echo "== INI errors"
try nosuch.ini
try notask.ini
try nofile.ini
try nolib.ini
try delay.ini
echo "== programs that fail"
try iofails.ini
try taskfails.ini
probe_log
left
echo "== -h"
emc -h | head -1
echo "exit $?"
