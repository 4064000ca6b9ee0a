# Kernel flavor in qemu, as root (cases/40-devices.sh; /dev/port to look at the data
# register): with Linux's parport_pc driving qemu's parallel port, hal_parport claims
# it through the parport layer (small-boards.md 3.5), not as a raw I/O range: by
# Linux parport number (cfg="0") and by the base address of a port Linux owns
# (cfg="0x378"). While hal_parport holds it, its pardevice is the port's active one
# and its writes reach the data register; after halrun -U the port is free again and
# parport can be unloaded (nothing of HAL holds it). Then the other order: rtapi.ko
# first (a parport number is refused while Linux has no parport layer), parport
# loaded after it, and the claim works as well (rtapi_parport_linux.h).
set -e
inport() { dd if=/dev/port bs=1 skip=$(($1)) count=1 2>/dev/null | od -An -tx1 | tr -d ' '; }
trap 'halrun -U >/dev/null 2>&1; rmmod parport_pc parport 2>/dev/null || true' EXIT
p=/proc/sys/dev/parport/parport0
active() { sed 's/(comp [0-9]*)//' $p/devices/active; }
load_parport() {
	insmod /lib/testdev-modules/parport.ko
	insmod /lib/testdev-modules/parport_pc.ko
	echo "parport0 base-addr: $(tr -s '\t ' ' ' <$p/base-addr), active: $(active)"
}
claim() {
	halcmd loadrt hal_parport "cfg=\"$1\""
	halcmd addf parport.0.write t
	halcmd setp parport.0.pin-03-out 1
	halcmd setp parport.0.pin-08-out 1
	halcmd start; sleep 0.1; halcmd stop
	echo "cfg=$1: active $(active), data $(inport 0x378)," \
		"raw regions $(grep -c hal_parport /proc/ioports || true)," \
		"rtapi_parport_linux $(grep -c '^rtapi_parport_linux ' /proc/modules || true)"
	halrun -U
	echo "after halrun -U: active $(active)," \
		"modules $(grep -cE '^(rtapi|hal_lib|rtapi_parport_linux) ' /proc/modules || true)"
}

echo "== parport before rtapi"
load_parport
for cfg in 0 0x378; do
	halcmd loadrt threads name1=t period1=1000000
	claim $cfg
done
rmmod parport_pc parport && echo "parport unloaded"

echo "== rtapi before parport"
halcmd loadrt threads name1=t period1=1000000
if halcmd loadrt hal_parport 'cfg="0"' >"$TEST_TMPDIR/out" 2>&1; then echo "cfg=0 loaded"; else echo "cfg=0 refused"; fi
sed 's/(comp [0-9]*)//' "$TEST_TMPDIR/out"
load_parport
claim 0
rmmod parport_pc parport && echo "parport unloaded"
