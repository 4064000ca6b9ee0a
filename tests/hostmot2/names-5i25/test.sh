# Every HAL name hostmot2 creates for a simulated 5i25 running 7i76 step/dir firmware
# (IOPort/GPIO, encoder, stepgen, pwmgen, watchdog, LED, raw, DPLL), with its type,
# direction and load-time value.
set -e
halcmd loadrt hostmot2
halcmd loadrt hm2_sim board=5i25 'config="enable_raw"'
halcmd -s show pin 'hm2_5i25.0.*'
halcmd -s show param 'hm2_5i25.0.*'
halcmd list funct 'hm2_5i25.0.*'
halcmd show alias
halrun -U
