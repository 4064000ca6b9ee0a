# Every IDROM refusal (hm2_sim fault=...) and config-string error makes the board
# load fail with one message naming the board and the reason; hm2_sim's own
# argument errors too. Nothing is left behind: only hostmot2 stays loaded.
halcmd loadrt hostmot2 || exit 1
for f in no-cookie bad-name idrom-offset-0 idrom-type port-width io-width io-ports \
	 clock-low clock-high pd-sentinel no-ioport md-inconsistent clock-tag duplicate-md; do
	if halcmd loadrt hm2_sim board=5i25 fault=$f; then echo "fault=$f: loaded"; fi
done
for c in num_encoders=2 num_stepgens=6 num_pwmgens=2 num_3pwmgens=1 num_bspis=1 \
	 num_resolvers=1 num_uarts=1 bogus=1 num_encoders=x stepgen_width=9 \
	 sserial_port_0=00 ssi_chan_0=pos%24g firmware= num_encoders; do
	if halcmd loadrt hm2_sim board=5i25 "config=\"$c\""; then echo "config=$c: loaded"; fi
done
for c in num_3pwmgens=2 num_bspis=2 num_uarts=2 num_encoders=9; do
	if halcmd loadrt hm2_sim board=5i23 "config=\"$c\""; then echo "5i23 config=$c: loaded"; fi
done
# sub-drivers: a missing or wrong channel name fails their load, nothing is left
if halcmd loadrt mesa_7i65; then echo "mesa_7i65 without bspi_chans: loaded"; fi
if halcmd loadrt mesa_7i65 bspi_chans=hm2_5i23.0.bspi.0; then echo "mesa_7i65 with no board: loaded"; fi
if halcmd loadrt mesa_uart uart_chans=hm2_5i23.0.uart.7; then echo "mesa_uart with no board: loaded"; fi
halcmd loadrt hm2_sim board=5i23
if halcmd loadrt mesa_7i65 bspi_chans=hm2_5i23.0.bspi.0,hm2_5i23.0.bspi.3; then
	echo "mesa_7i65 with one bad name: loaded"
fi
if halcmd loadrt mesa_uart uart_chans=hm2_5i23.0.bspi.0; then echo "mesa_uart on a BSPI: loaded"; fi
halcmd loadrt mesa_7i65 bspi_chans=hm2_5i23.0.bspi.0	# the first is usable again
halcmd unloadrt mesa_7i65
halcmd unloadrt hm2_sim
halcmd loadrt hm2_sim board=7i92 || true
halcmd loadrt hm2_sim board=5i25 fault=bogus || true
halcmd loadrt hm2_sim || true
halcmd loadrt hm2_sim board=5i25 config=enable_raw,num_leds=1 || true
echo "components: $(halcmd list comp)"
halrun -U
