# component foo in bar.comp: refused for --preprocess and --compile, exit status 1.
tmp=${TEST_TMPDIR:-$(mktemp -d)}
cd "$tmp"
cat > bar.comp <<'C'
component foo;
pin out bit out;
function _ nofp;
license "GPL";
;;
FUNCTION(_) { out = 1; }
C
halcompile --preprocess bar.comp 2>&1
echo "status $?"
halcompile --compile bar.comp 2>&1
echo "status $?"
ls bar.c bar.so foo.so 2>/dev/null
echo done
