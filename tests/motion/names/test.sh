# Every pin and parameter motmod creates (motion.md 4: type, direction, name; the
# homing pins and unlock pins of unlock_joints_mask included), then every seed
# motion(9) name (and the EMC2 names of motion.md 5) resolves to an object.
halcmd loadrt trivkins || exit 1
halcmd loadrt motmod num_joints=3 num_dio=2 num_aio=2 num_misc_error=1 unlock_joints_mask=4 || exit 1
echo "== pins"
halcmd -s show pin | awk '$1 == "motmod" || $NF ~ /^motion/ { print $2, $3, $NF }'
echo "== params"
halcmd -s show param | awk '{ print $2, $3, $NF }' | grep -E ' (motion|traj|tc)'
echo "== functions"
halcmd -s show funct | awk '{ print $NF }'
echo "== seed names"
grep -v '^#' seed-names | while read -r kind name; do
	case $kind in
	funct) halcmd -s show funct | awk '{ print $NF }' | grep -qx "$name" ;;
	*) halcmd getp "$name" >/dev/null ;;
	esac || echo "missing $kind $name"
done
echo "seed names checked: $(grep -vc '^#' seed-names)"
halcmd unloadrt motmod
halrun -U
