# In the kernel flavor hm2_eth refuses to load with its reason (hm2_eth(9)): a
# kernel UDP socket cannot be used from a realtime thread. Nothing stays loaded.
halcmd loadrt hostmot2 || exit 1
halcmd loadrt hm2_eth board_ip=192.168.1.121 >"$TEST_TMPDIR/msg" 2>&1
echo "exit $?"
sed 's/(comp [0-9]*)/(comp N)/g' "$TEST_TMPDIR/msg"
echo "components: $(halcmd list comp)"
halrun -U
