# SPDX-License-Identifier: GPL-2.0-or-later
# The hal module's functions for scripts, against realtime components and against
# components of this process.
import pytest

import hal
from conftest import halcmd


@pytest.fixture(scope="module")
def rt():
    """Realtime components to work on: and2.0, not.0 (unloaded afterwards)."""
    halcmd("loadrt", "and2")
    halcmd("loadrt", "not")
    yield
    halcmd("unloadrt", "and2")
    halcmd("unloadrt", "not")


def test_get_value_of_pin_param_signal(rt, name):
    hal.new_sig(name, hal.HAL_U32)
    hal.set_s(name, "0x10")
    assert hal.get_value(name) == 16
    assert hal.get_value("and2.0.out") is False
    assert hal.get_value("and2.0.tmax") == 0
    with pytest.raises(hal.error, match="'nope' is not a pin, parameter or signal"):
        hal.get_value("nope")


def test_set_p_takes_halcmd_values(rt):
    for text, want in (("1", True), ("off", False), ("YES", True), (False, False), (1, True)):
        hal.set_p("and2.0.in0", text)
        assert hal.get_value("and2.0.in0") is want
    hal.set_p("and2.0.tmax", 12)
    assert halcmd("getp", "and2.0.tmax").strip() == "12"
    with pytest.raises(ValueError, match="not a valid bit value"):
        hal.set_p("and2.0.in0", "maybe")
    with pytest.raises(ValueError, match="not a valid s32 value"):
        hal.set_p("and2.0.tmax", "1.5")
    with pytest.raises(TypeError):
        hal.set_p("and2.0.in0", None)
    with pytest.raises(hal.error, match="does not exist"):
        hal.set_p("and2.0.nope", "1")
    with pytest.raises(hal.error, match="is an output"):
        hal.set_p("and2.0.out", "1")


def test_signals_connect_disconnect(rt, name):
    hal.new_sig(name, hal.HAL_BIT)
    hal.connect("and2.0.out", name)
    hal.connect("not.0.in", name)
    assert hal.pin_has_writer("not.0.in") and not hal.pin_has_writer("and2.0.in1")
    assert "<== and2.0.out" in halcmd("show", "sig", name)
    with pytest.raises(hal.error, match="linked to signal"):
        hal.set_p("not.0.in", "1")   # a linked pin: halcmd's rule
    with pytest.raises(hal.error, match="already has a writer"):
        hal.set_s(name, "1")
    with pytest.raises(hal.error, match="already has writer"):
        hal.connect("not.0.out", name)
    with pytest.raises(hal.error, match="type mismatch"):
        hal.connect("and2.0.time", name)   # s32 pin, bit signal
    with pytest.raises(hal.error, match="already exists"):
        hal.new_sig(name, hal.HAL_BIT)
    with pytest.raises(ValueError, match="invalid type"):
        hal.new_sig(name + "x", 0)
    hal.disconnect("not.0.in")
    hal.disconnect("and2.0.out")
    assert not hal.pin_has_writer("not.0.in")
    with pytest.raises(hal.error, match="does not exist"):
        hal.disconnect("nope.in")
    with pytest.raises(hal.error, match="does not exist"):
        hal.pin_has_writer("nope.in")
    with pytest.raises(hal.error, match="signal 'nope' does not exist"):
        hal.set_s("nope", "1")


def test_component_queries(rt, make_comp, name):
    assert hal.component_exists("and2") and hal.component_is_ready("and2")
    assert not hal.component_exists(name) and not hal.component_is_ready(name)
    c = make_comp(name)
    assert hal.component_exists(name) and not hal.component_is_ready(name)
    c.ready()
    assert hal.component_is_ready(name)


def test_get_info_lists(rt, make_comp, name):
    c = make_comp(name)
    c.newpin("o", hal.HAL_S64, hal.HAL_OUT)
    c.newparam("p", hal.HAL_FLOAT, hal.HAL_RO)
    c["o"] = -5
    c["p"] = 0.25
    hal.new_sig(f"{name}-s", hal.HAL_S64)
    hal.connect(f"{name}.o", f"{name}-s")
    hal.new_sig(f"{name}-t", hal.HAL_BIT)

    pins = {d["NAME"]: d for d in hal.get_info_pins()}
    assert pins[f"{name}.o"] == {"NAME": f"{name}.o", "VALUE": -5, "TYPE": hal.HAL_S64,
                                 "DIRECTION": hal.HAL_OUT}
    assert pins["and2.0.in0"]["DIRECTION"] == hal.HAL_IN
    params = {d["NAME"]: d for d in hal.get_info_params()}
    assert params[f"{name}.p"] == {"NAME": f"{name}.p", "VALUE": 0.25, "TYPE": hal.HAL_FLOAT,
                                   "DIRECTION": hal.HAL_RO}
    sigs = {d["NAME"]: d for d in hal.get_info_signals()}
    assert sigs[f"{name}-s"] == {"NAME": f"{name}-s", "VALUE": -5, "TYPE": hal.HAL_S64,
                                 "DRIVER": f"{name}.o"}
    assert sigs[f"{name}-t"]["DRIVER"] is None
    names = [d["NAME"] for d in hal.get_info_pins()]
    assert names == sorted(names)
