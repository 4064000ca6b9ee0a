// SPDX-License-Identifier: GPL-2.0-or-later
// motcmd.cpp - motcmd(1): send one command to motmod (or a file of them), print the
// result or motion's status. For tests and for people debugging a machine.
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "cmdcheck.h"
#include "motcmd_parse.hpp"
#include "motion_client.hpp"

using namespace hal;
using namespace std::chrono_literals;

namespace {

constexpr int kExitOk = 0, kExitRefused = 1, kExitUsage = 2, kExitChannel = 3;

struct Options {
    int key = MOTION_DEFAULT_KEY;
    std::chrono::milliseconds timeout{5000};
    int id = 0;
    long force_number = -1;  // --force-number: write this command number (tests)
    std::string file;
    std::vector<std::string> words;
};

void print_errors(MotionClient& c)
{
    unsigned lost = 0;
    for (const std::string& e : c.take_errors(&lost))
        std::printf("error: %s\n", e.c_str());
    if (lost)
        std::printf("error: %u more messages were lost (error queue full)\n", lost);
}

void print_status(const motion_status& s)
{
    static const char letters[] = "xyzabcuvw";
    std::printf("state %s enabled %d inpos %d coord %d teleop %d error %d all-homed %d\n",
                motion_state_name(s.motion_state), !!(s.motionFlag & MOTION_FLAG_ENABLE),
                !!(s.motionFlag & MOTION_FLAG_INPOS), !!(s.motionFlag & MOTION_FLAG_COORD),
                !!(s.motionFlag & MOTION_FLAG_TELEOP), !!(s.motionFlag & MOTION_FLAG_ERROR),
                s.all_homed);
    std::printf("command %s (%d) number %u status %s heartbeat %u\n",
                cmdcheck_name(s.commandEcho), s.commandEcho, s.commandNumEcho,
                motion_cmd_status_name(s.commandStatus), s.heartbeat);
    std::printf("queue depth %d id %d motion-type %d current-vel %.6f distance-to-go %.6f paused %d\n",
                s.depth, s.id, s.motionType, s.current_vel, s.distance_to_go, s.paused);
    std::printf("feed-scale %.6f rapid-scale %.6f net-feed-scale %.6f enables 0x%x override-limits 0x%x on-soft-limit %d\n",
                s.feed_scale, s.rapid_scale, s.net_feed_scale, s.enables_new,
                s.overrideLimitMask, s.on_soft_limit);
    std::printf("probe value %d tripped %d probing %d\n", s.probeVal, s.probeTripped, s.probing);
    std::printf("world-cmd");
    for (int l = 0; l < MOTION_MAX_AXES; ++l)
        std::printf(" %c %.6f", letters[l], s.carte_pos_cmd.v[l]);
    std::printf("\nprobed-pos");
    for (int l = 0; l < MOTION_MAX_AXES; ++l)
        std::printf(" %c %.6f", letters[l], s.probedPos.v[l]);
    std::printf("\n");
    for (int j = 0; j < s.num_joints && j < MOTION_MAX_JOINTS; ++j) {
        const motion_joint_status& js = s.joint[j];
        std::printf("joint %d pos-cmd %.6f pos-fb %.6f vel-cmd %.6f ferror %.6f homed %d homing %d home-state %d flags 0x%02x\n",
                    j, js.pos_cmd, js.pos_fb, js.vel_cmd, js.ferror, js.homed, js.homing,
                    js.home_state, js.flag);
    }
    for (int i = 0; i < s.num_spindles && i < MOTION_MAX_SPINDLES; ++i)
        std::printf("spindle %d speed %.3f speed-out %.3f state %d brake %d orient-state %d\n", i,
                    s.spindle[i].speed, s.spindle[i].speed_out, s.spindle[i].state,
                    s.spindle[i].brake, s.spindle[i].orient_state);
}

// wait until pred(status) holds or wait_s passes (not a timing assertion: a bound)
template <typename Pred>
int wait_for(MotionClient& c, double wait_s, const char* what, Pred pred)
{
    auto deadline = std::chrono::steady_clock::now() +
                    std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                        std::chrono::duration<double>(wait_s));
    for (;;) {
        auto s = c.status(1000ms);
        if (!s) {
            std::fprintf(stderr, "motcmd: %s\n", s.error().message.c_str());
            return kExitChannel;
        }
        if (pred(*s))
            return kExitOk;
        if (std::chrono::steady_clock::now() > deadline) {
            std::printf("motcmd: %s: not reached within %g s\n", what, wait_s);
            return kExitRefused;
        }
        std::this_thread::sleep_for(2ms);
    }
}

int send(MotionClient& c, const Options& o, motion_command cmd)
{
    cmd.id = o.id ? o.id : cmd.id;
    auto r = c.send(cmd, o.timeout, o.force_number);
    if (!r) {
        std::fprintf(stderr, "motcmd: %s\n", r.error().message.c_str());
        return kExitChannel;
    }
    if (*r != MOTION_CMD_OK) {
        std::printf("motcmd: %s refused: %s\n", cmdcheck_name(cmd.command),
                    motion_cmd_status_name(*r));
        print_errors(c);
        return kExitRefused;
    }
    return kExitOk;
}

int comp_file(MotionClient& c, const Options& o, const MotcmdRequest& r)
{
    std::ifstream in(r.file);
    if (!in) {
        std::fprintf(stderr, "motcmd: comp-file: cannot read '%s': %s\n", r.file.c_str(),
                     std::strerror(errno));
        return kExitUsage;
    }
    std::string line;
    motion_command cmd = r.cmd;
    while (std::getline(in, line)) {
        if (!motcmd_comp_line(line, r.comp_type, &cmd.comp_nominal, &cmd.comp_forward,
                              &cmd.comp_reverse))
            break;  // reading stops at the first line that is not three numbers
        if (int rc = send(c, o, cmd); rc != kExitOk)
            return rc;
    }
    return kExitOk;
}

int run(MotionClient& c, const Options& o, const MotcmdRequest& r)
{
    switch (r.action) {
    case MotcmdAction::Status: {
        auto s = c.status(o.timeout);
        if (!s) {
            std::fprintf(stderr, "motcmd: %s\n", s.error().message.c_str());
            return kExitChannel;
        }
        print_status(*s);
        return kExitOk;
    }
    case MotcmdAction::Errors:
        print_errors(c);
        return kExitOk;
    case MotcmdAction::WaitInpos:
        return wait_for(c, r.wait_s, "wait-inpos", [](const motion_status& s) {
            bool homing = false;
            for (int j = 0; j < s.num_joints && j < MOTION_MAX_JOINTS; ++j)
                homing = homing || s.joint[j].homing;
            return (s.motionFlag & MOTION_FLAG_INPOS) && !homing && s.depth == 0;
        });
    case MotcmdAction::WaitHomed:
        return wait_for(c, r.wait_s, "wait-homed", [](const motion_status& s) { return s.all_homed != 0; });
    case MotcmdAction::WaitState:
        return wait_for(c, r.wait_s, "wait-state",
                        [&](const motion_status& s) { return s.motion_state == r.state; });
    case MotcmdAction::CompFile:
        return comp_file(c, o, r);
    case MotcmdAction::Send:
        break;
    }
    return send(c, o, r.cmd);
}

std::vector<std::string> split(const std::string& line)
{
    std::vector<std::string> words;
    std::istringstream in(line.substr(0, line.find('#')));
    std::string w;
    while (in >> w)
        words.push_back(w);
    return words;
}

int parse_options(int argc, char** argv, Options& o)
{
    int i = 1;
    for (; i < argc; ++i) {
        std::string a = argv[i];
        auto value = [&](const char* name) -> const char* {
            if (i + 1 >= argc) {
                std::fprintf(stderr, "motcmd: %s needs a value\n", name);
                return nullptr;
            }
            return argv[++i];
        };
        if (a == "--help" || a == "-h") {
            std::fputs(motcmd_usage(), stdout);
            return -1;
        }
        if (a == "--key" || a == "--timeout" || a == "--id" || a == "-f" || a == "--force-number") {
            const char* v = value(a.c_str());
            if (!v)
                return kExitUsage;
            if (a == "-f") {
                o.file = v;
                continue;
            }
            char* end = nullptr;
            long n = std::strtol(v, &end, 0);
            if (!*v || *end || n < 0 || n > 2147483647L) {
                std::fprintf(stderr, "motcmd: %s: '%s' is not a number\n", a.c_str(), v);
                return kExitUsage;
            }
            if (a == "--key")
                o.key = static_cast<int>(n);
            else if (a == "--timeout")
                o.timeout = std::chrono::milliseconds(n);
            else if (a == "--force-number")
                o.force_number = n;
            else
                o.id = static_cast<int>(n);
            continue;
        }
        if (a.size() > 1 && a[0] == '-' && !(a[1] >= '0' && a[1] <= '9') && a[1] != '.') {
            std::fprintf(stderr, "motcmd: unknown option '%s' (motcmd --help)\n", a.c_str());
            return kExitUsage;
        }
        break;
    }
    for (; i < argc; ++i)
        o.words.push_back(argv[i]);
    if (o.file.empty() && o.words.empty()) {
        std::fprintf(stderr, "motcmd: no command given (motcmd --help lists them)\n");
        return kExitUsage;
    }
    if (!o.file.empty() && !o.words.empty()) {
        std::fprintf(stderr, "motcmd: give either -f FILE or a command, not both\n");
        return kExitUsage;
    }
    return kExitOk;
}

}  // namespace

int main(int argc, char** argv)
{
    Options o;
    if (int rc = parse_options(argc, argv, o); rc != kExitOk)
        return rc < 0 ? kExitOk : rc;
    // parse everything before sending anything: a bad line sends nothing
    std::vector<MotcmdRequest> requests;
    if (!o.file.empty()) {
        std::ifstream in(o.file);
        if (!in) {
            std::fprintf(stderr, "motcmd: cannot read '%s': %s\n", o.file.c_str(), std::strerror(errno));
            return kExitUsage;
        }
        std::string line;
        for (int n = 1; std::getline(in, line); ++n) {
            auto words = split(line);
            if (words.empty())
                continue;
            auto r = motcmd_parse(words);
            if (!r) {
                std::fprintf(stderr, "motcmd: %s:%d: %s\n", o.file.c_str(), n, r.error().message.c_str());
                return kExitUsage;
            }
            requests.push_back(*r);
        }
    } else {
        auto r = motcmd_parse(o.words);
        if (!r) {
            std::fprintf(stderr, "motcmd: %s\n", r.error().message.c_str());
            return kExitUsage;
        }
        requests.push_back(*r);
    }
    auto client = MotionClient::attach(o.key);
    if (!client) {
        std::fprintf(stderr, "motcmd: %s\n", client.error().message.c_str());
        return kExitChannel;
    }
    for (const MotcmdRequest& r : requests)
        if (int rc = run(**client, o, r); rc != kExitOk)
            return rc;
    return kExitOk;
}
