# Compile a .comp from outside the tree with halcompile --install into a private
# module directory (beside links to the tree's modules), then load and run it.
set -e
tmp=${TEST_TMPDIR:-$(mktemp -d)}
rtlib=$(dirname "$(command -v halrun)")/../rtlib
mkdir -p "$tmp/rtlib" "$tmp/src"
ln -sf "$rtlib/threads.so" "$tmp/rtlib/threads.so"
cp mything.comp "$tmp/src/"
cd "$tmp/src"
HAL_RTLIB_DIR=$tmp/rtlib halcompile --install mything.comp
ls "$tmp/rtlib/mything.so" > /dev/null
export HAL_RTLIB_DIR=$tmp/rtlib
cat > test.hal <<'HAL'
loadrt threads name1=thread period1=1000000
loadrt mything count=2 personality=0x31,0
addf mything.0.add thread
addf mything.0.set-bits thread
addf mything.1.add thread
setp mything.0.in1 0.5
setp mything.0.sel 5
start
loadusr -w sleep 0.05
stop
getp mything.0.sum
getp mything.0.out-0
getp mything.0.out-1
getp mything.0.out-2
getp mything.0.out-3
getp mything.0.extra
getp mything.0.arr-02
getp mything.0.flag
getp mything.1.in0
getp mything.1.gain
ptype mything.0.count-io
list pin mything.1.*
HAL
halrun -f test.hal
