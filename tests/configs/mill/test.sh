# configs/sim/mill.ini: its HAL files load as the launcher runs them, Home All (Z, then
# X and Y) ends every joint at its [JOINT_n]HOME; then the whole machine through
# "emc mill.ini" (skipped, with the reason, while milltask/io are not built).
. ../common.sh
hal_check mill 3 "X Y Z" mill.hal || exit 1
launch_check mill
