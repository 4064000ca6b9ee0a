# hm2-over-pci.sh - sourced by tests/hm2_pci/over-*: runs a test of tests/hostmot2
# unchanged except for the board driver. Its "loadrt hm2_sim board=B config=C" line
# becomes "loadrt hm2_sim bus=pci board=B" (the same simulated board, shown as a PCI
# card: IDs, BARs, PLX bridge) and "loadrt hm2_pci config=C", so the HAL names and
# behaviour it checks are now those of hm2_pci. POSIX sh and busybox awk.
#   hm2_over_pci NAME            run tests/hostmot2/NAME so (from the test's directory)
#   hm2_over_pci_check NAME FILE check FILE as tests/hostmot2/NAME checks its result,
#     after naming the owner of the board's pins in "show" listings as there (the
#     board driver's component, hm2_pci instead of hm2_sim)
hm2_over_pci() {
	src=$(pwd)/../../hostmot2/$1
	work=${TEST_TMPDIR:-/tmp}/over-pci-$1
	mkdir -p "$work" && cp -r "$src"/. "$work"/ || return 1
	for f in test.hal test.sh; do
		[ -f "$src/$f" ] || continue
		awk '{
			if (match($0, /loadrt hm2_sim board=[^ ]*/)) {
				pre = substr($0, 1, RSTART - 1)
				mid = substr($0, RSTART, RLENGTH)
				post = substr($0, RSTART + RLENGTH)
				sub(/hm2_sim /, "hm2_sim bus=pci ", mid)
				print pre mid
				print pre "loadrt hm2_pci" post
			} else
				print
		}' "$src/$f" > "$work/$f"
	done
	cd "$work" || return 1
	if [ -f test.hal ]; then halrun -f test.hal; else sh test.sh; fi
}

hm2_over_pci_check() {
	src=../../hostmot2/$1
	sed 's/^hm2_pci /hm2_sim /' "$2" > "$2.as-sim"
	if [ -x "$src/checkresult" ]; then
		(cd "$src" && ./checkresult "$2.as-sim")
	else
		diff -u "$src/expected" "$2.as-sim"
	fi
}
