# Kernel flavor in qemu, against qemu's emulated parallel port at 0x378 (no Linux
# parport driver loaded): hal_parport claims 0x378-0x37f and the probed high range
# from the kernel's resource tree (not a simulated device), and in type x the four
# open-collector control pins read back high after write.
set -e
halcmd -f lpt.hal
grep -i 'hal_parport' /proc/ioports | sed 's/(comp [0-9]*)//; s/^ *//'
for p in 01 14 16 17 10 11 12 13 15; do
	echo "pin-$p-in $(halcmd getp parport.0.pin-$p-in) $(halcmd getp parport.0.pin-$p-in-not)"
done
halrun -U
echo done
