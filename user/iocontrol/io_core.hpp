// SPDX-License-Identifier: GPL-2.0-or-later
// io_core.hpp - iocontrol's logic without HAL or sockets (emcrsh-and-halui.md 2.3,
// 2.4): the pin values as a plain struct, one cycle() per CYCLE_TIME, commands from
// task, the tool data (index 0 = spindle) for random and non-random changers.
#pragma once

#include <string>
#include <vector>

#include "tooltable.hpp"

namespace hal::io {

// iocontrol.0.* pin values (names in io_main.cpp).
struct IoPins {
    bool user_enable_out = false;      // OUT
    bool user_request_enable = false;  // OUT
    bool emc_enable_in = false;        // IN
    bool coolant_mist = false;         // OUT
    bool coolant_flood = false;        // OUT
    bool lube = false;                 // OUT
    bool lube_level = false;           // IN
    bool tool_prepare = false;         // OUT
    bool tool_prepared = false;        // IN
    bool tool_change = false;          // OUT
    bool tool_changed = false;         // IN
    int tool_prep_number = 0;          // OUT
    int tool_prep_pocket = 0;          // OUT
    int tool_prep_index = 0;           // OUT
    int tool_number = 0;               // OUT
    int tool_from_pocket = 0;          // OUT
};

class IoCore {
public:
    enum class Outcome { Done, Pending, Failed };

    IoCore(std::string tool_table, bool random_changer);

    // (Re)reads the tool table (path empty: the configured one) and places the tool
    // in the spindle again.
    Result<void> load_table(const std::string& path = "");
    // One cycle: inputs read, handshakes checked; true when the pending command
    // completed in this cycle (its serial: pending_serial() before the call).
    bool cycle(IoPins& p);
    // The end of the cycle: user-request-enable back to FALSE; the outputs of the
    // commands handled so far are written, so the next inputs may show their effect.
    void end_cycle(IoPins& p);
    // Task's command <serial> was carried out (or started). IOSTAT reports `ack=`: the
    // last command whose outputs were written before the inputs it shows were read, so
    // task can tell a report that predates its ESTOP_OFF from one that follows it.
    void command_handled(long serial) { if (serial > handled_) handled_ = serial; }
    // A new link to task: its serial numbers start again.
    void reset_serials() { handled_ = inputs_after_ = 0; }

    // A command from task (IOCMD). Pending: completes in a later cycle().
    Outcome command(const std::vector<std::string>& words, IoPins& p, std::string& error);
    long pending_serial() const { return pending_serial_; }
    void set_pending_serial(long s) { pending_serial_ = s; }
    bool has_pending() const { return pending_ != Pending::None; }
    // The command that was pending is cancelled (ABORT, ESTOP_ON).
    long take_cancelled() { long s = cancelled_; cancelled_ = 0; return s; }

    // status for task (IOSTAT): "estop=0 tool=1 ..." and the table lines (IOTOOLS).
    std::string status_line(const IoPins& p) const;
    std::vector<std::string> table_lines() const;
    const std::vector<Tool>& tools() const { return tools_; }
    int pocket_prepped() const { return pocket_prepped_; }

private:
    enum class Pending { None, Prepare, Change };
    int find_index(int toolno) const;
    std::vector<Tool> table_in_file_order() const;
    Result<void> save();
    void cancel_pending();

    std::string path_;
    bool random_;
    std::vector<Tool> tools_;      // [0] = spindle; non-random: 1..n file order; random: index = pocket
    int pocket_prepped_ = -1;      // index prepared, -1 none
    int tool_in_spindle_ = 0;
    Pending pending_ = Pending::None;
    long pending_serial_ = 0;
    long cancelled_ = 0;
    long handled_ = 0;             // last command serial handled
    long inputs_after_ = 0;        // handled_ when the current inputs were read (IOSTAT ack=)
};

}  // namespace hal::io
