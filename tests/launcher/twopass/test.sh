# [HAL]TWOPASS: every loadrt/loadusr of all HAL files first (repeated "loadrt COMP
# count=/names=" merged into one), then the rest of each file: a.hal may addf what
# b.hal loads. Without TWOPASS the same files fail at a.hal:5.
. ../common.sh
start_bg "$T/out" m.ini
wait_text "$T/out" "running headless" || exit 1
sed -n -e "s|$PWD|.|g" -e '/TWOPASS/p' "$T/out"
comps
halcmd show thread servo | sed -n "s/^ *[0-9]* *//;s/ *$//;/^[a-z][a-z0-9.]*$/p"
kill -TERM $EMC_PID
wait_status $EMC_PID
echo "== without TWOPASS"
sed '/TWOPASS/d' m.ini > "$T/one.ini"
emc -H "$PWD" "$T/one.ini" > "$T/out" 2>&1 < /dev/null
echo "exit $?"
sed -e "s|$PWD|.|g" -e "s|$T|TMP|g" "$T/out"
left
