# Each bad module parameter is refused with a one-line message, and nothing stays loaded.
try() {
	halcmd loadrt "$@"
	echo "$1 status $? components $(halcmd -s show comp | grep -c .)"
}
try trivkins coordinates=xyq
try trivkins coordinates=XYZABCUVWXYZABCUV
try trivkins coordinates=xyzabcuvwxyzabcuvwxyzabcuvwxyzabc
try trivkins kinstype=z
try gantrykins coordinates=XYZABCUVWX
try genserkins coordinates=xyzq
try pumakins coordinates=
halcmd unloadrt pumakins
try trivkins coordinates=xyz
try kinstest joints=17
halrun -U
