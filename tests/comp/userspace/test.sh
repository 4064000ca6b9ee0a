# comp --compile --userspace builds a userspace component program (linking the HAL
# user library); loadusr runs it, its pins exist, unloadusr ends it.
set -e
tmp=${TEST_TMPDIR:-$(mktemp -d)}
cp ucount.comp "$tmp/"
cd "$tmp"
comp --compile --userspace ucount.comp
cat > test.hal <<'HAL'
loadusr -W ./ucount 100000
ptype ucount.0.n
getp ucount.0.stop
unloadusr ucount
HAL
halrun -f test.hal
