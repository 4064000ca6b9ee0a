// SPDX-License-Identifier: GPL-2.0-or-later
// session.hpp - one emcrsh connection: the text protocol of emcrsh(1) (HELLO, SET,
// GET, QUIT, SHUTDOWN, HELP and the 76 subcommands), independent of sockets so the
// unit tests drive it line by line. State shared by all sessions (set_wait, timeout,
// update, unit conversions, which session is enabled) lives in Shared.
#pragma once

#include <atomic>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "machine.hpp"
#include "options.hpp"
#include "text.hpp"

namespace hal::emcrsh {

struct Shared {
    explicit Shared(Options o) : opt(std::move(o)) {}
    const Options opt;
    std::mutex mu;                      // guards everything below but the atomics
    Wait set_wait = Wait::RECEIVED;
    double timeout = 0;                 // seconds; <= 0: wait forever
    bool update_auto = true;
    std::string linear_conv = "AUTO";   // LINEAR_UNIT_CONVERSION
    std::string angular_conv = "AUTO";  // ANGULAR_UNIT_CONVERSION
    std::string last_program;           // for RUN with no program open
    std::atomic<int> enabled{0};        // id of the enabled session, 0: none
    std::atomic<int> sessions{0};
    std::atomic<bool> shutdown{false};  // SHUTDOWN was accepted
};

// The subcommands in the reference's order; SET permission goes by position
// (everything from INIFILE on needs the enabled session).
const std::vector<std::string>& subcommands();
int subcommand_index(const std::string& upper_name);   // -1: unknown

class Session {
public:
    Session(int id, Shared& shared, Machine& machine);
    ~Session();
    Session(const Session&) = delete;
    Session& operator=(const Session&) = delete;

    // One request line (no line end): the bytes to send back (maybe none).
    std::string handle(const std::string& line);
    // QUIT or SHUTDOWN: the connection is to be closed after sending.
    bool closing() const { return closing_; }
    bool enabled() const { return shared_.enabled.load() == id_; }
    // Takes task's operator messages in (the latest of each kind is kept for GET
    // ERROR / OPERATOR_DISPLAY / OPERATOR_TEXT), so an idle session holds no backlog.
    void take_messages();

private:
    std::string hello(const std::vector<std::string>& w);
    std::string get(const std::string& line, const std::vector<std::string>& w);
    std::string set(const std::string& line, const std::vector<std::string>& w);
    std::string help(const std::vector<std::string>& w) const;
    std::string shutdown();

    std::optional<std::string> get_value(const std::string& sub, const std::vector<std::string>& args);
    bool set_value(const std::string& sub, const std::vector<std::string>& args, const std::string& rest);
    std::optional<std::string> get_position(const std::string& sub, const std::vector<std::string>& args);
    std::optional<std::string> get_joints(const std::string& sub, const std::vector<std::string>& args);
    std::optional<std::string> get_units(const std::string& sub);
    bool set_motion(const std::string& sub, const std::vector<std::string>& args, const std::string& rest);

    // status access (refreshed per GET when UPDATE is AUTO)
    bool refresh();
    std::string key(const std::string& k) const;
    double num(const std::string& k) const;
    double axis_value(const std::string& field, int axis) const;   // axis 0..8 = X..W
    std::vector<double> offsets(const std::string& k) const;       // 9 values, X..W
    bool send(const std::string& bus_line);

    int id_;
    Shared& shared_;
    Machine& m_;
    bool linked_ = false;
    bool echo_ = true;
    bool verbose_ = false;
    bool closing_ = false;
    std::string comm_mode_ = "ASCII";
    std::string client_name_, comm_prot_ = "1.1";
    std::optional<bus::Status> st_;
    std::string error_, display_, text_;   // latest operator messages not yet read
};

}  // namespace hal::emcrsh
