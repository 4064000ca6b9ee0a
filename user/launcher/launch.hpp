// SPDX-License-Identifier: GPL-2.0-or-later
// launch.hpp - one machine session: the start-up order of ini-and-launch.md 3.2 and
// the clean-up of 3.4, run through the realtime and halcmd tools (as the LinuxCNC
// script does), so either flavor works the way halrun starts it.
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

#include "options.hpp"
#include "plan.hpp"

namespace hal::launcher {

struct Tools {
    std::string halcmd;                // "halcmd" beside the launcher, else from PATH
    std::string realtime;
    std::string prog;                  // emc or linuxcnc: message prefix
};

class Launch {
public:
    Launch(Options opts, Plan plan, Tools tools) : opts_(std::move(opts)), plan_(std::move(plan)), tools_(std::move(tools)) {}
    // Start-up, the display (or a wait for a signal), clean-up. Returns the exit status.
    int run();

private:
    bool start_up();
    bool start_component(const char* what, const char* comp, const std::vector<std::string>& argv, pid_t& group);
    bool run_halfiles();
    bool run_twopass();
    bool run_halcmds();
    bool wait_task();
    void start_apps();
    int run_display();
    void clean_up();

    int halcmd(std::vector<std::string> args, const std::string& stdin_text = "");
    void say(const std::string& msg) const;
    void fail(const std::string& msg) const;

    Options opts_;
    Plan plan_;
    Tools tools_;
    bool realtime_up_ = false;
    pid_t io_ = 0, halui_ = 0, task_ = 0, display_ = 0;   // process groups (display: pid)
    std::vector<pid_t> apps_;
};

}  // namespace hal::launcher
