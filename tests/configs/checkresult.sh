# Shared checkresult of tests/configs: the HAL part exactly as in expected-hal; the
# launch part up (task and io components present), homed, the program run,
# stopped with exit 0 and nothing left.
result=$1
sed '/^launch/,$d' "$result" | diff expected-hal - || exit 1
grep -q '^launch: comps .*inihal' "$result" || { echo "no inihal component"; exit 1; }
grep -q '^launch: comps .*iocontrol' "$result" || { echo "no iocontrol component"; exit 1; }
grep -q '^launch: .* failed' "$result" && { grep '^launch: .* failed' "$result"; exit 1; }
grep -q '^launch: homed 1$' "$result" || { echo "not homed"; exit 1; }
grep -q "^launch: program ended, last error ''$" "$result" || { echo "the program did not run cleanly"; exit 1; }
grep -q '^launch: exit 0$' "$result" || { echo "launcher exit status not 0"; exit 1; }
grep -q '^launch: left 0$' "$result" || { echo "something left behind"; exit 1; }
