#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# make demo-hal: run demo/demo.hal in the simulated-realtime flavor and exit.
set -e
build=$(cd "${1:-build}" && pwd)
PATH="$build/bin:$PATH"
export PATH
export RTAPI_INSTANCE="demo-$$"
echo "demo: siggen -> not/and2 -> sampler on a 10 ms thread, printed by halsampler"
exec halrun -f "$(dirname "$0")/demo.hal"
