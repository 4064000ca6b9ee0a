# steplen 5000 ns -> 4 ticks, stepspace 3200 -> 2, dirtime 30000 -> 19 > 15: 15 ticks,
# param rewritten to 24000; word = 4 | tap 1 << 6 | 15 << 8 | polarity 0x8000 = 36676.
# Feed-forward only (debug-2 = 0), so the rates are exact. Tap 1: rate = steps/s x 1.6 us x 2^12; 50 kHz -> 327.68; the step space caps at
# 1 / (1.6 us x (2 + 4 + 2)) = 78.1 kHz, so 50 kHz passes; maxvel 10000 -> 65.536 -> 66.
. ../../helpers/pluto-firmware.sh
pluto_firmware pluto_step.rbf
halcmd -f setup.hal || echo "setup failed"
sleep 0.1
halcmd stop
echo "timing $(halcmd getp sim-parport.0.pluto.timing)"
echo "dirtime $(halcmd getp pluto-step.stepgen.dirtime)"
echo "outputs $(halcmd getp sim-parport.0.pluto.outputs)"
echo "rate0 $(halcmd getp sim-parport.0.pluto.stepgen.0.rate)"
echo "rate1 $(halcmd getp sim-parport.0.pluto.stepgen.1.rate)"
echo "maxvel1 $(halcmd getp pluto-step.stepgen.1.maxvel)"
halrun -U
pluto_no_firmware pluto_step.rbf
