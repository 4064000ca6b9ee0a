unset NOT_SET_ANYWHERE ALSO_NOT_SET
GATES=2 GATE=and2.1 WORDS="two  words" halrun -k -f env.hal
echo "exit $?"
