# SPDX-License-Identifier: GPL-2.0-or-later
# pytest suite of the Python hal module (registered with CTest: make unit-test).
# One simulated-flavor HAL for the whole run, in an RTAPI instance of its own, so
# it runs beside the other tests. CTest sets HAL_BIN_DIR (build/bin) and PYTHONPATH
# (the module's directory in the build tree).
import itertools
import os
import subprocess

import pytest

BIN_DIR = os.environ["HAL_BIN_DIR"]
os.environ["PATH"] = BIN_DIR + os.pathsep + os.environ.get("PATH", "")
os.environ["RTAPI_INSTANCE"] = f"pytest-{os.getpid()}"
os.environ["HAL_FLAVOR"] = "sim"   # before 'import hal': the ULAPI reads it once
os.environ.setdefault("RTAPI_MSG_LEVEL", "ERR")

_names = itertools.count()


def halcmd(*args, check=True):
    """Run halcmd; returns stdout. check=False returns (status, stdout, stderr)."""
    r = subprocess.run([os.path.join(BIN_DIR, "halcmd"), *args], capture_output=True,
                       text=True, timeout=60, stdin=subprocess.DEVNULL)
    if not check:
        return r.returncode, r.stdout, r.stderr
    assert r.returncode == 0, f"halcmd {' '.join(args)}: {r.stderr}"
    return r.stdout


@pytest.fixture(scope="session", autouse=True)
def realtime():
    # rtapi_app's output goes nowhere: it outlives this call
    subprocess.run([os.path.join(BIN_DIR, "realtime"), "start"], check=True, timeout=60,
                   stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    yield
    subprocess.run([os.path.join(BIN_DIR, "realtime"), "stop"], timeout=60,
                   stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


@pytest.fixture
def name():
    """A component/signal name no other test uses."""
    return f"py{next(_names)}"


@pytest.fixture
def make_comp():
    """make_comp(name, **kw): a hal.component that is exited after the test."""
    import hal
    made = []

    def make(comp_name, **kw):
        c = hal.component(comp_name, **kw)
        made.append(c)
        return c
    yield make
    for c in made:
        c.exit()
