# A simulated 5i20 with SVST8_4 firmware, some modules disabled by the config string:
# their pins become full GPIOs; stepgen_width=2 leaves the table pins as GPIO; the
# 8 board LEDs; no DPLL in this firmware (no timer-number params, no dpll pins).
set -e
halcmd loadrt hostmot2
halcmd loadrt hm2_sim board=5i20 'config="num_encoders=2 num_pwmgens=1 num_stepgens=1 num_leds=3"'
halcmd list pin 'hm2_5i20.0.*' | tr ' ' '\n'
halcmd list param 'hm2_5i20.0.*' | tr ' ' '\n'
halcmd list funct 'hm2_5i20.0.*'
halrun -U
