# halplot samples 200 periods of a 1 ms thread; the SVG read back must hold one
# trace group per channel, each labelled with the pin that feeds the channel
# (the signal's name when no pin writes it), with all 200 samples, and a time
# axis that ends at 200 x 1 ms = 0.2 s.
cat > plot.hal <<'HAL'
loadrt threads name1=fast period1=1000000
loadrt siggen
loadrt sampler cfg=fbs depth=4000
setp siggen.0.frequency 50
net sine siggen.0.sine => sampler.0.pin.0
net clock siggen.0.clock => sampler.0.pin.1
newsig level s32
sets level 7
linksp level sampler.0.pin.2
addf siggen.0.update fast
addf sampler.0 fast
start
HAL
halcmd -f plot.hal || exit 1
svg=$TEST_TMPDIR/plot.svg png=$TEST_TMPDIR/plot.png
halplot -n 200 -o "$svg" -T "halplot test"
echo "halplot svg: $?"
halplot -n 50 -o "$png" -s 400x300
echo "halplot png: $?"
halrun -U
size=$(wc -c <"$svg")
[ "$size" -gt 5000 ] && echo "svg size > 5000: yes" || echo "svg size: $size"
# each trace: <g id="gnuplot_plot_N"> ... <text>LABEL</text> ... <path d='M.. L.. ...'>
awk '
/<g id="gnuplot_plot_[0-9]+"/ { if (id) report(); id = ++n; label = ""; pts = 0; next }
id && label == "" && /<text>/ { label = $0; sub(/.*<text>/, "", label); sub(/<\/text>.*/, "", label) }
id && /<path|^[\t ]*L/ { pts += gsub(/[ML][0-9.]+,[0-9.]+/, "&") }
/<\/svg>/ { if (id) report() }
function report() { printf "trace %s: %s, %s points\n", id, label, (pts >= 200 ? ">= 200" : pts); id = "" }
' "$svg"
grep -o '<text>halplot test</text>' "$svg"
grep -o '<text>time (s)</text>' "$svg"
grep -q '<text> 0.2</text>\|<text>0.2</text>' "$svg" && echo "time axis ends at 0.2 s"
# PNG: signature and the size asked for (IHDR width and height, big-endian)
od -An -tx1 -N24 "$png" | tr -d ' \n' | sed 's/^\(89504e470d0a1a0a\).\{16\}\(.\{8\}\)\(.\{8\}\).*/png \1 \2 \3\n/'
