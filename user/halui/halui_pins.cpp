// SPDX-License-Identifier: GPL-2.0-or-later
// halui_pins.cpp - creating the halui.* pins and copying them (halui_pins.hpp).
#include "halui_pins.hpp"

#include <cstring>

namespace hal::halui {

namespace {

// Upper bound of pins: 16 joints x 20, 9 axes x 13, 8 spindles x 20, 64 MDI, ~100 others.
constexpr size_t MAX_PINS = 16 * 20 + 9 * 13 + 8 * 20 + 64 + 128;

// One value between a pin and its field (bool, double, int32_t, unsigned).
template <typename P, typename V>
void copy_as(void* pin, void* field, bool to_pin)
{
    if (to_pin)
        *static_cast<P*>(pin) = *static_cast<V*>(field);
    else
        *static_cast<V*>(field) = *static_cast<P*>(pin);
}

void copy_value(hal_type_t type, void* pin, void* field, bool to_pin)
{
    switch (type) {
    case HAL_BIT: copy_as<hal_bit_t, bool>(pin, field, to_pin); break;
    case HAL_FLOAT: copy_as<hal_float_t, double>(pin, field, to_pin); break;
    case HAL_S32: copy_as<hal_s32_t, int32_t>(pin, field, to_pin); break;
    default: copy_as<hal_u32_t, unsigned>(pin, field, to_pin); break;
    }
}

}  // namespace

int Pins::add(hal_type_t type, hal_pin_dir_t dir, void* field, const std::string& name,
              const std::vector<std::string>& aliases)
{
    if (!error_.empty())
        return -EINVAL;
    if (slots_left_ == 0) {
        error_ = "halui." + name + ": too many pins";
        return -ENOSPC;
    }
    void** slot = slots_++;
    --slots_left_;
    const std::string full = "halui." + name;
    if (int rc = hal_pin_new(full.c_str(), type, dir, slot, comp_id_); rc) {
        error_ = "cannot create pin " + full + ": " + std::strerror(-rc);
        return rc;
    }
    for (const std::string& a : aliases)
        if (int rc = hal_pin_alias(full.c_str(), ("halui." + a).c_str()); rc) {
            error_ = "cannot create alias halui." + a + " of " + full + ": " + std::strerror(-rc);
            return rc;
        }
    pins_.push_back({type, dir, slot, field});
    return 0;
}

int Pins::create(int comp_id, const Config& cfg, Inputs& in, Outputs& out, std::string& error)
{
    comp_id_ = comp_id;
    slots_ = static_cast<void**>(hal_malloc(static_cast<long>(MAX_PINS * sizeof(void*))));
    if (!slots_) {
        error = "out of HAL memory for the pins";
        return -ENOMEM;
    }
    slots_left_ = MAX_PINS;
    const hal_type_t B = HAL_BIT, F = HAL_FLOAT, S = HAL_S32, U = HAL_U32;
    const hal_pin_dir_t I = HAL_IN, O = HAL_OUT;

    add(B, I, &in.abort, "abort");
    add(B, I, &in.machine_on, "machine.on");
    add(B, I, &in.machine_off, "machine.off");
    add(B, O, &out.machine_is_on, "machine.is-on");
    add(F, O, &out.units_per_mm, "machine.units-per-mm");
    add(B, I, &in.estop_activate, "estop.activate");
    add(B, I, &in.estop_reset, "estop.reset");
    add(B, O, &out.estop_is_activated, "estop.is-activated");
    add(B, I, &in.mode_manual, "mode.manual");
    add(B, I, &in.mode_auto, "mode.auto");
    add(B, I, &in.mode_mdi, "mode.mdi");
    add(B, I, &in.mode_teleop, "mode.teleop");
    add(B, I, &in.mode_joint, "mode.joint");
    add(B, O, &out.is_manual, "mode.is-manual");
    add(B, O, &out.is_auto, "mode.is-auto");
    add(B, O, &out.is_mdi, "mode.is-mdi");
    add(B, O, &out.is_teleop, "mode.is-teleop");
    add(B, O, &out.is_joint, "mode.is-joint");
    add(B, I, &in.mist_on, "mist.on");
    add(B, I, &in.mist_off, "mist.off");
    add(B, O, &out.mist_is_on, "mist.is-on");
    add(B, I, &in.flood_on, "flood.on");
    add(B, I, &in.flood_off, "flood.off");
    add(B, O, &out.flood_is_on, "flood.is-on");
    add(B, I, &in.lube_on, "lube.on");
    add(B, I, &in.lube_off, "lube.off");
    add(B, O, &out.lube_is_on, "lube.is-on");
    add(B, I, &in.program_run, "program.run");
    add(B, I, &in.program_pause, "program.pause");
    add(B, I, &in.program_resume, "program.resume");
    add(B, I, &in.program_step, "program.step");
    add(B, I, &in.program_stop, "program.stop");
    add(B, O, &out.program_is_idle, "program.is-idle");
    add(B, O, &out.program_is_running, "program.is-running");
    add(B, O, &out.program_is_paused, "program.is-paused");
    add(B, I, &in.optional_stop_on, "program.optional-stop.on");
    add(B, I, &in.optional_stop_off, "program.optional-stop.off");
    add(B, O, &out.optional_stop_is_on, "program.optional-stop.is-on");
    add(B, I, &in.block_delete_on, "program.block-delete.on");
    add(B, I, &in.block_delete_off, "program.block-delete.off");
    add(B, O, &out.block_delete_is_on, "program.block-delete.is-on");
    add(B, I, &in.home_all, "home-all");

    // joints (EMC2 2.4: halui.jog.N.* for the jog pins)
    auto joint_status = [&](const std::string& p, JointOut& o, bool selected) {
        add(B, O, &o.is_homed, p + "is-homed", selected ? std::vector<std::string>{"joint.selected.is_homed"}
                                                        : std::vector<std::string>{});
        add(B, O, &o.has_fault, p + "has-fault");
        add(B, O, &o.on_soft_min, p + "on-soft-min-limit",
            selected ? std::vector<std::string>{"joint.selected.on-soft-limit"} : std::vector<std::string>{});
        add(B, O, &o.on_soft_max, p + "on-soft-max-limit");
        add(B, O, &o.on_hard_min, p + "on-hard-min-limit");
        add(B, O, &o.on_hard_max, p + "on-hard-max-limit");
        add(B, O, &o.override_limits, p + "override-limits");
    };
    // the jog pins of a joint, an axis or the selected one; 'old' is the 2.4 prefix or ""
    auto jog_pins = [&](const std::string& p, const std::string& old, JogIn& j, bool analog) {
        auto alias = [&](const char* suffix) {
            return old.empty() ? std::vector<std::string>{} : std::vector<std::string>{old + suffix};
        };
        add(B, I, &j.plus, p + "plus", alias("plus"));
        add(B, I, &j.minus, p + "minus", alias("minus"));
        if (analog)
            add(F, I, &j.analog, p + "analog", alias("analog"));
        add(F, I, &j.increment, p + "increment");
        add(B, I, &j.increment_plus, p + "increment-plus");
        add(B, I, &j.increment_minus, p + "increment-minus");
    };
    for (int n = 0; n < cfg.joints; ++n) {
        const std::string p = "joint." + std::to_string(n) + ".";
        JogIn& j = in.joint[static_cast<size_t>(n)];
        JointOut& o = out.joint[static_cast<size_t>(n)];
        add(B, I, &j.home, p + "home");
        add(B, I, &j.unhome, p + "unhome");
        add(B, I, &j.select, p + "select");
        add(B, O, &o.is_selected, p + "is-selected");
        jog_pins(p, "jog." + std::to_string(n) + ".", j, true);
        joint_status(p, o, false);
    }
    add(U, O, &out.joint_selected_index, "joint.selected");
    add(B, I, &in.joint_selected.home, "joint.selected.home");
    add(B, I, &in.joint_selected.unhome, "joint.selected.unhome");
    jog_pins("joint.selected.", "jog.selected.", in.joint_selected, false);
    joint_status("joint.selected.", out.joint_selected, true);
    add(F, I, &in.joint_jog_speed, "joint.jog-speed", {"jog-speed"});
    add(F, I, &in.joint_jog_deadband, "joint.jog-deadband", {"jog-deadband", "jog.deadband"});

    // axes by letter (EMC2 2.4: halui.axis.N.pos-* by axis number)
    for (size_t k = 0; k < cfg.axes.size(); ++k) {
        const int a = cfg.axes[k];
        const std::string p = std::string("axis.") + ini::axis_lower(a) + ".";
        const std::string old = "axis." + std::to_string(a) + ".";
        JogIn& j = in.axis[k];
        AxisOut& o = out.axis[k];
        add(B, I, &j.select, p + "select");
        add(B, O, &o.is_selected, p + "is-selected");
        jog_pins(p, "", j, true);
        add(F, O, &o.pos_commanded, p + "pos-commanded", {old + "pos-commanded"});
        add(F, O, &o.pos_feedback, p + "pos-feedback", {old + "pos-feedback"});
        add(F, O, &o.pos_relative, p + "pos-relative", {old + "pos-relative"});
    }
    add(U, O, &out.axis_selected_index, "axis.selected");
    jog_pins("axis.selected.", "", in.axis_selected, false);
    add(F, I, &in.axis_jog_speed, "axis.jog-speed");
    add(F, I, &in.axis_jog_deadband, "axis.jog-deadband");

    // spindles (EMC2 2.4: halui.spindle.* and halui.spindle-override.* for spindle 0)
    for (int s = 0; s < cfg.spindles; ++s) {
        const std::string p = "spindle." + std::to_string(s) + ".";
        SpindleIn& c = in.spindle[static_cast<size_t>(s)];
        SpindleOut& o = out.spindle[static_cast<size_t>(s)];
        auto old = [&](const std::string& emc2) {
            return s == 0 ? std::vector<std::string>{emc2} : std::vector<std::string>{};
        };
        const struct { bool* field; const char* name; } ins[] = {
            {&c.start, "start"},       {&c.forward, "forward"},   {&c.reverse, "reverse"},
            {&c.stop, "stop"},         {&c.increase, "increase"}, {&c.decrease, "decrease"},
            {&c.brake_on, "brake-on"}, {&c.brake_off, "brake-off"},
        };
        for (const auto& b : ins)
            add(B, I, b.field, p + b.name, old(std::string("spindle.") + b.name));
        const struct { bool* field; const char* name; } outs[] = {
            {&o.is_on, "is-on"}, {&o.runs_forward, "runs-forward"},
            {&o.runs_backward, "runs-backward"}, {&o.brake_is_on, "brake-is-on"},
        };
        for (const auto& b : outs)
            add(B, O, b.field, p + b.name, old(std::string("spindle.") + b.name));
        OverrideIn& k = c.override_;
        const std::string q = p + "override.";
        add(F, O, &o.override_value, q + "value", old("spindle-override.value"));
        add(S, I, &k.counts, q + "counts", old("spindle-override.counts"));
        add(B, I, &k.count_enable, q + "count-enable", old("spindle-override.count-enable"));
        add(B, I, &k.direct_value, q + "direct-value", old("spindle-override.direct-value"));
        add(F, I, &k.scale, q + "scale", old("spindle-override.scale"));
        add(B, I, &k.increase, q + "increase", old("spindle-override.increase"));
        add(B, I, &k.decrease, q + "decrease", old("spindle-override.decrease"));
        add(B, I, &k.reset, q + "reset");
    }

    // feed, rapid and max-velocity knobs (max-velocity has no reset pin)
    auto knob = [&](const std::string& p, OverrideIn& k, double& value, bool reset) {
        add(F, O, &value, p + ".value");
        add(S, I, &k.counts, p + ".counts");
        add(B, I, &k.count_enable, p + ".count-enable");
        add(B, I, &k.direct_value, p + ".direct-value");
        add(F, I, &k.scale, p + ".scale");
        add(B, I, &k.increase, p + ".increase");
        add(B, I, &k.decrease, p + ".decrease");
        if (reset)
            add(B, I, &k.reset, p + ".reset");
    };
    knob("feed-override", in.feed, out.feed_value, true);
    knob("rapid-override", in.rapid, out.rapid_value, true);
    knob("max-velocity", in.max_velocity, out.max_velocity_value, false);

    // tool (2.9 spells length_offset; the seed page length-offset)
    add(U, O, &out.tool_number, "tool.number");
    for (int a = 0; a < 9; ++a)
        add(F, O, &out.tool_length_offset[a], std::string("tool.length_offset.") + ini::axis_lower(a),
            {std::string("tool.length-offset.") + ini::axis_lower(a)});
    add(F, O, &out.tool_diameter, "tool.diameter");

    for (size_t k = 0; k < cfg.mdi.size(); ++k) {
        add(B, I, &in.mdi[k].run, std::string(k < 10 ? "mdi-command-0" : "mdi-command-") + std::to_string(k));
    }
    if (!error_.empty()) {
        error = error_;
        return -EINVAL;
    }
    // IN pins start at the defaults of their fields
    for (const Binding& b : pins_)
        if (b.dir == HAL_IN)
            copy_value(b.type, *b.pin, b.field, true);
    write();
    return 0;
}

void Pins::read()
{
    for (const Binding& b : pins_)
        if (b.dir == HAL_IN)
            copy_value(b.type, *b.pin, b.field, false);
}

void Pins::write() const
{
    for (const Binding& b : pins_)
        if (b.dir == HAL_OUT)
            copy_value(b.type, *b.pin, b.field, true);
}

}  // namespace hal::halui
