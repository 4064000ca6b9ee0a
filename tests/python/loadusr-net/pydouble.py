#!/usr/bin/env python3
# A userspace component in Python, as LinuxCNC users write them: out = in * gain,
# count counts the loop passes. SIGTERM (halcmd unloadusr) ends it cleanly.
import signal
import sys
import time

import hal

signal.signal(signal.SIGTERM, lambda *_: sys.exit(0))
c = hal.component("pydouble")
c.newpin("in", hal.HAL_FLOAT, hal.HAL_IN)
c.newpin("out", hal.HAL_FLOAT, hal.HAL_OUT)
c.newpin("negative", hal.HAL_BIT, hal.HAL_OUT)
c.newpin("count", hal.HAL_U32, hal.HAL_OUT)
c.newparam("gain", hal.HAL_FLOAT, hal.HAL_RW)
c["gain"] = 2.0
c.ready()
try:
    while True:
        c["out"] = c["in"] * c["gain"]
        c.negative = c["out"] < 0
        c["count"] = (c["count"] + 1) & 0xffffffff
        time.sleep(0.005)
except KeyboardInterrupt:
    raise SystemExit
