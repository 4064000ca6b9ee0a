# halmeter's terminal mode: one line per update for scripts (stdout is not a
# terminal here), pins, signals and parameters, and its error lines.
halcmd loadrt not
halcmd newsig x float
halcmd sets x 2.5
halcmd setp not.0.tmax 17
halmeter -t -n 1 sig x
echo "exit $?"
halmeter -l -n 3 -i 10 pin not.0.out
halmeter -t -n 2 -i 10 param not.0.tmax
halcmd sets x -0.001
halmeter -t -n 1 sig x
halmeter -t -n 1 pin nosuch
echo "exit $?"
halmeter -t -n 1 param nosuch
halmeter -t -n 1 sig nosuch
halmeter -t -n 0 sig x
echo "exit $?"
# no display: one line saying what to do (the kernel-test VM's static build has no GTK
# at all and says that instead)
out=$(DISPLAY= WAYLAND_DISPLAY= halmeter sig x 2>&1)
rc=$?
case $out in
"halmeter: cannot open a display (set DISPLAY, or use -t for terminal mode)" | \
"halmeter: this build has no GTK window; use -t for terminal mode")
	echo "no window: one line, exit $rc" ;;
*) echo "$out"; echo "exit $rc" ;;
esac
halrun -U
