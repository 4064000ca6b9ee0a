# Kernel flavor in qemu, as root (cases/40-devices.sh: it needs qemu's second 16550 at
# 0x2f8, from which that case unbinds Linux's 8250 driver, and /dev/port). serport
# claims 0x2f8-0x2fe from the kernel; its write puts DTR in MCR and Break in LCR, read
# back from the UART; qemu's idle modem status (DCD, DSR, CTS asserted, RI not) reads
# in RS-232 sense; then, with serport's write taken off the thread, the UART in
# loopback (MCR bit 4) returns DTR on DSR, RTS on CTS, OUT1 on RI and OUT2 on DCD.
set -e
inport() { dd if=/dev/port bs=1 skip=$(($1)) count=1 2>/dev/null | od -An -tu1 | tr -d ' '; }
outport() { printf "\\$(printf %o $(($2)))" | dd of=/dev/port bs=1 seek=$(($1)) count=1 conv=notrunc 2>/dev/null; }
pins() {
	for p in 1 6 8 9; do
		printf ' %s=%s/%s' $p "$(halcmd getp serport.0.pin-$p-in)" "$(halcmd getp serport.0.pin-$p-in-not)"
	done
	echo
}
halcmd -f uart.hal
grep serport /proc/ioports | sed 's/^ *//'
echo "mcr $(inport 0x2fc) lcr $(inport 0x2fb)"
printf 'idle:'; pins
halcmd delf serport.0.write t
for mcr in 0x11 0x12 0x14 0x18 0x10; do
	outport 0x2fc $mcr
	halcmd start
	sleep 0.05
	halcmd stop
	printf 'loopback mcr=%s:' $mcr; pins
done
outport 0x2fc 0
halrun -U
echo done
