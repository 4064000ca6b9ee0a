# Kernel flavor in qemu, against qemu's second emulated 16550 (ttyS1 at 0x2f8, not
# registered by Linux: 8250.nr_uarts=1): serport claims 0x2f8-0x2fe from the kernel
# and reads qemu's idle modem status (DCD, DSR, CTS asserted, RI not) in RS-232 sense.
set -e
halcmd -f uart.hal
grep serport /proc/ioports | sed 's/^ *//'
for p in 1 6 8 9; do
	echo "pin-$p-in $(halcmd getp serport.0.pin-$p-in) $(halcmd getp serport.0.pin-$p-in-not)"
done
halrun -U
