# SPDX-License-Identifier: GPL-2.0-or-later
# hal.component, its pins and parameters, and the errors LinuxCNC users expect.
import math

import pytest

import hal
from conftest import halcmd

LIMITS = {
    hal.HAL_S32: (-2**31, 2**31 - 1),
    hal.HAL_U32: (0, 2**32 - 1),
    hal.HAL_S64: (-2**63, 2**63 - 1),
    hal.HAL_U64: (0, 2**64 - 1),
}


def test_constants_have_linuxcnc_values():
    assert (hal.HAL_BIT, hal.HAL_FLOAT, hal.HAL_S32, hal.HAL_U32) == (1, 2, 3, 4)
    assert (hal.HAL_S64, hal.HAL_U64) == (5, 6)
    assert (hal.HAL_IN, hal.HAL_OUT, hal.HAL_IO) == (16, 32, 48)
    assert (hal.HAL_RO, hal.HAL_RW) == (64, 192)
    assert (hal.MSG_NONE, hal.MSG_ERR, hal.MSG_WARN, hal.MSG_INFO, hal.MSG_DBG, hal.MSG_ALL) == \
        (0, 1, 2, 3, 4, 5)
    assert issubclass(hal.error, RuntimeError)


def test_flags_in_the_simulated_flavor():
    assert hal.is_sim is True and hal.is_userspace is True
    assert hal.is_rt is False and hal.is_kernelspace is False


def test_pins_of_every_type_round_trip(make_comp, name):
    c = make_comp(name)
    for t in (hal.HAL_BIT, hal.HAL_FLOAT, *LIMITS):
        c.newpin(f"t{t}", t, hal.HAL_OUT)
    c.ready()
    c[f"t{hal.HAL_BIT}"] = True
    assert c[f"t{hal.HAL_BIT}"] is True
    c[f"t{hal.HAL_FLOAT}"] = -0.125
    assert c[f"t{hal.HAL_FLOAT}"] == -0.125
    for t, (lo, hi) in LIMITS.items():
        for v in (lo, hi):
            c[f"t{t}"] = v
            assert c[f"t{t}"] == v and type(c[f"t{t}"]) is int
            assert hal.get_value(f"{name}.t{t}") == v
    # what the rest of the HAL sees
    assert halcmd("getp", f"{name}.t{hal.HAL_BIT}").strip() == "TRUE"
    assert halcmd("getp", f"{name}.t{hal.HAL_FLOAT}").strip() == "-0.125"
    assert halcmd("getp", f"{name}.t{hal.HAL_U64}").strip() == str(2**64 - 1)


def test_pin_objects(make_comp, name):
    c = make_comp(name)
    p = c.newpin("out", hal.HAL_FLOAT, hal.HAL_OUT)
    q = c.newparam("gain", hal.HAL_S32, hal.HAL_RW)
    assert isinstance(p, hal.Pin) and isinstance(q, hal.Param)
    assert (p.get_name(), p.get_type(), p.get_dir(), p.is_pin()) == \
        (f"{name}.out", hal.HAL_FLOAT, hal.HAL_OUT, True)
    assert (q.get_name(), q.get_type(), q.get_dir(), q.is_pin()) == \
        (f"{name}.gain", hal.HAL_S32, hal.HAL_RW, False)
    p.set(2.5)
    assert p.get() == 2.5 and c["out"] == 2.5
    q.set(-4)
    assert c["gain"] == -4 and hal.get_value(f"{name}.gain") == -4
    assert c.getpin("out").get_name() == f"{name}.out"
    assert c.getparam("gain").get() == -4
    assert sorted(c.getpins()) == ["out"]
    assert repr(p) == f'<hal pin "{name}.out">'


def test_attribute_access(make_comp, name):
    c = make_comp(name)
    c.newpin("x", hal.HAL_S32, hal.HAL_OUT)
    c.x = 12
    assert c.x == 12 and c["x"] == 12
    assert "x" in c and "y" not in c
    with pytest.raises(AttributeError):
        c.y
    c.y = "ordinary attribute"   # not a pin: kept on the object, as on any Python object
    assert c.y == "ordinary attribute"


def test_prefix(make_comp, name):
    c = make_comp(name, prefix=f"{name}x")
    assert c.getprefix() == f"{name}x"
    c.newpin("a", hal.HAL_BIT, hal.HAL_IN)
    c.setprefix(f"{name}y")
    c.newpin("b", hal.HAL_BIT, hal.HAL_IN)
    assert c.getpin("a").get_name() == f"{name}x.a"
    assert c.getpin("b").get_name() == f"{name}y.b"
    assert halcmd("-s", "show", "pin", f"{name}y.b").split()[4] == f"{name}y.b"


def test_ready_and_exit(name):
    c = hal.component(name)
    assert hal.component_exists(name) and not hal.component_is_ready(name)
    c.newpin("in", hal.HAL_FLOAT, hal.HAL_IN)
    c.ready()
    assert hal.component_is_ready(name)
    assert halcmd("-s", "show", "comp", name).split()[1:3] == ["User", name]
    p = c.getpin("in")
    c.exit()
    c.exit()   # twice is harmless
    assert not hal.component_exists(name)
    assert halcmd("-s", "show", "pin", name).strip() == ""
    for access in (lambda: c["in"], lambda: p.get(), lambda: p.set(1.0),
                   lambda: c.newpin("x", hal.HAL_BIT, hal.HAL_IN), c.ready):
        with pytest.raises(hal.error, match="has exited"):
            access()


def test_duplicate_component_is_refused(make_comp, name):
    make_comp(name)
    with pytest.raises(hal.error, match=f"component '{name}' already exists"):
        hal.component(name)


@pytest.mark.parametrize("bad, message", [
    ("", "name is empty"),
    ("x" * 80, "longer than 63"),
    ("two words", "whitespace"),
])
def test_bad_component_names(bad, message):
    with pytest.raises(hal.error, match=message):
        hal.component(bad)


def test_bad_pins_and_params(make_comp, name):
    c = make_comp(name)
    c.newpin("ok", hal.HAL_BIT, hal.HAL_IN)
    with pytest.raises(hal.error, match=f"pin '{name}.ok' already exists"):
        c.newpin("ok", hal.HAL_BIT, hal.HAL_IN)
    with pytest.raises(hal.error, match="invalid type 99"):
        c.newpin("t", 99, hal.HAL_IN)
    with pytest.raises(hal.error, match="invalid direction"):
        c.newpin("d", hal.HAL_BIT, hal.HAL_RW)
    with pytest.raises(hal.error, match="invalid direction"):
        c.newparam("d", hal.HAL_BIT, hal.HAL_IN)
    with pytest.raises(hal.error, match="longer than 63"):
        c.newpin("n" * 70, hal.HAL_BIT, hal.HAL_IN)
    with pytest.raises(hal.error, match="whitespace"):
        c.newpin("a b", hal.HAL_BIT, hal.HAL_IN)
    # nothing half-made stays behind
    assert halcmd("-s", "show", "pin", name).split()[4::5] == [f"{name}.ok"]


def test_no_pins_after_ready(make_comp, name):
    c = make_comp(name)
    c.ready()
    with pytest.raises(hal.error, match="already ready"):
        c.newpin("late", hal.HAL_FLOAT, hal.HAL_IN)
    with pytest.raises(hal.error, match="already ready"):
        c.newparam("late", hal.HAL_FLOAT, hal.HAL_RW)


def test_unready_allows_more_pins(make_comp, name):
    c = make_comp(name)
    c.newpin("first", hal.HAL_FLOAT, hal.HAL_IN)
    c.ready()
    c.unready()
    assert not hal.component_is_ready(name)
    c.newpin("second", hal.HAL_BIT, hal.HAL_OUT)
    c.newparam("third", hal.HAL_S32, hal.HAL_RW)
    c.ready()
    assert hal.component_is_ready(name)
    assert halcmd("-s", "show", "pin", name).split()[4::5] == [f"{name}.first", f"{name}.second"]
    c.exit()
    with pytest.raises(hal.error, match="has exited"):
        c.unready()


def test_unknown_names_raise_attribute_error(make_comp, name):
    c = make_comp(name)
    c.newpin("pin", hal.HAL_BIT, hal.HAL_IN)
    c.newparam("par", hal.HAL_BIT, hal.HAL_RW)
    with pytest.raises(AttributeError, match="no pin or parameter 'nope'"):
        c["nope"]
    with pytest.raises(AttributeError):
        c["nope"] = 1
    with pytest.raises(AttributeError):
        c.getpin("nope")
    with pytest.raises(AttributeError, match="is a parameter"):
        c.getpin("par")
    with pytest.raises(AttributeError, match="is a pin"):
        c.getparam("pin")


def test_bad_values(make_comp, name):
    c = make_comp(name)
    for t in (hal.HAL_BIT, hal.HAL_FLOAT, *LIMITS):
        c.newpin(f"t{t}", t, hal.HAL_OUT)
    for t, (lo, hi) in LIMITS.items():
        for v in (lo - 1, hi + 1):
            with pytest.raises(ValueError, match="out of range"):
                c[f"t{t}"] = v
        with pytest.raises(ValueError, match="not an integer"):
            c[f"t{t}"] = math.nan
        with pytest.raises(TypeError):
            c[f"t{t}"] = "1"
        assert c[f"t{t}"] == 0   # a refused value changes nothing
    with pytest.raises(TypeError, match="expected a number"):
        c[f"t{hal.HAL_FLOAT}"] = "1.5"
    with pytest.raises(TypeError):
        c[f"t{hal.HAL_FLOAT}"] = None
    with pytest.raises(TypeError, match="expected a bool or a number"):
        c[f"t{hal.HAL_BIT}"] = "0"
    # numbers convert as Python's int() and float() do
    c[f"t{hal.HAL_S32}"] = -7.9
    assert c[f"t{hal.HAL_S32}"] == -7
    c[f"t{hal.HAL_FLOAT}"] = 3
    assert c[f"t{hal.HAL_FLOAT}"] == 3.0 and type(c[f"t{hal.HAL_FLOAT}"]) is float
    c[f"t{hal.HAL_BIT}"] = 2
    assert c[f"t{hal.HAL_BIT}"] is True


def test_input_pins_follow_their_signal(make_comp, name):
    c = make_comp(name)
    c.newpin("in", hal.HAL_FLOAT, hal.HAL_IN)
    c.ready()
    c["in"] = 1.5   # unlinked: the pin's own value, as halcmd setp does
    assert hal.get_value(f"{name}.in") == 1.5
    hal.new_sig(f"{name}-s", hal.HAL_FLOAT)
    hal.connect(f"{name}.in", f"{name}-s")
    hal.set_s(f"{name}-s", "-3.25")
    assert c["in"] == -3.25
    c["in"] = 4.0   # a signal nobody writes: setting the pin sets the signal
    assert hal.get_value(f"{name}-s") == 4.0


def test_setting_an_input_that_has_a_writer_is_refused(make_comp, name):
    src = make_comp(f"{name}src")
    src.newpin("out", hal.HAL_S32, hal.HAL_OUT)
    dst = make_comp(name)
    dst.newpin("in", hal.HAL_S32, hal.HAL_IN)
    hal.new_sig(f"{name}-s", hal.HAL_S32)
    hal.connect(f"{name}src.out", f"{name}-s")
    hal.connect(f"{name}.in", f"{name}-s")
    src["out"] = 42
    assert dst["in"] == 42
    assert hal.pin_has_writer(f"{name}.in")
    with pytest.raises(hal.error, match="has a writer"):
        dst["in"] = 1
    assert dst["in"] == 42


def test_params_and_setp(make_comp, name):
    c = make_comp(name)
    c.newparam("ro", hal.HAL_U32, hal.HAL_RO)
    c.newparam("rw", hal.HAL_FLOAT, hal.HAL_RW)
    c["ro"] = 9   # the owner may set its read-only parameter
    assert halcmd("getp", f"{name}.ro").strip() == "9"
    with pytest.raises(hal.error):
        hal.set_p(f"{name}.ro", "1")
    hal.set_p(f"{name}.rw", "0.5")   # others set RW parameters, the component sees it
    assert c["rw"] == 0.5
    halcmd("setp", f"{name}.rw", "-2")
    assert c["rw"] == -2.0


def test_msg_level():
    old = hal.get_msg_level()
    hal.set_msg_level(hal.MSG_DBG)
    assert hal.get_msg_level() == hal.MSG_DBG
    hal.set_msg_level(old)
    with pytest.raises(ValueError):
        hal.set_msg_level(9)
