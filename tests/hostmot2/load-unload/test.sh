# 100 load/unload cycles of hostmot2 with two simulated boards (one of each layout)
# leave nothing behind: the same components and the same HAL memory use as before.
set -e
tmp=${TEST_TMPDIR:-$(mktemp -d)}
halcmd loadrt threads name1=thread period1=1000000
before=$(halcmd status | grep "used/total")
i=0
: > "$tmp/cycles.hal"
while [ $i -lt 100 ]; do
	cat >> "$tmp/cycles.hal" <<'CYCLE'
loadrt hostmot2
loadrt hm2_sim board=5i25,5i20 config="enable_raw,num_encoders=4"
addf hm2_5i25.0.read thread
addf hm2_5i20.0.write thread
unloadrt hm2_sim
unloadrt hostmot2
CYCLE
	i=$((i + 1))
done
halcmd -f "$tmp/cycles.hal"
after=$(halcmd status | grep "used/total")
echo "components: $(halcmd list comp)"
echo "functions: $(halcmd list funct)"
[ "$before" = "$after" ] && echo "memory: unchanged" || echo "memory: $before -> $after"
halrun -U
