# SPDX-License-Identifier: GPL-2.0-or-later
# Python components as separate programs: exit statuses, clean-up when the program
# ends, and the module found through halcmd's environment (loadusr).
import os
import signal
import subprocess
import sys

import hal
from conftest import halcmd

CHILD_ENV = dict(os.environ)


def run_python(code, **kw):
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          timeout=60, env=CHILD_ENV, stdin=subprocess.DEVNULL, **kw)


def test_component_leaves_hal_when_program_ends(name):
    r = run_python(f"import hal; c = hal.component('{name}'); "
                   f"c.newpin('x', hal.HAL_BIT, hal.HAL_OUT); c.ready(); print(hal.component_is_ready('{name}'))")
    assert r.returncode == 0, r.stderr
    assert r.stdout == "True\n"
    assert not hal.component_exists(name)   # atexit: hal_exit, not left for clean-up
    assert halcmd("-s", "show", "pin", name) == ""


def test_uncaught_hal_error_exits_1(name):
    r = run_python(f"import hal; a = hal.component('{name}'); b = hal.component('{name}')")
    assert r.returncode == 1
    assert r.stderr.splitlines()[-1] == f"hal.error: component '{name}' already exists"
    assert not hal.component_exists(name)


def test_killed_component_is_cleaned_up_by_halcmd(name):
    p = subprocess.Popen([sys.executable, "-c",
                          f"import hal, time; c = hal.component('{name}'); c.ready(); "
                          "print('ready', flush=True); time.sleep(60)"],
                         stdout=subprocess.PIPE, text=True, env=CHILD_ENV, stdin=subprocess.DEVNULL)
    try:
        assert p.stdout.readline() == "ready\n"
        assert hal.component_is_ready(name)
    finally:
        p.send_signal(signal.SIGKILL)
        p.wait(timeout=30)
        p.stdout.close()
    halcmd("show", "comp")   # halcmd removes components whose process is gone
    assert not hal.component_exists(name)


def test_halcmd_puts_the_module_on_pythonpath(name):
    env = {k: v for k, v in CHILD_ENV.items() if k != "PYTHONPATH"}
    code = f"import hal; c = hal.component('{name}'); c.ready(); c.exit()"
    r = subprocess.run([os.path.join(os.environ["HAL_BIN_DIR"], "halcmd"), "loadusr", "-w",
                        sys.executable, "-c", code], capture_output=True, text=True, timeout=60,
                       env=env, stdin=subprocess.DEVNULL)
    assert r.returncode == 0, r.stderr
    # and a program that fails makes loadusr -w fail
    r = subprocess.run([os.path.join(os.environ["HAL_BIN_DIR"], "halcmd"), "loadusr", "-w",
                        sys.executable, "-c", "import hal; hal.get_value('nope')"],
                       capture_output=True, text=True, timeout=60, env=env, stdin=subprocess.DEVNULL)
    assert r.returncode == 1
    assert "hal.error: 'nope' is not a pin, parameter or signal" in r.stderr
    assert "exited with status 1" in r.stderr


def test_halcmd_puts_its_module_first_once():
    module_dir = os.path.dirname(hal.__file__)
    code = "import os; print(os.environ['PYTHONPATH'])"
    halcmd_bin = os.path.join(os.environ["HAL_BIN_DIR"], "halcmd")
    for given, want in (("/elsewhere", f"{module_dir}:/elsewhere"),
                        (f"{module_dir}:/elsewhere", f"{module_dir}:/elsewhere"),
                        (module_dir, module_dir)):
        env = dict(CHILD_ENV, PYTHONPATH=given)
        r = subprocess.run([halcmd_bin, "loadusr", "-w", sys.executable, "-c", code],
                           capture_output=True, text=True, timeout=60, env=env,
                           stdin=subprocess.DEVNULL)
        assert r.returncode == 0, r.stderr
        assert r.stdout == want + "\n"
