// SPDX-License-Identifier: GPL-2.0-or-later
// The estop reports between iocontrol and task (user/task/io_estop.hpp): io's core
// runs cycle by cycle as io_main.cpp's loop does, with user-enable-out looped back to
// emc-enable-in through a net; messages travel in queues, delivered when the test says.
#include <gtest/gtest.h>

#include <deque>

#include "io_core.hpp"
#include "io_estop.hpp"

using hal::io::IoCore;
using hal::io::IoPins;
using hal::task::IoEstop;
using hal::task::parse_iostat;

namespace {

struct Machine {
    IoCore core{"", false};
    IoPins pins;
    bool net = false;   // the estop-loop signal: user-enable-out -> emc-enable-in
    bool chain_ok = true;   // an external chain in series (false: open)
    bool held = false;      // emc-enable-in held TRUE (setp, no loop)
    std::deque<std::pair<long, std::vector<std::string>>> to_io;
    std::deque<std::string> to_task;
    std::string last_status;

    // one io cycle: end of the previous one, inputs, commands, status, outputs
    void io_cycle()
    {
        core.end_cycle(pins);
        pins.emc_enable_in = held || (net && chain_ok);
        core.cycle(pins);
        while (!to_io.empty()) {
            auto [serial, words] = to_io.front();
            to_io.pop_front();
            core.command_handled(serial);
            std::string err;
            core.command(words, pins, err);
        }
        status();
        net = pins.user_enable_out;
    }
    void status()
    {
        std::string st = core.status_line(pins);
        if (st != last_status)
            to_task.push_back(st);
        last_status = st;
    }
    // a new link: io numbers from 0 again and reports at once (io_main.cpp reconnect)
    void link()
    {
        core.reset_serials();
        last_status.clear();
        status();
    }
};

struct TaskSide {
    IoEstop io;
    long serial = 0;
    std::vector<int> raw;   // every estop= io sent, in order
    int rising = 0;         // estop edges task sees (each is an "emergency stop")

    long send(Machine& m, std::vector<std::string> words)
    {
        long n = ++serial;
        if (words[0] == "ESTOP_ON" || words[0] == "ESTOP_OFF")
            io.sent(n, words[0] == "ESTOP_ON");
        m.to_io.push_back({n, std::move(words)});
        return n;
    }
    void deliver(Machine& m)
    {
        while (!m.to_task.empty()) {
            auto kv = parse_iostat(m.to_task.front());
            m.to_task.pop_front();
            bool before = io.estop();
            raw.push_back(static_cast<int>(kv.at("estop")));
            io.report(kv.at("estop") != 0, kv.count("ack") ? kv.at("ack") : 0);
            if (io.estop() && !before)
                ++rising;
        }
    }
    bool reset_done() const { return io.settled() && !io.estop(); }
    // io connects, task sends ESTOP_OFF, `cycles` io cycles each followed by delivery
    void connect_and_reset(Machine& m, int cycles)
    {
        m.link();
        io.connected();
        send(m, {"ESTOP_OFF"});
        for (int k = 0; k < cycles; ++k) {
            m.io_cycle();
            deliver(m);
        }
    }
};

// io has the machine enabled (a task ran it and stopped); returns once settled
void enabled_by_old_task(Machine& m)
{
    m.to_io.push_back({57, {"ESTOP_OFF"}});
    m.io_cycle();
    m.io_cycle();
    m.to_task.clear();
    ASSERT_TRUE(m.net);
}

}  // namespace

TEST(IoEstop, ParseIostat)
{
    auto kv = parse_iostat(" estop=1 tool=3 junk ack=12 bad=x empty=");
    EXPECT_EQ(kv.size(), 3u);
    EXPECT_EQ(kv["estop"], 1);
    EXPECT_EQ(kv["tool"], 3);
    EXPECT_EQ(kv["ack"], 12);
}

// The race once seen in tests/task: a restarted task meets an io that still has
// user-enable-out TRUE; task sends ESTOP_ON on connect and the test's ESTOP_RESET
// follows at once. io's reports: estop=0 (from before ESTOP_ON), estop=1 (read before
// ESTOP_OFF reached HAL), estop=0. Taken at face value the reset looked done at the
// first and the second was an external estop after the machine was turned on.
TEST(IoEstop, RestartedTaskResetIgnoresReportsFromBeforeItsCommands)
{
    Machine m;
    enabled_by_old_task(m);
    TaskSide t;
    m.link();
    t.io.connected();
    t.send(m, {"INIT"});
    t.send(m, {"ESTOP_ON"});
    t.deliver(m);
    EXPECT_TRUE(t.io.estop()) << "the report io sends on connect predates ESTOP_ON";
    m.io_cycle();   // INIT, ESTOP_ON handled; status still shows the old input
    t.deliver(m);
    EXPECT_TRUE(t.io.estop());
    // ESTOP_RESET: task's set_state(ESTOP_RESET)
    t.send(m, {"ESTOP_OFF"});
    t.send(m, {"LUBE", "0"});
    t.send(m, {"ABORT"});
    t.deliver(m);
    EXPECT_FALSE(t.reset_done()) << "no report yet follows the ESTOP_OFF";
    m.io_cycle();   // reads the input ESTOP_ON dropped, then handles ESTOP_OFF
    t.deliver(m);
    EXPECT_FALSE(t.reset_done());
    m.io_cycle();   // reads the input ESTOP_OFF raised
    t.deliver(m);
    EXPECT_TRUE(t.reset_done());
    for (int k = 0; k < 5; ++k) {   // machine on, time passes: nothing more arrives
        m.io_cycle();
        t.deliver(m);
    }
    EXPECT_FALSE(t.io.estop());
    EXPECT_EQ(t.rising, 0);
    // the sequence io sent is the one that used to trip task
    std::vector<int> want = {0, 0, 1, 0};
    EXPECT_EQ(t.raw, want);
}

// The same interleaving on a running task: STATE ESTOP then STATE ESTOP_RESET before
// io's estop=1 came back.
TEST(IoEstop, QuickEstopAndResetEndsReset)
{
    Machine m;
    TaskSide t;
    m.link();
    t.io.connected();
    t.send(m, {"INIT"});
    t.send(m, {"ESTOP_OFF"});
    for (int k = 0; k < 3; ++k) {
        m.io_cycle();
        t.deliver(m);
    }
    ASSERT_TRUE(t.reset_done());
    t.send(m, {"ESTOP_ON"});
    t.send(m, {"ESTOP_OFF"});
    t.deliver(m);
    EXPECT_FALSE(t.reset_done());
    m.io_cycle();   // both handled in one cycle: the output never drops
    t.deliver(m);
    EXPECT_FALSE(t.reset_done()) << "the status of that cycle shows inputs read before the commands";
    m.io_cycle();
    t.deliver(m);
    EXPECT_TRUE(t.reset_done());
    EXPECT_EQ(t.rising, 0);
}

TEST(IoEstop, ExternalChainOpeningIsAnEdge)
{
    Machine m;
    TaskSide t;
    t.connect_and_reset(m, 2);
    ASSERT_TRUE(t.reset_done());
    m.chain_ok = false;
    m.io_cycle();
    t.deliver(m);
    EXPECT_TRUE(t.io.estop());
    EXPECT_EQ(t.rising, 1);
}

TEST(IoEstop, ResetWithTheChainOpenNeverCompletes)
{
    Machine m;
    m.chain_ok = false;
    TaskSide t;
    t.connect_and_reset(m, 5);
    EXPECT_TRUE(t.io.settled());
    EXPECT_TRUE(t.io.estop());
    EXPECT_FALSE(t.reset_done());
}

TEST(IoEstop, DisconnectIsEstopAndANewLinkStartsOver)
{
    Machine m;
    TaskSide t;
    t.connect_and_reset(m, 2);
    ASSERT_FALSE(t.io.estop());
    t.io.disconnected();
    EXPECT_TRUE(t.io.estop());
    EXPECT_FALSE(t.io.settled());
    // io reconnects still enabled: its first report is from before task's commands
    m.link();
    t.io.connected();
    t.send(m, {"INIT"});
    t.send(m, {"ESTOP_OFF"});
    t.deliver(m);
    EXPECT_TRUE(t.io.estop());
    m.io_cycle();
    m.io_cycle();
    t.deliver(m);
    EXPECT_TRUE(t.reset_done());
}

// STATE ESTOP latches task's estop when it sends ESTOP_ON, before io reports, and
// keeps it when io's input says otherwise (emc-enable-in held TRUE), until ESTOP_OFF.
TEST(IoEstop, EstopOnLatchesUntilEstopOff)
{
    Machine m;
    m.held = true;
    TaskSide t;
    t.connect_and_reset(m, 2);
    ASSERT_TRUE(t.reset_done());
    t.send(m, {"ESTOP_ON"});
    EXPECT_TRUE(t.io.estop()) << "at once, before any report";
    for (int k = 0; k < 3; ++k) {
        m.io_cycle();
        t.deliver(m);
    }
    EXPECT_EQ(t.raw.back(), 0) << "io's input stays TRUE";
    EXPECT_TRUE(t.io.estop());
    t.send(m, {"ESTOP_OFF"});
    for (int k = 0; k < 2; ++k) {   // handled, then a report that follows it
        m.io_cycle();
        t.deliver(m);
    }
    EXPECT_TRUE(t.reset_done());
}
