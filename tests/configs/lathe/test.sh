# configs/sim/lathe.ini (trivkins coordinates=XZ): its HAL file loads as the launcher
# runs it, Home All (X, then Z) ends each joint at its [JOINT_n]HOME; then the whole
# machine through "emc lathe.ini" with the sample program (skipped, with the reason,
# while milltask/io are not built).
. ../common.sh
hal_check lathe 2 "X Z" lathe.hal || exit 1
launch_check lathe
