# Faults disable motion with the documented messages: a limit switch (again after a
# re-enable, not with the override, which ends with the jog off the switch), the
# following error, an amplifier fault, motion.enable going FALSE; ENABLE is refused
# while motion.enable is FALSE.
. ../lib.sh
motion_load 2
halcmd unlinkp joint.1.motor-pos-fb || exit 1	# joint 1: no feedback -> following error
halcmd start || exit 1
motion_config 2 10 100
state() { motcmd status | head -1 | cut -d' ' -f1-4; }
echo "== limit switch"
motcmd enable || exit 1
halcmd setp joint.0.pos-lim-sw-in 1
motcmd wait-state disabled 5 || exit 1
motcmd errors
state
echo "== enable again on the switch"
motcmd enable || exit 1
motcmd wait-state disabled 5 || exit 1
motcmd errors
echo "== override"
motcmd override-limits 0 || exit 1
motcmd enable || exit 1
motcmd wait-state free 5 || exit 1
motcmd jog-incr 0 -0.5 1 || exit 1
halcmd setp joint.0.pos-lim-sw-in 0
motcmd wait-inpos 5 || exit 1
motcmd status | grep -o 'override-limits 0x[0-9a-f]*'
state
echo "== following error"
motcmd jog-incr 1 2 10 || exit 1
motcmd wait-state disabled 5 || exit 1
motcmd errors
halcmd net fb1 joint.1.motor-pos-fb || exit 1
echo "== amplifier fault"
motcmd enable || exit 1
motcmd wait-state free 5 || exit 1
halcmd setp joint.0.amp-fault-in 1
motcmd wait-state disabled 5 || exit 1
motcmd errors | sort -u
halcmd setp joint.0.amp-fault-in 0
echo "== enable input"
motcmd enable || exit 1
motcmd wait-state free 5 || exit 1
halcmd setp motion.enable 0
motcmd wait-state disabled 5 || exit 1
motcmd errors
motcmd enable
echo "enable status $?"
halcmd getp joint.0.amp-enable-out
halrun -U
