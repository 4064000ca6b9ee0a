// SPDX-License-Identifier: GPL-2.0-or-later
// halui_core.cpp - halui's pin logic (halui_core.hpp; behaviour of
// emcrsh-and-halui.md 3.2). Almost every IN pin acts on its rising edge; jog buttons
// also on the falling edge (stop), analog jogs and overrides when their value moves.
#include "halui_core.hpp"

#include <cmath>
#include <cstdio>

namespace hal::halui {

namespace {

bool rise(bool now, bool before) { return now && !before; }
bool fall(bool now, bool before) { return !now && before; }

std::string num(double v)
{
    char b[40];
    std::snprintf(b, sizeof b, "%.9g", v);
    return b;
}

std::string two_digits(size_t k)
{
    char b[8];
    std::snprintf(b, sizeof b, "%02zu", k);
    return b;
}

}  // namespace

Core::Core(Config cfg)
    : cfg_(std::move(cfg)), feed_(0, cfg_.max_feed_override, true), rapid_(0, 1.0, true),
      max_velocity_(0, cfg_.max_velocity, false)
{
    joint_jog_.resize(static_cast<size_t>(cfg_.joints));
    axis_jog_.resize(cfg_.axes.size());
    for (int s = 0; s < cfg_.spindles; ++s)
        spindle_override_.emplace_back(cfg_.min_spindle_override, cfg_.max_spindle_override, true);
    prev_ = make_inputs();
}

Inputs Core::make_inputs() const
{
    Inputs in;
    in.joint.resize(static_cast<size_t>(cfg_.joints));
    in.axis.resize(cfg_.axes.size());
    in.spindle.resize(static_cast<size_t>(cfg_.spindles));
    in.mdi.resize(cfg_.mdi.size());
    return in;
}

Outputs Core::make_outputs() const
{
    Outputs out;
    out.joint.resize(static_cast<size_t>(cfg_.joints));
    out.axis.resize(cfg_.axes.size());
    out.spindle.resize(static_cast<size_t>(cfg_.spindles));
    return out;
}

std::vector<Command> Core::cycle(const Inputs& in, const StatusView* st, double now_s, Outputs& out)
{
    std::vector<Command> cmds = std::move(pending_);
    pending_.clear();
    if (!started_) {
        prev_ = in;   // levels present at start-up are not edges
        started_ = true;
    }
    if (st) {
        write_outputs(*st, out);
        mode_now_ = st->mode;
        simple_commands(in, *st, cmds);
        jogs(in, cmds);
        spindles(in, *st, now_s, cmds);
        overrides(in, *st, now_s, cmds);
        mdi_commands(in, *st, cmds);
    } else {
        // nobody to tell: the knobs still take in their counts so no jump follows
        StatusView none;
        none.spindles.resize(static_cast<size_t>(cfg_.spindles));
        std::vector<Command> dropped;
        overrides(in, none, now_s, dropped);
        spindles(in, none, now_s, dropped);
        cmds.clear();
    }
    for (size_t j = 0; j < out.joint.size(); ++j)
        out.joint[j].is_selected = j == joint_selected_;
    for (size_t a = 0; a < out.axis.size(); ++a)
        out.axis[a].is_selected = a == axis_selected_;
    out.joint_selected_index = joint_selected_;
    out.axis_selected_index = cfg_.axes.empty() ? 0 : static_cast<unsigned>(cfg_.axes[axis_selected_]);
    if (joint_selected_ < out.joint.size())
        out.joint_selected = out.joint[joint_selected_];
    prev_ = in;
    return cmds;
}

void Core::write_outputs(const StatusView& st, Outputs& out) const
{
    out.machine_is_on = st.state == "ON";
    out.estop_is_activated = st.state == "ESTOP";
    out.units_per_mm = st.units_per_mm;
    out.is_manual = st.mode == "MANUAL";
    out.is_auto = st.mode == "AUTO";
    out.is_mdi = st.mode == "MDI";
    out.is_teleop = st.traj_mode == "TELEOP";
    out.is_joint = st.traj_mode == "FREE";
    out.mist_is_on = st.mist;
    out.flood_is_on = st.flood;
    out.lube_is_on = st.lube;
    out.program_is_idle = st.interp == "IDLE";
    out.program_is_running = st.interp == "READING" || st.interp == "WAITING";
    out.program_is_paused = st.interp == "PAUSED";
    out.optional_stop_is_on = st.optional_stop;
    out.block_delete_is_on = st.block_delete;
    for (size_t j = 0; j < out.joint.size() && j < st.joints.size(); ++j) {
        const JointStatus& js = st.joints[j];
        JointOut& o = out.joint[j];
        o.is_homed = js.homed;
        o.has_fault = js.fault;
        o.on_soft_min = js.min_soft;
        o.on_soft_max = js.max_soft;
        o.on_hard_min = js.min_hard;
        o.on_hard_max = js.max_hard;
        o.override_limits = js.override_limits;
    }
    for (size_t k = 0; k < out.axis.size(); ++k) {
        int a = cfg_.axes[k];
        out.axis[k].pos_commanded = st.pos_cmd[a];
        out.axis[k].pos_feedback = st.pos_fb[a];
        out.axis[k].pos_relative = relative_position(st, a);
    }
    for (size_t s = 0; s < out.spindle.size() && s < st.spindles.size(); ++s) {
        const SpindleStatus& sp = st.spindles[s];
        SpindleOut& o = out.spindle[s];
        o.is_on = sp.enabled && sp.direction != 0;
        o.runs_forward = sp.enabled && sp.direction > 0;
        o.runs_backward = sp.enabled && sp.direction < 0;
        o.brake_is_on = sp.brake;
        o.override_value = sp.scale;
    }
    out.feed_value = st.feed_scale;
    out.rapid_value = st.rapid_scale;
    out.max_velocity_value = st.max_velocity;
    out.tool_number = st.tool > 0 ? static_cast<unsigned>(st.tool) : 0;
    for (int a = 0; a < 9; ++a)
        out.tool_length_offset[a] = st.tool_offset[a];
    out.tool_diameter = st.tool_diameter;
}

void Core::simple_commands(const Inputs& in, const StatusView& st, std::vector<Command>& cmds)
{
    const Inputs& p = prev_;
    auto on = [&](bool now, bool before, const std::string& line) {
        if (rise(now, before))
            cmds.push_back({line});
    };
    // a program command needs an open program and AUTO mode (run switches to it)
    auto program = [&](bool now, bool before, const char* what, const std::string& line) {
        if (!rise(now, before))
            return;
        if (st.file.empty()) {
            notes_.push_back(std::string("program.") + what + ": no program is open");
            return;
        }
        if (st.mode != "AUTO")
            cmds.push_back({"MODE AUTO"});
        cmds.push_back({line});
    };
    on(in.estop_activate, p.estop_activate, "STATE ESTOP");
    on(in.estop_reset, p.estop_reset, "STATE ESTOP_RESET");
    on(in.machine_off, p.machine_off, "STATE OFF");
    on(in.machine_on, p.machine_on, "STATE ON");
    on(in.abort, p.abort, "ABORT");
    on(in.program_stop, p.program_stop, "ABORT");
    on(in.mode_manual, p.mode_manual, "MODE MANUAL");
    on(in.mode_auto, p.mode_auto, "MODE AUTO");
    on(in.mode_mdi, p.mode_mdi, "MODE MDI");
    on(in.mode_teleop, p.mode_teleop, "TELEOP 1");
    on(in.mode_joint, p.mode_joint, "TELEOP 0");
    on(in.mist_on, p.mist_on, "MIST ON");
    on(in.mist_off, p.mist_off, "MIST OFF");
    on(in.flood_on, p.flood_on, "FLOOD ON");
    on(in.flood_off, p.flood_off, "FLOOD OFF");
    on(in.lube_on, p.lube_on, "LUBE ON");
    on(in.lube_off, p.lube_off, "LUBE OFF");
    program(in.program_run, p.program_run, "run", "RUN");
    on(in.program_pause, p.program_pause, "PAUSE");
    on(in.program_resume, p.program_resume, "RESUME");
    program(in.program_step, p.program_step, "step", "STEP");
    on(in.optional_stop_on, p.optional_stop_on, "OPTIONAL_STOP 1");
    on(in.optional_stop_off, p.optional_stop_off, "OPTIONAL_STOP 0");
    on(in.block_delete_on, p.block_delete_on, "BLOCK_DELETE 1");
    on(in.block_delete_off, p.block_delete_off, "BLOCK_DELETE 0");
    on(in.home_all, p.home_all, "HOME -1");
    for (size_t j = 0; j < in.joint.size(); ++j) {
        on(in.joint[j].home, p.joint[j].home, "HOME " + std::to_string(j));
        on(in.joint[j].unhome, p.joint[j].unhome, "UNHOME " + std::to_string(j));
    }
    on(in.joint_selected.home, p.joint_selected.home, "HOME " + std::to_string(joint_selected_));
    on(in.joint_selected.unhome, p.joint_selected.unhome, "UNHOME " + std::to_string(joint_selected_));
}

void Core::jog_one(const std::string& target, const JogIn& cur, const JogIn& prev, double speed, bool speed_changed,
                   double deadband, JogState* analog, std::vector<Command>& cmds)
{
    auto cont = [&](double v) { cmds.push_back({"JOG_CONT " + target + " " + num(v)}); };
    auto stop = [&] { cmds.push_back({"JOG_STOP " + target}); };
    if (rise(cur.plus, prev.plus))
        cont(speed);
    else if (rise(cur.minus, prev.minus))
        cont(-speed);
    else if ((fall(cur.plus, prev.plus) && !cur.minus) || (fall(cur.minus, prev.minus) && !cur.plus))
        stop();
    else if (speed_changed && cur.plus != cur.minus)
        cont(cur.plus ? speed : -speed);   // held: the new speed applies at once
    if (analog && (cur.analog != prev.analog || speed_changed)) {
        if (std::fabs(cur.analog) > deadband) {
            cont(speed * cur.analog);
            analog->analog_jogging = true;
        } else if (analog->analog_jogging) {
            stop();
            analog->analog_jogging = false;
        }
    }
    // the direction goes with the distance (a speed of 0 has no sign to carry it)
    if (rise(cur.increment_plus, prev.increment_plus))
        cmds.push_back({"JOG_INCR " + target + " " + num(speed) + " " + num(std::fabs(cur.increment))});
    if (rise(cur.increment_minus, prev.increment_minus))
        cmds.push_back({"JOG_INCR " + target + " " + num(speed) + " " + num(-std::fabs(cur.increment))});
}

void Core::jogs(const Inputs& in, std::vector<Command>& cmds)
{
    const Inputs& p = prev_;
    const double jv = in.joint_jog_speed / 60.0, av = in.axis_jog_speed / 60.0;   // per minute -> per second
    const bool jchg = in.joint_jog_speed != p.joint_jog_speed, achg = in.axis_jog_speed != p.axis_jog_speed;

    // selection; a jog of the selected one that is held moves over to the new one
    auto select = [&](const std::vector<JogIn>& now, const std::vector<JogIn>& before, size_t& sel,
                      const JogIn& held, double v, auto name) {
        size_t want = sel;
        for (size_t k = 0; k < now.size(); ++k)
            if (rise(now[k].select, before[k].select))
                want = k;
        if (want == sel)
            return;
        if (held.plus != held.minus) {
            cmds.push_back({"JOG_STOP " + name(sel)});
            cmds.push_back({"JOG_CONT " + name(want) + " " + num(held.plus ? v : -v)});
        }
        sel = want;
    };
    auto joint_name = [](size_t j) { return std::to_string(j); };
    auto axis_name = [this](size_t k) { return std::string(1, ini::axis_lower(cfg_.axes[k])); };
    size_t jsel = joint_selected_;
    select(in.joint, p.joint, jsel, in.joint_selected, jv, joint_name);
    joint_selected_ = static_cast<unsigned>(jsel);
    select(in.axis, p.axis, axis_selected_, in.axis_selected, av, axis_name);

    for (size_t j = 0; j < in.joint.size(); ++j)
        jog_one(joint_name(j), in.joint[j], p.joint[j], jv, jchg, in.joint_jog_deadband, &joint_jog_[j], cmds);
    jog_one(joint_name(joint_selected_), in.joint_selected, p.joint_selected, jv, jchg, 0, nullptr, cmds);
    for (size_t k = 0; k < in.axis.size(); ++k)
        jog_one(axis_name(k), in.axis[k], p.axis[k], av, achg, in.axis_jog_deadband, &axis_jog_[k], cmds);
    if (!in.axis.empty())
        jog_one(axis_name(axis_selected_), in.axis_selected, p.axis_selected, av, achg, 0, nullptr, cmds);
}

void Core::spindles(const Inputs& in, const StatusView& st, double now_s, std::vector<Command>& cmds)
{
    for (size_t s = 0; s < in.spindle.size(); ++s) {
        const SpindleIn& c = in.spindle[s];
        const SpindleIn& p = prev_.spindle[s];
        const std::string n = std::to_string(s);
        const SpindleStatus& sp = st.spindles[s];
        // the active S word (spindle 0: the interpreter's, else motion's); 0: task uses 500 rpm
        double rpm = std::fabs(s == 0 ? st.spindle_speed : sp.speed);
        if (rise(c.start, p.start) || rise(c.forward, p.forward))
            cmds.push_back({"SPINDLE FORWARD " + num(rpm) + " " + n});
        if (rise(c.reverse, p.reverse))
            cmds.push_back({"SPINDLE REVERSE " + num(rpm) + " " + n});
        if (rise(c.stop, p.stop))
            cmds.push_back({"SPINDLE OFF 0 " + n});
        if (rise(c.increase, p.increase))
            cmds.push_back({"SPINDLE INCREASE 0 " + n});
        if (rise(c.decrease, p.decrease))
            cmds.push_back({"SPINDLE DECREASE 0 " + n});
        if (fall(c.increase, p.increase) || fall(c.decrease, p.decrease))
            cmds.push_back({"SPINDLE CONSTANT 0 " + n});
        if (rise(c.brake_on, p.brake_on))
            cmds.push_back({"BRAKE ON " + n});
        if (rise(c.brake_off, p.brake_off))
            cmds.push_back({"BRAKE OFF " + n});
        if (auto v = spindle_override_[s].update(c.override_, sp.scale, now_s))
            cmds.push_back({"SPINDLE_OVERRIDE " + num(*v) + " " + n});
    }
}

void Core::overrides(const Inputs& in, const StatusView& st, double now_s, std::vector<Command>& cmds)
{
    if (auto v = feed_.update(in.feed, st.feed_scale, now_s))
        cmds.push_back({"FEED_OVERRIDE " + num(*v)});
    if (auto v = rapid_.update(in.rapid, st.rapid_scale, now_s))
        cmds.push_back({"RAPID_OVERRIDE " + num(*v)});
    if (auto v = max_velocity_.update(in.max_velocity, st.max_velocity, now_s))
        cmds.push_back({"MAX_VELOCITY " + num(*v)});
}

void Core::mdi_commands(const Inputs& in, const StatusView&, std::vector<Command>& cmds)
{
    for (size_t k = 0; k < in.mdi.size(); ++k)
        if (rise(in.mdi[k].run, prev_.mdi[k].run))
            mdi_queue_.push_back(k);
    if (mdi_step_ == MdiStep::Idle && !mdi_queue_.empty())
        mdi_advance(cmds);
}

// The next step of the sequence: MODE MDI for the next queued command, or, when the
// queue is empty, back to the mode of before.
void Core::mdi_advance(std::vector<Command>& cmds)
{
    if (mdi_queue_.empty()) {
        std::string back = mdi_saved_mode_;
        mdi_saved_mode_.clear();
        if (back == "MANUAL" || back == "AUTO") {
            cmds.push_back({"MODE " + back, TAG_MDI_RESTORE});
            mdi_step_ = MdiStep::WaitRestore;
        } else {
            mdi_step_ = MdiStep::Idle;
        }
        return;
    }
    if (mdi_saved_mode_.empty())
        mdi_saved_mode_ = mode_now_;
    cmds.push_back({"MODE MDI", TAG_MDI_MODE});
    mdi_step_ = MdiStep::WaitMode;
}

void Core::on_result(int tag, bool ok)
{
    if (mdi_step_ == MdiStep::WaitMode && tag == TAG_MDI_MODE) {
        size_t k = mdi_queue_.front();
        if (ok) {
            pending_.push_back({"MDI " + cfg_.mdi[k], TAG_MDI_LINE});
            mdi_step_ = MdiStep::WaitMdi;
            return;
        }
        notes_.push_back("mdi-command-" + two_digits(k) + ": not sent (task did not switch to MDI mode)");
        mdi_queue_.erase(mdi_queue_.begin());
        mdi_advance(pending_);
    } else if (mdi_step_ == MdiStep::WaitMdi && tag == TAG_MDI_LINE) {
        mdi_queue_.erase(mdi_queue_.begin());
        mdi_advance(pending_);
    } else if (mdi_step_ == MdiStep::WaitRestore && tag == TAG_MDI_RESTORE) {
        mdi_step_ = MdiStep::Idle;
        if (!mdi_queue_.empty())
            mdi_advance(pending_);
    }
}

std::vector<std::string> Core::take_notes()
{
    std::vector<std::string> out = std::move(notes_);
    notes_.clear();
    return out;
}

}  // namespace hal::halui
