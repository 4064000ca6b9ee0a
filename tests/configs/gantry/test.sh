# configs/sim/gantry.ini (gantrykins coordinates=XYYZ): Home All homes the two Y joints
# as a synchronized group, each ends at [JOINT_n]HOME although their switches are 0.5 mm
# through "emc gantry.ini" (skipped, with the reason, while milltask/io are not built).
. ../common.sh
hal_check gantry 4 "X Y Z" gantry.hal || exit 1
launch_check gantry
