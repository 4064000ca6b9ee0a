# A script (not a component) that wires and inspects the HAL with the hal module's
# functions, then tries what must be refused, printing each exception's class.
import os

import hal


def attempt(what, fn, *args):
    try:
        fn(*args)
        print(f"{what}: accepted")
    except Exception as e:  # the class is what this test checks
        print(f"{what}: {type(e).__module__}.{type(e).__name__}: {e}")


# is_sim/is_kernelspace tell the flavor the HAL runs in (the runner's HAL_TEST_FLAVOR)
kernel = os.environ.get("HAL_TEST_FLAVOR") == "kernel"
print("flags match the flavor:",
      (hal.is_sim, hal.is_userspace, hal.is_kernelspace) == (not kernel, not kernel, kernel))
hal.new_sig("x", hal.HAL_FLOAT)
hal.connect("abs.0.in", "x")
hal.set_s("x", "-2.5")
print("abs.0.in:", hal.get_value("abs.0.in"), "x:", hal.get_value("x"))
hal.set_p("not.0.in", "TRUE")
print("not.0.in:", hal.get_value("not.0.in"), "has writer:", hal.pin_has_writer("not.0.in"))
hal.set_p("abs.0.tmax", 7)
print("abs.0.tmax:", hal.get_value("abs.0.tmax"))
hal.new_sig("y", hal.HAL_BIT)
hal.connect("abs.0.is-negative", "y")
hal.connect("not.0.in", "y")
print("linked not.0.in has writer:", hal.pin_has_writer("not.0.in"))
print("abs exists:", hal.component_exists("abs"), "ready:", hal.component_is_ready("abs"),
      "nope exists:", hal.component_exists("nope"), "ready:", hal.component_is_ready("nope"))
for s in hal.get_info_signals():
    print("signal", s)
for p in hal.get_info_pins():
    if p["NAME"].startswith("not."):
        print("pin", p)
for p in hal.get_info_params():
    if p["NAME"].startswith("abs."):
        print("param", p)

attempt("set_p unknown", hal.set_p, "nope.in", "1")
attempt("set_p output pin", hal.set_p, "abs.0.out", "1")
attempt("set_p linked input", hal.set_p, "not.0.in", "0")
attempt("set_p bad s32", hal.set_p, "abs.0.tmax", "seven")
attempt("set_s driven signal", hal.set_s, "y", "1")
attempt("set_s unknown", hal.set_s, "nope", "1")
attempt("set_s bad float", hal.set_s, "x", "nan")
attempt("new_sig duplicate", hal.new_sig, "x", hal.HAL_FLOAT)
attempt("new_sig bad type", hal.new_sig, "z", 99)
attempt("connect second writer", hal.connect, "not.0.out", "y")
attempt("connect wrong type", hal.connect, "abs.0.out", "y")
attempt("connect unknown pin", hal.connect, "nope.in", "x")
attempt("get_value unknown", hal.get_value, "nope")
attempt("pin_has_writer unknown", hal.pin_has_writer, "nope")
attempt("disconnect unknown", hal.disconnect, "nope")
hal.disconnect("not.0.in")
print("after disconnect:", hal.pin_has_writer("not.0.in"))
