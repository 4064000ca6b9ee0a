# Kernel flavor in qemu, as root (cases/40-devices.sh; /dev/port to look at the
# registers): hal_parport against qemu's emulated parallel port at 0x378, which no
# Linux driver holds (parport_pc is not loaded). hal_parport claims 0x378-0x37f and the
# high range 0x778-0x77a from the kernel's resource tree. Type out: the data byte is
# the pins 2-9 (with their inverts), the control byte the pins 1, 14, 16, 17 with the
# port's inversions; qemu models a printer on the port: strobing it (pin 1 low while
# selected) clears Busy, which pin 11 reads through the port's own inversion, and it
# returns to idle when the strobe ends. Type x: the four control pins read back high.
# Type in: the direction bit is set and the data pins read what qemu's port returns.
set -e
inport() { dd if=/dev/port bs=1 skip=$(($1)) count=1 2>/dev/null | od -An -tx1 | tr -d ' '; }
run() { halcmd start; sleep 0.1; halcmd stop; }
status() {
	for p in 10 11 12 13 15; do printf ' %s=%s' $p "$(halcmd getp parport.0.pin-$p-in)"; done
	echo
}
halcmd -f out.hal
grep -i 'hal_parport' /proc/ioports | sed 's/(comp [0-9]*)//; s/^ *//'
echo "out: data $(inport 0x378) control $(inport 0x37a) (qemu reads bits 6-7 as 1)"
printf 'idle status:'; status
halcmd setp parport.0.pin-01-out 0; run
echo "strobe: control $(inport 0x37a)"
printf 'strobed status:'; status
halcmd setp parport.0.pin-01-out 1; run
printf 'strobe over:'; status
halrun -U
grep -ci 'hal_parport' /proc/ioports || true

halcmd loadrt threads name1=t period1=1000000
halcmd loadrt hal_parport 'cfg="0x378 x"'
halcmd addf parport.0.read t
halcmd addf parport.0.write t
halcmd setp parport.0.pin-02-out 1
run
echo "x: data $(inport 0x378) control $(inport 0x37a)"
for p in 01 14 16 17; do printf ' %s=%s/%s' $p "$(halcmd getp parport.0.pin-$p-in)" "$(halcmd getp parport.0.pin-$p-in-not)"; done
echo
halrun -U

halcmd loadrt threads name1=t period1=1000000
halcmd loadrt hal_parport 'cfg="0x378 in"'
halcmd addf parport.0.read t
halcmd addf parport.0.write t
run
echo "in: control $(inport 0x37a)"
for p in 02 03 04 05 06 07 08 09; do printf ' %s=%s' $p "$(halcmd getp parport.0.pin-$p-in)"; done
echo
halrun -U
echo done
