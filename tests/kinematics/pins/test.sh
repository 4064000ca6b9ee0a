# Every kinematics module's pins and parameters: type, direction, default, name
# (kins(9), gantrykins(9), kinematics.md); none exports a function.
for m in trivkins gantrykins rotatekins tripodkins maxkins pumakins scarakins genserkins genhexkins; do
	echo "== $m"
	halcmd loadrt $m || exit 1
	halcmd -s show pin $m | awk '{ print "pin", $2, $3, $4, $5 }'
	halcmd -s show param $m | awk '{ print "param", $2, $3, $4, $5 }'
	echo "functions: $(halcmd -s show funct | grep -c .)"
	halcmd unloadrt $m || exit 1
done
halrun -U
