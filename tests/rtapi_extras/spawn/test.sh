# Build extras.c with only -I RIP/include, load it, read what it found.
set -e
tmp=${TEST_TMPDIR:-$(mktemp -d)}
rip=$(dirname "$(command -v halrun)")/..
mkdir -p "$tmp/rtlib"
cc -shared -fPIC -DRTAPI -Wall -Werror -I "$rip/include" -o "$tmp/rtlib/extras.so" extras.c
HAL_RTLIB_DIR=$tmp/rtlib halcmd loadrt extras touch="$tmp/spawned"
halcmd getp extras.spawn-status
halcmd getp extras.open-ok
halcmd getp extras.kernelspace
halcmd getp extras.pll-refused
ls "$tmp/spawned" > /dev/null && echo spawned
halrun -U
