// SPDX-License-Identifier: GPL-2.0-or-later
// halui - HAL pins that drive task and motion (emcrsh-and-halui.md 3; docs/halui.md):
// the userspace component `halui`. Every 20 ms (50 Hz) it reads task's status over
// the machine bus once, writes the OUT pins, compares the IN pins with the previous
// cycle and sends the commands their edges ask for. It never waits for a command:
// DONE/ERROR replies are collected in later cycles (errors go to stderr). Started by
// the launcher as `halcmd loadusr -Wn halui halui -ini INI`, before task: it serves
// HAL at once and keeps retrying the bus until task is there (and after task restarts).
//
//   halui -ini FILE [-bus PATH]
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "bus/client.hpp"
#include "bus/program_args.hpp"
#include "hal.h"
#include "halui_config.hpp"
#include "halui_core.hpp"
#include "halui_pins.hpp"
#include "ini/ini_file.hpp"

using namespace hal;
using namespace std::chrono;

namespace {

constexpr auto PERIOD = milliseconds(20);
constexpr auto STATUS_TIMEOUT = milliseconds(500);   // task answers within its loop (ms)
constexpr auto RETRY = milliseconds(500);

// The bus side: connection, one status per cycle, commands out, replies collected.
class Link {
public:
    Link(std::string path, bool trace) : path_(std::move(path)), trace_(trace) {}

    // Task's status, or nothing while task is not reachable.
    std::optional<halui::StatusView> status(const halui::Config& cfg)
    {
        if (!client_ && !reconnect())
            return std::nullopt;
        auto st = client_->status(STATUS_TIMEOUT);
        if (!st) {
            drop(st.error().message);
            return std::nullopt;
        }
        client_->take_messages();   // operator messages are for displays, not for halui
        return halui::parse_status(*st, cfg.joints, cfg.spindles);
    }

    void send(const halui::Command& c)
    {
        if (!client_) {
            std::fprintf(stderr, "halui: %s: not sent, task is not reachable\n", c.line.c_str());
            return;
        }
        auto s = client_->send(c.line);
        if (!s) {
            drop(s.error().message);
            return;
        }
        waiting_[*s] = c;
        if (trace_)
            std::fprintf(stderr, "halui: sent %ld %s\n", *s, c.line.c_str());
    }

    // Replies that arrived: errors reported, tagged outcomes handed to the core.
    void collect(halui::Core& core)
    {
        for (int tag : lost_)
            core.on_result(tag, false);
        lost_.clear();
        if (!client_)
            return;
        for (auto it = waiting_.begin(); it != waiting_.end();) {
            auto r = client_->wait_done(it->first, milliseconds(0));
            if (!r && r.error().code == -ETIMEDOUT) {   // not answered yet
                ++it;
                continue;
            }
            if (!r)
                std::fprintf(stderr, "halui: %s: %s\n", it->second.line.c_str(), r.error().message.c_str());
            else if (trace_)
                std::fprintf(stderr, "halui: done %ld %s\n", it->first, it->second.line.c_str());
            if (it->second.tag)
                core.on_result(it->second.tag, static_cast<bool>(r));
            it = waiting_.erase(it);
        }
    }

    bool connected() const { return client_ != nullptr; }

private:
    bool reconnect()
    {
        auto now = steady_clock::now();
        if (now < next_try_)
            return false;
        next_try_ = now + RETRY;
        auto c = bus::Client::connect(path_, "client", milliseconds(1000));
        if (!c)
            return false;   // task not (yet / any more) there: halui keeps serving HAL
        client_ = std::move(*c);
        return true;
    }

    void drop(const std::string& why)
    {
        if (client_)
            std::fprintf(stderr, "halui: lost the bus (%s); retrying\n", why.c_str());
        client_.reset();
        // their replies will not come: a tagged step (MDI_COMMAND sequence) has failed
        for (const auto& [serial, c] : waiting_)
            if (c.tag)
                lost_.push_back(c.tag);
        waiting_.clear();
    }

    std::string path_;
    std::unique_ptr<bus::Client> client_;
    steady_clock::time_point next_try_{};
    std::map<long, halui::Command> waiting_;   // serial -> command, until DONE/ERROR
    std::vector<int> lost_;
    bool trace_;                                // HALUI_TRACE set: every command and DONE on stderr
};

}  // namespace

int main(int argc, char** argv)
{
    bus::ProgramArgs args;
    if (int rc = bus::parse_program_args("halui", argc, argv, args); rc >= 0)
        return rc;
    auto ini = ini::IniFile::load(args.ini_path);
    if (!ini) {
        std::fprintf(stderr, "halui: %s\n", ini.error().message.c_str());
        return 1;
    }
    auto cfg = halui::read_config(*ini);
    if (!cfg) {
        std::fprintf(stderr, "halui: %s\n", cfg.error().message.c_str());
        return 1;
    }
    auto path = bus::resolve_socket_path(args.bus_path, args.ini_path);
    if (!path) {
        std::fprintf(stderr, "halui: %s\n", path.error().message.c_str());
        return 1;
    }
    volatile std::sig_atomic_t* stop = bus::install_stop_signals();

    halui::Core core(*cfg);
    halui::Inputs in = core.make_inputs();
    halui::Outputs out = core.make_outputs();
    int id = hal_init("halui");
    if (id < 0) {
        std::fprintf(stderr, "halui: hal_init(halui) failed: %s\n", std::strerror(-id));
        return 1;
    }
    halui::Pins pins;
    std::string err;
    if (pins.create(id, *cfg, in, out, err) != 0) {
        std::fprintf(stderr, "halui: %s\n", err.c_str());
        hal_exit(id);
        return 1;
    }
    hal_ready(id);

    Link link(*path, std::getenv("HALUI_TRACE") != nullptr);
    const auto t0 = steady_clock::now();
    auto next = t0;
    while (!*stop) {
        pins.read();
        auto st = link.status(*cfg);
        link.collect(core);
        double now_s = duration<double>(steady_clock::now() - t0).count();
        for (const halui::Command& c : core.cycle(in, st ? &*st : nullptr, now_s, out))
            link.send(c);
        for (const std::string& n : core.take_notes())
            std::fprintf(stderr, "halui: %s\n", n.c_str());
        pins.write();
        next += PERIOD;
        auto now = steady_clock::now();
        if (next < now)
            next = now;
        std::this_thread::sleep_until(next);
    }
    hal_exit(id);
    return 0;
}
