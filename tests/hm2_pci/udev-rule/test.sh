# firmware/udev/60-hal.rules for Mesa PCI cards (hm2_pci in the simulated flavor maps
# the card's sysfs resource0): which cards of hm2_pci's ID table the rule gives to
# group 'hal' (the bridgeless 5i24/5i25/6i25) and which it leaves to root (the PLX
# cards: their bridge can do DMA); then the rule's own command, run on a stand-in
# sysfs directory (root's 0600 files, as the kernel makes them; the group 'hal' is a
# free test gid here): the card is enabled, resource0 becomes readable and writable
# for a user in that group, not for one outside it, and `enable` stays root's.
rules=../../../firmware/udev/60-hal.rules
ids=../../../kernel/drivers/hostmot2/hm2_pci_ids.h
rule=$(grep '^ACTION=="add", SUBSYSTEM=="pci"' "$rules")
[ "$(echo "$rule" | wc -l)" -eq 1 ] || { echo "no single Mesa PCI rule in $rules"; exit 1; }
vendor=$(echo "$rule" | sed -n 's/.*ATTR{vendor}=="\(0x[0-9a-f]*\)".*/\1/p')
echo "rule matches vendor $vendor"
sed -n 's/^[[:space:]]*X(HM2_PCI_\([A-Z]*\), \(0x[0-9A-F]*\), [A-Z0-9_]*, \(0x[0-9A-F]*\), "\([^"]*\)".*/\1 \2 \3 \4/p' "$ids" |
while read -r v dev sub board; do
	case $v in
	PLX) vid=0x10b5 ;;
	MESA) vid=0x2718 ;;
	*) vid=unknown ;;
	esac
	if [ "$vid" = "$vendor" ]; then echo "$board $dev:$sub group hal"; else echo "$board $dev:$sub root only"; fi
done

cmd=$(echo "$rule" | sed -n "s/.*RUN+=\"\/bin\/sh -c '\(.*\)'\"\$/\1/p")
[ -n "$cmd" ] || { echo "the rule has no RUN+=\"/bin/sh -c '...'\""; exit 1; }
# (not under TEST_TMPDIR: user nobody must reach it)
T=$(mktemp -d /tmp/udev-rule.XXXXXX) || exit 1
trap 'rm -rf "$T"' EXIT
dev=/devices/pci0000:00/0000:00:05.0
mkdir -p "$T/sys$dev" || exit 1
printf 0 > "$T/sys$dev/enable"
head -c 65536 /dev/zero > "$T/sys$dev/resource0"
chmod 0600 "$T/sys$dev/enable" "$T/sys$dev/resource0"
# a gid no group has
gid=4242
while getent group $gid > /dev/null; do gid=$((gid + 1)); done
# the command as udev runs it: %p is the device path; 'hal' is the test gid here
run=$(echo "$cmd" | sed "s|/sys%p|$T/sys$dev|g; s|chgrp hal |chgrp $gid |")
sh -c "$run" || { echo "the rule's command failed: $run"; exit 1; }
echo "enable: $(cat "$T/sys$dev/enable")"
echo "resource0: mode $(stat -c %a "$T/sys$dev/resource0"), group is hal: $([ "$(stat -c %g "$T/sys$dev/resource0")" = $gid ] && echo yes || echo no)"
echo "enable: mode $(stat -c %a "$T/sys$dev/enable")"
chmod 0755 "$T" "$T/sys" "$T/sys/devices" "$T/sys$dev/.." "$T/sys$dev"
as() {	# as GROUPS WHAT: nobody with these supplementary groups writes to WHAT
	if setpriv --reuid=65534 --regid=65534 --groups="$1" sh -c "printf 1 | dd of='$T/sys$dev/$2' conv=notrunc status=none" 2> /dev/null
	then echo "user in groups $3 writes $2: yes"; else echo "user in groups $3 writes $2: no"; fi
}
as $gid resource0 hal
as 65534 resource0 other
as $gid enable hal
