#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# plot-toolpath.sh OUTDIR PERIOD_S - draws what mill-run.sh recorded in OUTDIR with
# gnuplot: OUTDIR/toolpath.png and OUTDIR/toolpath.svg, two panels: the X-Y view of
# the sampled joint positions coloured by Z over the program's path (rs274's calls
# through toolpath_check), and Z over time (PERIOD_S: the sampling period, seconds).
# Exit 0, or 1 with a one-line message.
set -u
out=${1:?usage: plot-toolpath.sh OUTDIR PERIOD_S}
period=${2:?usage: plot-toolpath.sh OUTDIR PERIOD_S}
command -v gnuplot > /dev/null 2>&1 ||
	{ echo "plot-toolpath: gnuplot is not installed (scripts/install-deps installs gnuplot-nox)" >&2; exit 1; }
set -- $(sed -n 1p "$out/samples.txt")
[ $# -eq 3 ] || { echo "plot-toolpath: no samples in $out/samples.txt" >&2; exit 1; }
toolpath_check path "$out/canon.txt" "$1" "$2" "$3" > "$out/path.txt" || exit 1
for fmt in png svg; do
	if [ $fmt = png ]; then
		term="pngcairo size 1000,800 font 'sans,11'"
	else
		term="svg size 1000,800 font 'sans,11' background '#ffffff'"
	fi
	gnuplot > "$out/gnuplot.log" 2>&1 <<GP || { cat "$out/gnuplot.log" >&2; echo "plot-toolpath: gnuplot failed ($fmt)" >&2; exit 1; }
set terminal $term
set output '$out/toolpath.$fmt'
set datafile commentschars '#o'
set palette defined (0 '#1f3c88', 0.5 '#2aa198', 0.8 '#e5b700', 1 '#d1495b')
set grid lc rgb '#dddddd'
# the X-Y frame around the work: the first moves (from the home position, the tool
# change's quill-up) leave it
stats '$out/path.txt' every ::3 using 1:2 nooutput
mx = (STATS_max_x - STATS_min_x) * 0.08 + 1
my = (STATS_max_y - STATS_min_y) * 0.08 + 1
set xrange [STATS_min_x - mx : STATS_max_x + mx]
set yrange [STATS_min_y - my : STATS_max_y + my]
set multiplot title 'configs/sim/mill.ngc run by the simulated mill: its joints sampled every servo period'
set origin 0, 0.3
set size 1, 0.68
set size ratio -1
set xlabel 'X (mm)'
set ylabel 'Y (mm)'
set cblabel 'Z (mm)'
set key outside right top box
plot '$out/path.txt' using 1:2 with lines lw 5 lc rgb '#c8c8c8' title 'program path (rs274)', \
     '$out/samples.txt' using 1:2:3 with lines lw 1.5 lc palette title 'sampled joints 0, 1'
set origin 0, 0
set size 1, 0.3
set size noratio
set autoscale
set xlabel 'time (s)'
set ylabel 'Z (mm)'
unset colorbox
set key off
plot '$out/samples.txt' using (\$0 * $period):3:3 with lines lw 1.5 lc palette title 'joint 2'
unset multiplot
GP
done
exit 0
