// SPDX-License-Identifier: GPL-2.0-or-later
// emcbus - the machine bus on the command line: one command per invocation, waiting
// for task to report it done (docs/bus.md).
//
//   emcbus [-ini FILE | -bus PATH] [-t SECONDS] COMMAND [ARGS...]
//
// Exit status: 0 done, 1 refused or failed (task's message on stderr, naming the
// command), 2 bad usage, 3 no bus (task not running, permission).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

#include "bus/client.hpp"

using namespace hal::bus;
using namespace std::chrono;

static void usage(FILE* f)
{
    std::fprintf(f,
                 "usage: emcbus [-ini FILE | -bus PATH] [-t SECONDS] COMMAND [ARGS...]\n"
                 "  status [KEY...]           print the status, or the values of KEYs\n"
                 "  watch [SECONDS]           print operator messages as they arrive\n"
                 "  wait KEY VALUE [SECONDS]  wait until the status KEY has VALUE\n"
                 "  any task command, sent and waited for (-t, default 30 s):\n");
    for (const CommandSpec& c : commands())
        if (std::string(c.name) != "STATUS")
            std::fprintf(f, "    %s%s%s\n", c.name, c.usage[0] ? " " : "", c.usage);
    std::fprintf(f, "exit status: 0 done, 1 refused or failed, 2 bad usage, 3 no bus\n");
}

static void print_messages(Client& c)
{
    for (const Message& m : c.take_messages()) {
        if (m.kind == "ERROR")
            std::fprintf(stderr, "emcbus: task error: %s\n", m.text.c_str());
        else
            std::printf("%s: %s\n", m.kind.c_str(), m.text.c_str());
    }
    std::fflush(stdout);
}

static double seconds_arg(const std::string& s, const char* what)
{
    char* end = nullptr;
    double v = std::strtod(s.c_str(), &end);
    if (s.empty() || *end != '\0' || !(v >= 0) || v > 1e6) {
        std::fprintf(stderr, "emcbus: %s: '%s' is not a number of seconds\n", what, s.c_str());
        std::exit(2);
    }
    return v;
}

int main(int argc, char** argv)
{
    std::string ini, bus;
    double timeout_s = 30;
    int i = 1;
    for (; i < argc; ++i) {
        std::string a = argv[i];
        if ((a == "-ini" || a == "--ini" || a == "-i") && i + 1 < argc) {
            ini = argv[++i];
        } else if ((a == "-bus" || a == "--bus") && i + 1 < argc) {
            bus = argv[++i];
        } else if ((a == "-t" || a == "--timeout") && i + 1 < argc) {
            timeout_s = seconds_arg(argv[++i], "-t");
        } else if (a == "-h" || a == "--help") {
            usage(stdout);
            return 0;
        } else if (!a.empty() && a[0] == '-' && a.size() > 1 && !(a[1] >= '0' && a[1] <= '9')) {
            std::fprintf(stderr, "emcbus: unknown option '%s'\n", a.c_str());
            usage(stderr);
            return 2;
        } else {
            break;
        }
    }
    if (i >= argc) {
        usage(stderr);
        return 2;
    }
    std::vector<std::string> words(argv + i, argv + argc);
    std::string verb = words[0];
    for (char& ch : verb)
        ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
    std::string line;
    for (size_t k = 0; k < words.size(); ++k)
        line += (k ? " " : "") + (k == 0 ? verb : words[k]);

    // check locally what can be checked, so a typo is exit status 2 without a bus
    bool local = verb == "STATUS" || verb == "WATCH" || verb == "WAIT";
    if (!local) {
        auto req = parse_request("1 " + line);
        if (!req) {
            std::fprintf(stderr, "emcbus: %s\n", req.error().message.c_str());
            return 2;
        }
    }
    if (verb == "WAIT" && (words.size() < 3 || words.size() > 4)) {
        std::fprintf(stderr, "emcbus: wait: needs KEY VALUE [SECONDS]\n");
        return 2;
    }
    if (verb == "WATCH" && words.size() > 2) {
        std::fprintf(stderr, "emcbus: watch: needs at most SECONDS\n");
        return 2;
    }
    auto path = resolve_socket_path(bus, ini);
    if (!path) {
        std::fprintf(stderr, "emcbus: %s\n", path.error().message.c_str());
        return 3;
    }
    auto client = Client::connect(*path);
    if (!client) {
        std::fprintf(stderr, "emcbus: %s\n", client.error().message.c_str());
        return 3;
    }
    Client& c = **client;
    const auto tmo = milliseconds(static_cast<long>(timeout_s * 1000));

    if (verb == "STATUS") {
        auto st = c.status(tmo);
        if (!st) {
            std::fprintf(stderr, "emcbus: status: %s\n", st.error().message.c_str());
            return 1;
        }
        if (words.size() == 1) {
            for (const auto& [k, v] : *st)
                std::printf("%s %s\n", k.c_str(), v.c_str());
            return 0;
        }
        int rc = 0;
        for (size_t k = 1; k < words.size(); ++k) {
            auto it = st->find(words[k]);
            if (it == st->end()) {
                std::fprintf(stderr, "emcbus: status: no key '%s'\n", words[k].c_str());
                rc = 1;
                continue;
            }
            std::printf("%s\n", it->second.c_str());
        }
        return rc;
    }
    if (verb == "WATCH") {
        double secs = words.size() > 1 ? seconds_arg(words[1], "watch") : 1e6;
        auto deadline = steady_clock::now() + milliseconds(static_cast<long>(secs * 1000));
        while (steady_clock::now() < deadline) {
            auto left = duration_cast<milliseconds>(deadline - steady_clock::now());
            auto r = c.pump(std::min(left, milliseconds(200)));
            for (const Message& m : c.take_messages())
                std::printf("%s %s\n", m.kind.c_str(), m.text.c_str());
            std::fflush(stdout);
            if (!r) {
                std::fprintf(stderr, "emcbus: watch: %s\n", r.error().message.c_str());
                return 3;
            }
        }
        return 0;
    }
    if (verb == "WAIT") {
        double secs = words.size() > 3 ? seconds_arg(words[3], "wait") : timeout_s;
        auto deadline = steady_clock::now() + milliseconds(static_cast<long>(secs * 1000));
        std::string last = "(none)";
        for (;;) {
            auto st = c.status(tmo);
            if (!st) {
                std::fprintf(stderr, "emcbus: wait: %s\n", st.error().message.c_str());
                return 1;
            }
            auto it = st->find(words[1]);
            if (it == st->end()) {
                std::fprintf(stderr, "emcbus: wait: no status key '%s'\n", words[1].c_str());
                return 2;
            }
            last = it->second;
            if (last == words[2])
                break;
            if (steady_clock::now() >= deadline) {
                print_messages(c);
                std::fprintf(stderr, "emcbus: wait: %s is '%s', not '%s', after %g s\n", words[1].c_str(),
                             last.c_str(), words[2].c_str(), secs);
                return 1;
            }
            std::this_thread::sleep_for(milliseconds(20));
        }
        print_messages(c);
        return 0;
    }
    auto r = c.command(line, tmo);
    print_messages(c);
    if (!r) {
        std::fprintf(stderr, "emcbus: %s: %s\n", line.c_str(), r.error().message.c_str());
        return 1;
    }
    return 0;
}
