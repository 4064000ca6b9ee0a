// SPDX-License-Identifier: GPL-2.0-or-later
// session.cpp - the top-level commands of one connection (session.hpp). The
// subcommands are in subcommands_get.cpp and subcommands_set.cpp.
#include "session.hpp"

#include <algorithm>

namespace hal::emcrsh {

const std::vector<std::string>& subcommands()
{
    // the reference's setCommands[] order (emcrsh-and-halui.md 1.3): SET permission
    // depends on the position (INIFILE and later: the enabled session only)
    static const std::vector<std::string> names = {
        "ECHO", "VERBOSE", "ENABLE", "CONFIG", "COMM_MODE", "COMM_PROT", "INIFILE", "PLAT", "INI", "DEBUG",
        "SET_WAIT", "WAIT", "TIMEOUT", "UPDATE", "ERROR", "OPERATOR_DISPLAY", "OPERATOR_TEXT", "TIME", "ESTOP",
        "MACHINE", "MODE", "MIST", "FLOOD", "LUBE", "LUBE_LEVEL", "SPINDLE", "BRAKE", "TOOL", "TOOL_OFFSET",
        "LOAD_TOOL_TABLE", "HOME", "JOG_STOP", "JOG", "JOG_INCR", "FEED_OVERRIDE", "ABS_CMD_POS", "ABS_ACT_POS",
        "REL_CMD_POS", "REL_ACT_POS", "JOINT_POS", "POS_OFFSET", "JOINT_LIMIT", "JOINT_FAULT", "JOINT_HOMED",
        "MDI", "TASK_PLAN_INIT", "OPEN", "RUN", "PAUSE", "RESUME", "STEP", "ABORT", "PROGRAM", "PROGRAM_LINE",
        "PROGRAM_STATUS", "PROGRAM_CODES", "JOINT_TYPE", "JOINT_UNITS", "PROGRAM_UNITS", "PROGRAM_LINEAR_UNITS",
        "PROGRAM_ANGULAR_UNITS", "USER_LINEAR_UNITS", "USER_ANGULAR_UNITS", "DISPLAY_LINEAR_UNITS",
        "DISPLAY_ANGULAR_UNITS", "LINEAR_UNIT_CONVERSION", "ANGULAR_UNIT_CONVERSION", "PROBE_CLEAR",
        "PROBE_TRIPPED", "PROBE_VALUE", "PROBE", "TELEOP_ENABLE", "KINEMATICS_TYPE", "OVERRIDE_LIMITS",
        "SPINDLE_OVERRIDE", "OPTIONAL_STOP"};
    return names;
}

int subcommand_index(const std::string& name)
{
    // the man page calls TIMEOUT "set_timeout"
    const std::string& n = name == "SET_TIMEOUT" ? std::string("TIMEOUT") : name;
    const auto& v = subcommands();
    auto it = std::find(v.begin(), v.end(), n);
    return it == v.end() ? -1 : static_cast<int>(it - v.begin());
}

Session::Session(int id, Shared& shared, Machine& machine) : id_(id), shared_(shared), m_(machine) {}

Session::~Session()
{
    int me = id_;
    shared_.enabled.compare_exchange_strong(me, 0);   // a closed session gives enable up
}

std::string Session::handle(const std::string& line)
{
    std::vector<std::string> w = split_words(line);
    if (w.empty())
        return "";
    std::string out = echo_ && linked_ ? line + "\r\n" : "";
    std::string cmd = upper(w[0]);
    if (cmd == "HELLO")
        return out + hello(w);
    if (cmd == "GET")
        return out + get(line, w);
    if (cmd == "SET")
        return out + set(line, w);
    if (cmd == "QUIT") {
        closing_ = true;
        return out;
    }
    if (cmd == "SHUTDOWN")
        return out + shutdown();
    if (cmd == "HELP")
        return out + help(w);
    return out;   // an unknown command gets no reply (emcrsh(1))
}

std::string Session::hello(const std::vector<std::string>& w)
{
    if (w.size() < 4 || w[1] != shared_.opt.connect_pw)
        return "HELLO NAK\r\n";
    linked_ = true;
    client_name_ = w[2];
    comm_prot_ = w[3];
    return "HELLO ACK " + shared_.opt.name + " 1.1\r\n";
}

std::string Session::shutdown()
{
    if (!linked_ || !enabled())
        return "SHUTDOWN NAK\r\n";
    shared_.shutdown = true;
    closing_ = true;
    return "";
}

std::string Session::get(const std::string&, const std::vector<std::string>& w)
{
    if (w.size() < 2)
        return "GET NAK\r\n";
    std::string sub = upper(w[1]);
    if (subcommand_index(sub) < 0)
        return "GET NAK\r\n";
    std::vector<std::string> args(w.begin() + 2, w.end());
    auto v = get_value(sub, args);
    return v ? crlf(*v) : get_nak(sub);
}

std::string Session::set(const std::string& line, const std::vector<std::string>& w)
{
    if (!linked_ || w.size() < 2)
        return "SET NAK\r\n";
    std::string sub = upper(w[1]);
    int idx = subcommand_index(sub);
    if (idx < 0)
        return "SET NAK\r\n";
    if (idx >= subcommand_index("INIFILE") && !enabled())
        return set_nak(sub);
    std::vector<std::string> args(w.begin() + 2, w.end());
    if (!set_value(sub, args, rest_after(line, 2)))
        return set_nak(sub);
    return verbose_ ? set_ack(sub) : "";
}

std::string Session::help(const std::vector<std::string>& w) const
{
    // the usage text; lines end "\n\r" like the reference's
    std::string topic = w.size() > 1 ? upper(w[1]) : "";
    std::string t;
    auto line = [&](const std::string& s) { t += s + "\n\r"; };
    if (topic == "HELLO") {
        line("Usage: HELLO <password> <client name> <protocol version>");
        line("  Logs in; replies HELLO ACK <server name> 1.1, or HELLO NAK.");
    } else if (topic == "GET") {
        line("Usage: GET <subcommand> [arguments]");
        line("  Replies <SUBCOMMAND> <value>, or GET <SUBCOMMAND> NAK.");
    } else if (topic == "SET") {
        line("Usage: SET <subcommand> <arguments>");
        line("  Needs HELLO; from INIFILE on in the list, the enabled session (SET ENABLE <password>).");
        line("  Silent on success (SET <SUBCOMMAND> ACK when VERBOSE is ON), SET <SUBCOMMAND> NAK on failure.");
    } else if (topic == "QUIT") {
        line("Usage: QUIT");
        line("  Closes this connection.");
    } else if (topic == "SHUTDOWN") {
        line("Usage: SHUTDOWN");
        line("  From the enabled session: ends emcrsh (and the machine, when emcrsh is its display).");
    } else {
        line("Available commands:");
        line("  HELLO <password> <client name> <protocol version>");
        line("  GET <subcommand> [arguments]");
        line("  SET <subcommand> <arguments>");
        line("  SHUTDOWN");
        line("  QUIT");
        line("  HELP [command]");
        std::string subs = "Subcommands:";
        for (const auto& s : subcommands()) {
            if (subs.size() + s.size() > 72) {
                line(subs);
                subs = " ";
            }
            subs += " " + s;
        }
        line(subs);
    }
    return t;
}

}  // namespace hal::emcrsh
