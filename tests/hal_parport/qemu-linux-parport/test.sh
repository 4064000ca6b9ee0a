# Kernel flavor in qemu, as root (cases/40-devices.sh; /dev/port to look at the data
# register): with Linux's parport_pc driving qemu's parallel port, hal_parport claims
# it through the parport layer (small-boards.md 3.5), not as a raw I/O range: by
# Linux parport number (cfg="0") and by the base address of a port Linux owns
# (cfg="0x378"). While hal_parport holds it, its pardevice is the port's active one
# and its writes reach the data register; after halrun -U the port is free again.
set -e
inport() { dd if=/dev/port bs=1 skip=$(($1)) count=1 2>/dev/null | od -An -tx1 | tr -d ' '; }
trap 'halrun -U >/dev/null 2>&1; rmmod parport_pc parport 2>/dev/null || true' EXIT
insmod /lib/testdev-modules/parport.ko
insmod /lib/testdev-modules/parport_pc.ko
p=/proc/sys/dev/parport/parport0
echo "parport0 base-addr: $(cat $p/base-addr | tr -s '\t ' ' ')"
echo "active: $(cat $p/devices/active)"
for cfg in 0 0x378; do
	halcmd loadrt threads name1=t period1=1000000
	halcmd loadrt hal_parport "cfg=\"$cfg\""
	halcmd addf parport.0.write t
	halcmd setp parport.0.pin-03-out 1
	halcmd setp parport.0.pin-08-out 1
	halcmd start; sleep 0.1; halcmd stop
	echo "cfg=$cfg: active $(cat $p/devices/active), data $(inport 0x378)"
	grep -c hal_parport /proc/ioports || true
	halrun -U
	echo "after halrun -U: active $(cat $p/devices/active)"
done
