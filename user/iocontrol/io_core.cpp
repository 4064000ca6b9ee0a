// SPDX-License-Identifier: GPL-2.0-or-later
// io_core.cpp - iocontrol's cycle, commands and tool data (see io_core.hpp).
#include "io_core.hpp"

#include <cmath>
#include <cstdlib>

namespace hal::io {

IoCore::IoCore(std::string tool_table, bool random_changer) : path_(std::move(tool_table)), random_(random_changer)
{
    tools_.resize(1);
}

int IoCore::find_index(int toolno) const
{
    // non-random: index 0 is the spindle's copy, look in the pockets (1..n) first
    for (size_t i = random_ ? 0 : 1; i < tools_.size(); ++i)
        if (tools_[i].toolno == toolno)
            return static_cast<int>(i);
    return -1;
}

std::vector<Tool> IoCore::table_in_file_order() const
{
    std::vector<Tool> out;
    for (size_t i = random_ ? 0 : 1; i < tools_.size(); ++i)
        if (tools_[i].toolno >= 0)
            out.push_back(tools_[i]);
    return out;
}

Result<void> IoCore::load_table(const std::string& path)
{
    if (!path.empty())
        path_ = path;
    if (path_.empty()) {
        tools_.assign(1, Tool{});
        return ok();
    }
    auto r = read_tool_file(path_);
    if (!r)
        return r.error();
    std::vector<Tool> t(1);
    if (random_) {
        for (const Tool& tool : *r) {
            if (static_cast<size_t>(tool.pocket) >= t.size())
                t.resize(tool.pocket + 1);
            if (t[tool.pocket].toolno >= 0)
                return Error{-1, path_ + ": pocket " + std::to_string(tool.pocket) + " holds two tools"};
            t[tool.pocket] = tool;
        }
        tools_ = std::move(t);
        tool_in_spindle_ = tools_[0].toolno >= 0 ? tools_[0].toolno : 0;
    } else {
        t.insert(t.end(), r->begin(), r->end());
        tools_ = std::move(t);
        // the tool in the spindle keeps its place if the new table still has it
        int idx = tool_in_spindle_ > 0 ? find_index(tool_in_spindle_) : -1;
        if (idx > 0) {
            tools_[0] = tools_[idx];
        } else {
            tools_[0] = Tool{};
            tool_in_spindle_ = 0;
        }
    }
    pocket_prepped_ = -1;
    return ok();
}

Result<void> IoCore::save()
{
    if (path_.empty())
        return ok();
    return write_tool_file(path_, table_in_file_order());
}

void IoCore::cancel_pending()
{
    if (pending_ != Pending::None)
        cancelled_ = pending_serial_;
    pending_ = Pending::None;
    pending_serial_ = 0;
}

bool IoCore::cycle(IoPins& p)
{
    if (pending_ == Pending::Prepare && p.tool_prepare && p.tool_prepared) {
        pocket_prepped_ = p.tool_prep_index;
        p.tool_prepare = false;
        pending_ = Pending::None;
        return true;
    }
    if (pending_ == Pending::Change && p.tool_change && p.tool_changed) {
        int idx = pocket_prepped_;
        if (random_) {
            // the tool from pocket idx goes to the spindle, the spindle's to pocket idx
            if (static_cast<size_t>(idx) < tools_.size()) {
                std::swap(tools_[0], tools_[idx]);
                if (tools_[0].toolno >= 0)
                    tools_[0].pocket = 0;
                if (tools_[idx].toolno >= 0)
                    tools_[idx].pocket = idx;
            }
            tool_in_spindle_ = tools_[0].toolno >= 0 ? tools_[0].toolno : 0;
            p.tool_from_pocket = idx;
            (void)save();   // a write failure shows up at the next table load
        } else if (idx <= 0 || static_cast<size_t>(idx) >= tools_.size()) {
            tools_[0] = Tool{};
            tool_in_spindle_ = 0;
            p.tool_from_pocket = 0;
        } else {
            tools_[0] = tools_[idx];
            tool_in_spindle_ = tools_[idx].toolno;
            p.tool_from_pocket = tools_[idx].pocket;
        }
        p.tool_number = tool_in_spindle_;
        pocket_prepped_ = -1;
        p.tool_prep_number = p.tool_prep_pocket = p.tool_prep_index = 0;
        p.tool_change = false;
        pending_ = Pending::None;
        return true;
    }
    return false;
}

void IoCore::end_cycle(IoPins& p)
{
    p.user_request_enable = false;
    inputs_after_ = handled_;
}

static bool on_arg(const std::vector<std::string>& w) { return w.size() > 1 && w[1] == "1"; }

static bool int_arg(const std::vector<std::string>& w, size_t i, int& v)
{
    if (i >= w.size())
        return false;
    char* end = nullptr;
    long l = std::strtol(w[i].c_str(), &end, 10);
    if (*end != '\0' || w[i].empty() || l < -2147483647L || l > 2147483647L)
        return false;
    v = static_cast<int>(l);
    return true;
}

static bool double_arg(const std::vector<std::string>& w, size_t i, double& v)
{
    if (i >= w.size())
        return false;
    char* end = nullptr;
    v = std::strtod(w[i].c_str(), &end);
    return *end == '\0' && !w[i].empty() && std::isfinite(v);
}

IoCore::Outcome IoCore::command(const std::vector<std::string>& w, IoPins& p, std::string& error)
{
    if (w.empty()) {
        error = "empty io command";
        return Outcome::Failed;
    }
    const std::string& v = w[0];
    if (v == "INIT") {
        cancel_pending();
        auto r = load_table();
        if (!r) {
            error = r.error().message;
            return Outcome::Failed;
        }
        p.tool_number = tool_in_spindle_;
        return Outcome::Done;
    }
    if (v == "ESTOP_ON") {
        cancel_pending();
        p.user_enable_out = p.user_request_enable = false;
        p.coolant_mist = p.coolant_flood = p.lube = false;
        p.tool_prepare = p.tool_change = false;
        p.tool_prep_number = p.tool_prep_pocket = p.tool_prep_index = 0;
        p.tool_from_pocket = 0;
        return Outcome::Done;
    }
    if (v == "ESTOP_OFF") {
        p.user_enable_out = true;
        p.user_request_enable = true;   // one cycle: end_cycle() clears it
        return Outcome::Done;
    }
    if (v == "MIST") {
        p.coolant_mist = on_arg(w);
        return Outcome::Done;
    }
    if (v == "FLOOD") {
        p.coolant_flood = on_arg(w);
        return Outcome::Done;
    }
    if (v == "LUBE") {
        p.lube = on_arg(w);
        return Outcome::Done;
    }
    if (v == "ABORT") {
        cancel_pending();
        p.coolant_mist = p.coolant_flood = false;
        p.tool_change = p.tool_prepare = false;
        return Outcome::Done;
    }
    if (v == "TOOL_PREPARE") {
        int toolno = 0;
        if (!int_arg(w, 1, toolno)) {
            error = "TOOL_PREPARE needs a tool number";
            return Outcome::Failed;
        }
        int idx = (!random_ && toolno == 0) ? 0 : find_index(toolno);
        if (random_ && idx == 0)
            return Outcome::Done;   // already in the spindle: nothing to fetch
        if (idx < 0) {
            pocket_prepped_ = -1;
        } else {
            p.tool_prep_index = idx;
            p.tool_prep_number = idx == 0 ? 0 : toolno;
            p.tool_prep_pocket = idx == 0 ? 0 : (random_ ? idx : tools_[idx].pocket);
        }
        p.tool_prepare = true;
        pending_ = Pending::Prepare;
        return Outcome::Pending;
    }
    if (v == "TOOL_LOAD") {
        if (pocket_prepped_ < 0)
            return Outcome::Done;   // nothing prepared
        if (random_ && pocket_prepped_ == 0)
            return Outcome::Done;
        if (!random_ && pocket_prepped_ > 0 && static_cast<size_t>(pocket_prepped_) < tools_.size() &&
            tools_[pocket_prepped_].toolno == tool_in_spindle_ && tool_in_spindle_ > 0)
            return Outcome::Done;   // the prepared tool is already in the spindle
        p.tool_change = true;
        pending_ = Pending::Change;
        return Outcome::Pending;
    }
    if (v == "TOOL_UNLOAD") {
        tools_[0] = Tool{};
        tool_in_spindle_ = 0;
        p.tool_number = 0;
        return Outcome::Done;
    }
    if (v == "TOOL_SET_NUMBER") {
        int toolno = 0;
        if (!int_arg(w, 1, toolno) || toolno < 0) {
            error = "TOOL_SET_NUMBER needs a tool number";
            return Outcome::Failed;
        }
        int idx = toolno == 0 ? -1 : find_index(toolno);
        if (toolno != 0 && idx < 0) {
            error = "tool " + std::to_string(toolno) + " is not in the tool table";
            return Outcome::Failed;
        }
        if (toolno == 0) {
            tools_[0] = Tool{};
            p.tool_from_pocket = 0;
        } else if (random_ && idx != 0) {
            std::swap(tools_[0], tools_[idx]);
            tools_[0].pocket = 0;
            if (tools_[idx].toolno >= 0)
                tools_[idx].pocket = idx;
            (void)save();
        } else if (!random_) {
            tools_[0] = tools_[idx];
        }
        tool_in_spindle_ = toolno;
        p.tool_number = toolno;
        return Outcome::Done;
    }
    if (v == "TOOL_SET_OFFSET") {
        // TOOL POCKET X Y Z A B C U V W DIAMETER FRONTANGLE BACKANGLE ORIENTATION
        Tool t;
        bool good = w.size() == 16 && int_arg(w, 1, t.toolno) && int_arg(w, 2, t.pocket) && t.toolno >= 0 &&
                    t.pocket >= 0 && t.pocket < POCKETS_MAX;
        for (int k = 0; good && k < 9; ++k)
            good = double_arg(w, 3 + k, t.offset[k]);
        good = good && double_arg(w, 12, t.diameter) && double_arg(w, 13, t.frontangle) &&
               double_arg(w, 14, t.backangle) && int_arg(w, 15, t.orientation);
        if (!good) {
            error = "TOOL_SET_OFFSET: bad arguments";
            return Outcome::Failed;
        }
        bool found = false;
        for (Tool& e : tools_)
            if (e.toolno == t.toolno) {
                int pocket = e.pocket;
                std::string comment = e.comment;
                e = t;
                e.pocket = pocket;     // G10 L1 does not move a tool
                e.comment = comment;   // the remark stays
                found = true;
            }
        if (!found) {
            if (random_) {
                if (static_cast<size_t>(t.pocket) >= tools_.size())
                    tools_.resize(t.pocket + 1);
                if (tools_[t.pocket].toolno >= 0) {
                    error = "pocket " + std::to_string(t.pocket) + " already holds tool " +
                            std::to_string(tools_[t.pocket].toolno);
                    return Outcome::Failed;
                }
                tools_[t.pocket] = t;
            } else {
                tools_.push_back(t);
            }
        }
        auto r = save();
        if (!r) {
            error = r.error().message;
            return Outcome::Failed;
        }
        return Outcome::Done;
    }
    if (v == "LOAD_TOOL_TABLE") {
        auto r = load_table(w.size() > 1 ? w[1] : "");
        if (!r) {
            error = r.error().message;
            return Outcome::Failed;
        }
        p.tool_number = tool_in_spindle_;
        return Outcome::Done;
    }
    error = "unknown io command '" + v + "'";
    return Outcome::Failed;
}

std::string IoCore::status_line(const IoPins& p) const
{
    auto b = [](bool x) { return x ? "1" : "0"; };
    return std::string("estop=") + b(!p.emc_enable_in) + " enabled_out=" + b(p.user_enable_out) +
           " mist=" + b(p.coolant_mist) + " flood=" + b(p.coolant_flood) + " lube=" + b(p.lube) +
           " lube_level=" + b(p.lube_level) + " tool=" + std::to_string(tool_in_spindle_) +
           " pocket_prepped=" + std::to_string(pocket_prepped_) + " prep_tool=" +
           std::to_string(p.tool_prep_number) + " from_pocket=" + std::to_string(p.tool_from_pocket) +
           " tool_prepare=" + b(p.tool_prepare) + " tool_change=" + b(p.tool_change) +
           " ack=" + std::to_string(inputs_after_);
}

std::vector<std::string> IoCore::table_lines() const
{
    std::vector<std::string> out;
    for (const Tool& t : table_in_file_order())
        out.push_back(format_tool(t));
    return out;
}

}  // namespace hal::io
