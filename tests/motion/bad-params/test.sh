# Bad load parameters are refused with one line naming them, and nothing stays
# loaded (no component, no thread, no shared block); motmod needs a kinematics module.
try() {
	halcmd loadrt motmod "$@"
	echo "status $? components $(halcmd -s show comp | grep -c motmod) threads $(halcmd -s show thread | grep -c servo-thread)"
}
echo "== no kinematics module"
try
halcmd loadrt trivkins || exit 1
try num_joints=0
try num_joints=17
try num_extrajoints=4 num_joints=3
try num_extrajoints=1 num_joints=3
try num_spindles=9
try num_dio=0
try num_dio=65
try num_aio=65
try num_misc_error=65
try num_dio=4 names_din=a,b
try names_dout=a,,b
try base_period_nsec=2000000 servo_period_nsec=1000000
try servo_period_nsec=0
try unlock_joints_mask=8 num_joints=3
motcmd status
echo "motcmd status $?"
try num_joints=3
halcmd unloadrt motmod
halrun -U
