# GAIN comes only from --extra-compile-args; the link marker only from --extra-link-args;
# with --personalities=2 a third personality= value is refused.
set -e
. ../private-rtlib.sh
cp pers.comp "$tmp/src/"
cd "$tmp/src"
HAL_RTLIB_DIR=$tmp/rtlib halcompile --install --extra-compile-args=-DGAIN=3 \
	--extra-link-args=-Wl,--defsym=pers_link_marker=0 --personalities=2 pers.comp
nm -D "$tmp/rtlib/pers.so" | grep -c pers_link_marker
export HAL_RTLIB_DIR=$tmp/rtlib
halcompile --personalities=0 pers.comp 2>&1 | head -1
if halcmd loadrt pers count=2 personality=5,7,9 > out 2>&1; then echo "loaded with 3 personalities"; fi
grep -o "personality: 3 values given, at most 2 allowed" out
halrun -U
cat > test.hal <<'HAL'
loadrt threads name1=thread period1=1000000
loadrt pers count=2 personality=5,7
addf pers.0 thread
addf pers.1 thread
start
loadusr -w sleep 0.02
stop
getp pers.0.out
getp pers.1.out
HAL
halrun -f test.hal
