// halui's pin logic (user/halui/halui_core.cpp): edges -> bus commands, jogs, the
// selected joint/axis, spindles, overrides, the MDI_COMMAND sequence, OUT values.
#include <gtest/gtest.h>

#include "halui_core.hpp"

using namespace hal::halui;

namespace {

Config mill()
{
    Config c;
    c.joints = 3;
    c.axes = {0, 1, 2};
    c.spindles = 1;
    c.max_feed_override = 1.5;
    c.max_velocity = 100;
    c.mdi = {"G0 X1", "G0 Y2"};
    return c;
}

std::vector<std::string> lines(const std::vector<Command>& cmds)
{
    std::vector<std::string> out;
    for (const Command& c : cmds)
        out.push_back(c.line);
    return out;
}

using Lines = std::vector<std::string>;

// A core with a status and a clock: each step() is one 20 ms cycle.
struct Rig {
    Core core{mill()};
    Inputs in = core.make_inputs();
    Outputs out = core.make_outputs();
    StatusView st;
    double t = 0;
    std::vector<Command> last;

    Rig()
    {
        st.joints.resize(3);
        st.spindles.resize(1);
        step();
    }
    Lines step()
    {
        t += 0.02;
        last = core.cycle(in, &st, t, out);
        return lines(last);
    }
};

}  // namespace

TEST(HaluiCore, LevelsAtStartAreNotEdges)
{
    Core core(mill());
    Inputs in = core.make_inputs();
    Outputs out = core.make_outputs();
    StatusView st;
    st.joints.resize(3);
    st.spindles.resize(1);
    in.machine_on = true;
    in.joint[0].plus = true;
    EXPECT_TRUE(core.cycle(in, &st, 0, out).empty());
    EXPECT_TRUE(core.cycle(in, &st, 0.02, out).empty());
}

TEST(HaluiCore, RisingEdgesSendOnce)
{
    Rig r;
    r.in.estop_reset = true;
    EXPECT_EQ(r.step(), Lines{"STATE ESTOP_RESET"});
    EXPECT_EQ(r.step(), Lines{});   // held
    r.in.estop_reset = false;
    r.in.machine_on = true;
    r.in.mist_on = true;
    r.in.optional_stop_on = true;
    EXPECT_EQ(r.step(), (Lines{"STATE ON", "MIST ON", "OPTIONAL_STOP 1"}));
    r.in.machine_on = false;
    EXPECT_EQ(r.step(), Lines{});   // falling edge: nothing
    r.in.mode_teleop = true;
    r.in.home_all = true;
    r.in.abort = true;
    EXPECT_EQ(r.step(), (Lines{"ABORT", "TELEOP 1", "HOME -1"}));
    r.in.joint[2].unhome = true;
    r.in.joint_selected.home = true;
    EXPECT_EQ(r.step(), (Lines{"UNHOME 2", "HOME 0"}));
}

TEST(HaluiCore, NoStatusNothingSentAndNoEdgeLater)
{
    Rig r;
    r.in.machine_on = true;
    EXPECT_TRUE(r.core.cycle(r.in, nullptr, 1, r.out).empty());
    EXPECT_EQ(r.step(), Lines{});   // the edge happened while task was away
}

TEST(HaluiCore, ProgramRunNeedsAProgramAndSwitchesToAuto)
{
    Rig r;
    r.in.program_run = true;
    EXPECT_EQ(r.step(), Lines{});
    EXPECT_EQ(r.core.take_notes(), Lines{"program.run: no program is open"});
    r.in.program_run = false;
    r.step();
    r.st.file = "/p.ngc";
    r.in.program_run = true;
    EXPECT_EQ(r.step(), (Lines{"MODE AUTO", "RUN"}));
    r.st.mode = "AUTO";
    r.in.program_pause = true;
    r.in.program_step = true;
    EXPECT_EQ(r.step(), (Lines{"PAUSE", "STEP"}));
    r.in.program_resume = true;
    r.in.program_stop = true;
    EXPECT_EQ(r.step(), (Lines{"ABORT", "RESUME"}));
}

TEST(HaluiCore, ContinuousJogPlusMinusAndSpeedChange)
{
    Rig r;
    r.in.joint_jog_speed = 600;   // units per minute
    r.step();
    r.in.joint[1].plus = true;
    EXPECT_EQ(r.step(), Lines{"JOG_CONT 1 10"});
    EXPECT_EQ(r.step(), Lines{});
    r.in.joint_jog_speed = 1200;   // held: restarted at the new speed
    EXPECT_EQ(r.step(), Lines{"JOG_CONT 1 20"});
    r.in.joint[1].plus = false;
    EXPECT_EQ(r.step(), Lines{"JOG_STOP 1"});
    r.in.joint[1].minus = true;
    EXPECT_EQ(r.step(), Lines{"JOG_CONT 1 -20"});
    r.in.joint[1].minus = false;
    EXPECT_EQ(r.step(), Lines{"JOG_STOP 1"});
    r.in.axis_jog_speed = 60;
    r.in.axis[2].minus = true;
    EXPECT_EQ(r.step(), Lines{"JOG_CONT z -1"});
}

TEST(HaluiCore, AnalogJogDeadband)
{
    Rig r;
    r.in.joint_jog_speed = 60;
    r.step();
    r.in.joint[0].analog = 0.1;   // inside the 0.2 deadband
    EXPECT_EQ(r.step(), Lines{});
    r.in.joint[0].analog = 0.5;
    EXPECT_EQ(r.step(), Lines{"JOG_CONT 0 0.5"});
    r.in.joint[0].analog = -1;
    EXPECT_EQ(r.step(), Lines{"JOG_CONT 0 -1"});
    r.in.joint[0].analog = 0.05;
    EXPECT_EQ(r.step(), Lines{"JOG_STOP 0"});
    r.in.joint[0].analog = 0.0;
    EXPECT_EQ(r.step(), Lines{});   // already stopped
}

TEST(HaluiCore, IncrementalJogs)
{
    Rig r;
    r.in.axis_jog_speed = 120;
    r.in.axis[0].increment = 0.5;
    r.step();
    r.in.axis[0].increment_plus = true;
    EXPECT_EQ(r.step(), Lines{"JOG_INCR x 2 0.5"});
    r.in.axis[0].increment_plus = false;
    r.in.axis[0].increment_minus = true;
    EXPECT_EQ(r.step(), Lines{"JOG_INCR x 2 -0.5"});
}

TEST(HaluiCore, SelectedJointAndTransferOfAHeldJog)
{
    Rig r;
    r.in.joint_jog_speed = 60;
    r.step();
    EXPECT_EQ(r.out.joint_selected_index, 0u);
    EXPECT_TRUE(r.out.joint[0].is_selected);
    r.in.joint[2].select = true;
    r.step();
    EXPECT_EQ(r.out.joint_selected_index, 2u);
    EXPECT_TRUE(r.out.joint[2].is_selected);
    EXPECT_FALSE(r.out.joint[0].is_selected);
    r.in.joint_selected.plus = true;
    EXPECT_EQ(r.step(), Lines{"JOG_CONT 2 1"});
    r.in.joint[1].select = true;   // the held jog moves to joint 1
    EXPECT_EQ(r.step(), (Lines{"JOG_STOP 2", "JOG_CONT 1 1"}));
    r.in.joint_selected.plus = false;
    EXPECT_EQ(r.step(), Lines{"JOG_STOP 1"});
    r.in.axis[1].select = true;
    r.step();
    EXPECT_EQ(r.out.axis_selected_index, 1u);
    r.in.axis_selected.increment = 1;
    r.in.axis_selected.increment_minus = true;
    EXPECT_EQ(r.step(), Lines{"JOG_INCR y 0 -1"});
}

TEST(HaluiCore, SpindleCommandsNameTheSpindle)
{
    Rig r;
    r.st.spindle_speed = 1200;
    r.in.spindle[0].forward = true;
    EXPECT_EQ(r.step(), Lines{"SPINDLE FORWARD 1200 0"});
    r.in.spindle[0].increase = true;
    EXPECT_EQ(r.step(), Lines{"SPINDLE INCREASE 0 0"});
    r.in.spindle[0].increase = false;
    EXPECT_EQ(r.step(), Lines{"SPINDLE CONSTANT 0 0"});
    r.in.spindle[0].stop = true;
    r.in.spindle[0].brake_on = true;
    EXPECT_EQ(r.step(), (Lines{"SPINDLE OFF 0 0", "BRAKE ON 0"}));
    r.in.spindle[0].override_.increase = true;
    r.st.spindles[0].scale = 0.5;
    EXPECT_EQ(r.step(), Lines{"SPINDLE_OVERRIDE 0.6 0"});
    r.in.spindle[0].override_.counts = 10;   // clamped at MAX_SPINDLE_OVERRIDE 1.0
    EXPECT_EQ(r.step(), Lines{"SPINDLE_OVERRIDE 1 0"});
}

TEST(HaluiCore, OverrideKnobsAndClamps)
{
    Rig r;
    r.in.feed.counts = 10;
    EXPECT_EQ(r.step(), Lines{"FEED_OVERRIDE 1.5"});   // 1 + 10 x 0.1, clamped to 1.5
    r.in.rapid.decrease = true;
    EXPECT_EQ(r.step(), Lines{"RAPID_OVERRIDE 0.9"});
    r.in.max_velocity.direct_value = true;
    r.in.max_velocity.scale = 1;
    r.in.max_velocity.counts = 250;
    EXPECT_EQ(r.step(), Lines{"MAX_VELOCITY 100"});
}

TEST(HaluiCore, MdiCommandSequenceRestoresTheMode)
{
    Rig r;
    r.st.mode = "MANUAL";
    r.in.mdi[0].run = true;
    r.in.mdi[1].run = true;
    auto c = r.step();
    EXPECT_EQ(c, Lines{"MODE MDI"});
    EXPECT_EQ(r.last[0].tag, TAG_MDI_MODE);
    EXPECT_TRUE(r.core.mdi_busy());
    r.st.mode = "MDI";
    EXPECT_EQ(r.step(), Lines{});   // waits for the mode's DONE
    r.core.on_result(TAG_MDI_MODE, true);
    EXPECT_EQ(r.step(), Lines{"MDI G0 X1"});
    r.core.on_result(TAG_MDI_LINE, true);
    EXPECT_EQ(r.step(), Lines{"MODE MDI"});   // the second one, mode recorded once
    r.core.on_result(TAG_MDI_MODE, true);
    EXPECT_EQ(r.step(), Lines{"MDI G0 Y2"});
    r.core.on_result(TAG_MDI_LINE, false);   // an error does not stop the sequence
    EXPECT_EQ(r.step(), Lines{"MODE MANUAL"});
    EXPECT_EQ(r.last[0].tag, TAG_MDI_RESTORE);
    r.core.on_result(TAG_MDI_RESTORE, true);
    r.st.mode = "MANUAL";
    r.step();
    EXPECT_FALSE(r.core.mdi_busy());
}

TEST(HaluiCore, MdiCommandNotSentWhenModeRefused)
{
    Rig r;
    r.st.mode = "AUTO";
    r.in.mdi[1].run = true;
    EXPECT_EQ(r.step(), Lines{"MODE MDI"});
    r.core.on_result(TAG_MDI_MODE, false);
    EXPECT_EQ(r.step(), Lines{"MODE AUTO"});
    EXPECT_EQ(r.core.take_notes(), Lines{"mdi-command-01: not sent (task did not switch to MDI mode)"});
    r.core.on_result(TAG_MDI_RESTORE, true);
    r.step();
    EXPECT_FALSE(r.core.mdi_busy());
}

TEST(HaluiCore, MdiModeStaysWhenStartedFromMdi)
{
    Rig r;
    r.st.mode = "MDI";
    r.in.mdi[0].run = true;
    EXPECT_EQ(r.step(), Lines{"MODE MDI"});
    r.core.on_result(TAG_MDI_MODE, true);
    EXPECT_EQ(r.step(), Lines{"MDI G0 X1"});
    r.core.on_result(TAG_MDI_LINE, true);
    EXPECT_EQ(r.step(), Lines{});
    EXPECT_FALSE(r.core.mdi_busy());
}

TEST(HaluiCore, OutputsFollowTheStatus)
{
    Rig r;
    r.st.state = "ON";
    r.st.mode = "AUTO";
    r.st.interp = "PAUSED";
    r.st.traj_mode = "TELEOP";
    r.st.flood = true;
    r.st.block_delete = true;
    r.st.units_per_mm = 0.03937;
    r.st.joints[1].homed = true;
    r.st.joints[1].fault = true;
    r.st.spindles[0] = {500, 0.9, 1, true, false};
    r.st.pos_cmd[1] = 4;
    r.st.pos_fb[1] = 4.5;
    r.st.feed_scale = 1.2;
    r.st.tool = 3;
    r.st.tool_offset[2] = 7;
    r.st.tool_diameter = 6;
    r.in.joint[1].select = true;
    r.step();
    const Outputs& o = r.out;
    EXPECT_TRUE(o.machine_is_on);
    EXPECT_FALSE(o.estop_is_activated);
    EXPECT_TRUE(o.is_auto);
    EXPECT_FALSE(o.is_manual);
    EXPECT_TRUE(o.is_teleop);
    EXPECT_FALSE(o.is_joint);
    EXPECT_TRUE(o.program_is_paused);
    EXPECT_FALSE(o.program_is_idle);
    EXPECT_TRUE(o.flood_is_on);
    EXPECT_TRUE(o.block_delete_is_on);
    EXPECT_DOUBLE_EQ(o.units_per_mm, 0.03937);
    EXPECT_TRUE(o.joint[1].is_homed);
    EXPECT_TRUE(o.joint_selected.is_homed);
    EXPECT_TRUE(o.joint_selected.has_fault);
    EXPECT_TRUE(o.spindle[0].is_on);
    EXPECT_TRUE(o.spindle[0].runs_forward);
    EXPECT_FALSE(o.spindle[0].runs_backward);
    EXPECT_DOUBLE_EQ(o.spindle[0].override_value, 0.9);
    EXPECT_DOUBLE_EQ(o.axis[1].pos_commanded, 4);
    EXPECT_DOUBLE_EQ(o.axis[1].pos_feedback, 4.5);
    EXPECT_DOUBLE_EQ(o.axis[1].pos_relative, 4.5);
    EXPECT_DOUBLE_EQ(o.feed_value, 1.2);
    EXPECT_EQ(o.tool_number, 3u);
    EXPECT_DOUBLE_EQ(o.tool_length_offset[2], 7);
    EXPECT_DOUBLE_EQ(o.tool_diameter, 6);
}
