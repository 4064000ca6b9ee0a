# End to end: the demo's run (demo/mill-run.sh): "emc mill.ini" headless, driven through
# emcrsh as a telnet user would (demo/drive-emcrsh.sh): Home All, the sample program
# mill.ngc to its end with joint.0-2.pos-fb sampled every servo period, a clean
# shut-down; then every sample must lie within the program's G64 P tolerance of rs274's
# path and every move's end be passed in order (toolpath_check), and, where gnuplot is
# (not in the kernel flavor's VM), the picture make demo shows is drawn.
T=${TEST_TMPDIR:-/tmp}
for prog in milltask io emcrsh rsh_client rs274 toolpath_check; do
	command -v $prog > /dev/null 2>&1 || { echo "run: $prog is not built"; exit 1; }
done
../../../demo/mill-run.sh "$T/run" || exit 1
echo "run: ok"
toolpath_check check "$T/run/canon.txt" "$T/run/samples.txt"
echo "check: exit $?"
if [ "$HAL_TEST_FLAVOR" = kernel ]; then
	echo "picture: not drawn in the kernel flavor's VM (no gnuplot there)"
	exit 0
fi
../../../demo/plot-toolpath.sh "$T/run" 0.001 || exit 1
echo "picture: png $(wc -c < "$T/run/toolpath.png") bytes, svg $(wc -c < "$T/run/toolpath.svg") bytes"
# the trace: gnuplot writes each plotted line as SVG paths of "L x,y" points; the
# samples give one per sample (tens of thousands)
echo "picture: svg trace legend $(grep -c 'sampled joints' "$T/run/toolpath.svg")"
echo "picture: svg path points $(tr ' ' '\n' < "$T/run/toolpath.svg" | grep -c '^L')"
