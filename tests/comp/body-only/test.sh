# Build twice.comp (no FUNCTION(_) in it) and run it.
set -e
. ../private-rtlib.sh
cp twice.comp "$tmp/src/"
cd "$tmp/src"
HAL_RTLIB_DIR=$tmp/rtlib halcompile --install twice.comp
export HAL_RTLIB_DIR=$tmp/rtlib
cat > test.hal <<'HAL'
loadrt threads name1=thread period1=1000000
loadrt twice
setp twice.0.in 21
addf twice.0 thread
start
loadusr -w sleep 0.02
stop
getp twice.0.out
HAL
halrun -f test.hal
