# Sourced by the halcompile tests: a private module directory $tmp/rtlib holding only
# the build's threads.so, so the modules a test compiles and installs are found there
# and nothing lands in the build's own rtlib/. Sets tmp (scratch) and rip (the
# run-in-place tree of the halrun in use), and makes $tmp/src for sources.
tmp=${TEST_TMPDIR:-$(mktemp -d)}
rip=$(dirname "$(command -v halrun)")/..
mkdir -p "$tmp/rtlib" "$tmp/src"
ln -sf "$rip/rtlib/threads.so" "$tmp/rtlib/threads.so"
