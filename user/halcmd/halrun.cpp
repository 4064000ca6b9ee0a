// SPDX-License-Identifier: GPL-2.0-or-later
// halrun.cpp - halrun (halcmd(1)): refuse a second realtime session, run halcmd with
// the given arguments (a .hal file means -f file), optionally an interactive
// "halcmd -kf" (-I), then tear everything down. "halrun -U" tears down whatever is left.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "commands.hpp"
#include "hal_query.h"
#include "input_text.hpp"
#include "options.hpp"
#include "python_path.hpp"
#include "hal/kmod.hpp"
#include "realtime.hpp"
#include "session.hpp"
#include "snapshot.hpp"
#include "teardown.hpp"


namespace {

using namespace hal::halcmd;

void complain(const std::string& msg)
{
    std::fflush(stdout);
    std::fprintf(stderr, "halrun: %s\n", hal::halcmd::printable(msg).c_str());
}

std::string instance()
{
    const char* v = std::getenv("RTAPI_INSTANCE");
    return v ? v : "0";
}

void refuse_second_session()
{
    complain("a realtime session is already running (RTAPI_INSTANCE=" + instance() +
             "); end it with 'halrun -U'");
}

int run_session(const HalrunOptions& opts)
{
    if (rt_running()) {
        refuse_second_session();
        return 1;
    }
    // This session ends with halrun, so rtapi_app may keep our stderr (rtapi_client.cpp).
    setenv("RTAPI_APP_STDERR", "keep", 1);
    int status;
    {
        Session session(opts.halcmd);
        if (!session.start())
            return 1;
        if (!take_snapshot(snap_comps).comps.empty()) {
            refuse_second_session();
            return 1;                             // not ours: leave it running
        }
        // "halrun -I" alone: the interactive halcmd is the whole run, not a second one.
        bool has_input = opts.halcmd.from_file || !opts.halcmd.command.empty();
        status = opts.interactive && !has_input ? 0 : session.run_input();
        if (opts.interactive && session.run_keep_going_stdin() != 0)
            status = 1;
        if (!teardown_attached("halrun"))
            status = 1;
    }                                             // the session detaches here
    if (!shutdown_realtime("halrun"))
        status = 1;
    return status;
}

}  // namespace

int main(int argc, char** argv)
{
    std::vector<std::string> args(argv + 1, argv + argc);
    auto opts = parse_halrun_options(args);
    if (!opts) {
        complain(opts.error().message);
        return 1;
    }
    export_python_path();                  // for loadusr'd Python components and scripts
    try {
        if (auto r = select_flavor(opts->halcmd.flavor); !r) {
            complain(r.error().message);
            return 1;
        }
        if (opts->force_exit)
            return force_exit("halrun");
        if (opts->halcmd.help) {
            hal::halcmd::Session s(opts->halcmd);
            return s.run();
        }
        return run_session(*opts);
    } catch (const std::exception& e) {
        complain(std::string("internal error: ") + e.what());
        return 1;
    }
}
