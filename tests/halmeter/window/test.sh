# halmeter's GTK window under Xvfb. What the window displays is read back through
# halmeter's HALMETER_REPORT hook (the texts of its GTK labels, written on every
# change): the value follows a signal that the test changes, -s shows the name in the
# title bar, and the Select dialog (driven by HALMETER_TEST_SELECT: pick, Apply, OK)
# switches to a parameter.
T=${TEST_TMPDIR:-/tmp}
wait_for() {
	i=0
	while ! grep -q "$2" "$1" 2>/dev/null; do
		i=$((i + 1)); [ $i -gt 400 ] && { echo "timed out waiting for '$2' in $1"; cat "$1"; return 1; }
		sleep 0.05
	done
}
command -v Xvfb >/dev/null || { echo "Xvfb is not installed (scripts/install-deps)"; exit 1; }
Xvfb -displayfd 5 -screen 0 800x600x24 -nolisten tcp 5>"$T/display" 2>"$T/xvfb.log" &
xvfb=$!
wait_for "$T/display" '[0-9]' || exit 1
export DISPLAY=:$(cat "$T/display")
export NO_AT_BRIDGE=1
halcmd loadrt not
halcmd newsig x float
halcmd sets x 1.5
halcmd setp not.0.tmax 42

HALMETER_REPORT=$T/big halmeter sig x 2>&1 &
m=$!
wait_for "$T/big" "value=1.5" || exit 1
halcmd sets x -3.25
wait_for "$T/big" "value=-3.25" || exit 1
kill $m; wait $m 2>/dev/null
cat "$T/big"

HALMETER_REPORT=$T/small halmeter -s pin not.0.in -g 10 20 300 2>&1 &
m=$!
wait_for "$T/small" "value=" || exit 1
kill $m; wait $m 2>/dev/null
cat "$T/small"

HALMETER_REPORT=$T/select HALMETER_TEST_SELECT="param not.0.tmax" halmeter sig x 2>&1 &
m=$!
wait_for "$T/select" "value=42" || exit 1
kill $m; wait $m 2>/dev/null
cat "$T/select"

kill $xvfb; wait $xvfb 2>/dev/null
halrun -U
