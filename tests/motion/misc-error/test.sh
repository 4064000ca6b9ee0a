# Misc-error fault inputs (motion.md 2, 4.1, 11.3): TRUE while enabled -> "Motion
# Stopped by misc error N", motion disabled; numbered and named variants.
. ../lib.sh
state() { motcmd status | head -1 | cut -d' ' -f1-4; }
motion_load 1 num_misc_error=2
halcmd start || exit 1
motion_config 1
motcmd enable || exit 1
motcmd wait-state free 5 || exit 1
echo "== motion.misc-error-01"
halcmd setp motion.misc-error-01 1
motcmd wait-state disabled 5 || exit 1
motcmd errors | sort -u
state
echo "== enable while it stays TRUE"
motcmd enable || exit 1
motcmd wait-state disabled 5 || exit 1
motcmd errors | sort -u
halcmd setp motion.misc-error-01 0
motcmd enable || exit 1
motcmd wait-state free 5 || exit 1
sleep 0.05
state
halrun -U
echo "== names_misc_errors=coolant,door"
motion_load 1 names_misc_errors=coolant,door
halcmd start || exit 1
motion_config 1
halcmd -s show pin motion.err | awk '{ print $2, $3, $5 }'
motcmd enable || exit 1
motcmd wait-state free 5 || exit 1
halcmd setp motion.err-door 1
motcmd wait-state disabled 5 || exit 1
motcmd errors | sort -u
state
halrun -U
