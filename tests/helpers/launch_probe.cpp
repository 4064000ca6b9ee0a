// SPDX-License-Identifier: GPL-2.0-or-later
// launch_probe - a test fixture for the launcher tests (tests/launcher): stands in
// for [EMCIO]EMCIO, [TASK]TASK, [HAL]HALUI, an [APPLICATIONS]APP or the display and
// records how it was started. Not a product program: it does nothing else.
//
//   launch_probe [-ini FILE] NAME [--no-hal] [--exit N] [--fail] [ARGS...]
//
// Appends to $LAUNCH_PROBE_LOG one line "start NAME pid=N args=[...] ini=... cwd=..." (and
// "stop NAME" on SIGTERM/SIGINT). Unless --no-hal, makes the HAL component NAME (with
// one pin NAME.alive) and calls hal_ready. --exit N: exit with N after 0.2 s (a display
// that quits); --fail: exit 1 before hal_ready (a program that cannot start).
#include <signal.h>
#include <unistd.h>

#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "hal.h"

namespace {

volatile sig_atomic_t stop_requested = 0;
void on_signal(int) { stop_requested = 1; }

void record(const std::string& line)
{
    const char* log = std::getenv("LAUNCH_PROBE_LOG");
    if (!log)
        return;
    if (FILE* f = std::fopen(log, "a")) {
        std::fprintf(f, "%s\n", line.c_str());
        std::fclose(f);
    }
}

}  // namespace

int main(int argc, char** argv)
{
    std::string name, ini, all;
    bool hal = true, fail = false;
    int exit_after = -1;
    for (int i = 1; i < argc; i++) {
        std::string a = argv[i];
        all += (all.empty() ? "" : " ") + a;
        if (a == "-ini" && i + 1 < argc) {
            ini = argv[++i];
            all += std::string(" ") + argv[i];
        } else if (a == "--no-hal") {
            hal = false;
        } else if (a == "--fail") {
            fail = true;
        } else if (a == "--exit" && i + 1 < argc) {
            exit_after = std::atoi(argv[++i]);
            all += std::string(" ") + argv[i];
        } else if (name.empty() && a[0] != '-') {
            name = a;
        }
    }
    if (name.empty()) {
        std::fprintf(stderr, "usage: launch_probe [-ini FILE] NAME [--no-hal] [--exit N] [--fail] [ARGS...]\n");
        return 2;
    }
    char cwd[PATH_MAX];
    const char* env_ini = std::getenv("INI_FILE_NAME");
    record("start " + name + " pid=" + std::to_string(getpid()) + " args=[" + all + "] ini=" + ini + " INI_FILE_NAME=" + (env_ini ? env_ini : "") +
           " cwd=" + (getcwd(cwd, sizeof cwd) ? cwd : "?"));
    if (fail) {
        std::fprintf(stderr, "launch_probe %s: failing as asked\n", name.c_str());
        return 1;
    }
    signal(SIGTERM, on_signal);
    signal(SIGINT, on_signal);
    int id = -1;
    if (hal) {
        id = hal_init(name.c_str());
        if (id < 0)
            return 1;
        hal_bit_t** alive = static_cast<hal_bit_t**>(hal_malloc(sizeof(hal_bit_t*)));
        if (!alive || hal_pin_bit_newf(HAL_OUT, alive, id, "%s.alive", name.c_str()) != 0) {
            hal_exit(id);
            return 1;
        }
        **alive = 1;
        hal_ready(id);
    }
    for (int ms = 0; !stop_requested; ms += 20) {
        if (exit_after >= 0 && ms >= 200)
            break;
        usleep(20000);
    }
    record((stop_requested ? "stop " : "exit ") + name);
    if (id >= 0)
        hal_exit(id);
    return stop_requested ? 0 : exit_after;
}
