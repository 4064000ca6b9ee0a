# A run-in-place tree of our own: bin/halrun (a copy, found first on PATH) and rtlib/.
set -e
tmp=${TEST_TMPDIR:-$(mktemp -d)}
unset HAL_RTLIB_DIR
mkdir -p "$tmp/tree/bin" "$tmp/tree/rtlib" "$tmp/src"
cp "$(command -v halrun)" "$tmp/tree/bin/halrun"
cd "$tmp/src"
cat > here.comp <<'C'
component here;
pin out bit out;
function _ nofp;
license "GPL";
;;
FUNCTION(_) { out = 1; }
C
PATH=$tmp/tree/bin:$PATH halcompile --install here.comp
ls "$tmp/tree/rtlib"
