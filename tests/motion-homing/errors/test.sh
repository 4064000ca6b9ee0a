# Refusals and aborts, with their messages: a bad homing config; motion.homing-inhibit;
# a shared home switch that is closed; a limit switch (comp.1: TRUE above 0.5, wired to
# joint.0.pos-lim-sw-in) met during the search for a switch at 1.0, which aborts homing
# (and then faults motion, the joint being on its limit).
. ../lib.sh
homing_machine 2
halcmd -f <<'HAL' || exit 1
setp comp.0.in0 1.0
setp comp.1.in0 0.5
unlinkp comp.1.in1
net m0 => comp.1.in1
unlinkp comp.1.out
net lim comp.1.out => joint.0.pos-lim-sw-in
setp comp.1.hyst 0
start
HAL
joint_limits 0
motcmd enable || exit 1
wait_idle() { motcmd wait-inpos 10 >/dev/null; sleep 0.2; }
echo "-- search without latch"
motcmd set-joint-homing 0 0 0 -1 2 0 0 0 || exit 1
motcmd home 0; wait_idle; motcmd errors
echo "-- latch without search or index"
motcmd set-joint-homing 0 0 0 -1 0 0.5 0 0 || exit 1
motcmd home 0; wait_idle; motcmd errors
echo "-- homing-inhibit"
motcmd set-joint-homing 0 0 0 -1 2 0.5 0 0 || exit 1
halcmd setp motion.homing-inhibit TRUE
motcmd home 0; motcmd errors
halcmd setp motion.homing-inhibit FALSE
echo "-- shared switch closed"
halcmd setp comp.0.in0 -1.0
motcmd set-joint-homing 0 0 0 -1 2 0.5 4 0 || exit 1
motcmd home 0; wait_idle; motcmd errors
echo "joint.0.homed $(halcmd getp joint.0.homed) home-state $(halcmd getp joint.0.home-state)"
halcmd setp comp.0.in0 1.0
echo "-- limit switch during the search"
motcmd set-joint-homing 0 0 0 -1 2 0.5 0 0 || exit 1
motcmd home 0 || exit 1
motcmd wait-state disabled 20 || exit 1
motcmd errors
echo "joint.0.homed $(halcmd getp joint.0.homed) homing $(halcmd getp joint.0.homing) home-state $(halcmd getp joint.0.home-state)"
halrun -U
