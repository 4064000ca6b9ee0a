// SPDX-License-Identifier: GPL-2.0-or-later
// hal_testcomp - a minimal userspace HAL component for the loadusr/unloadusr/crash
// tests: "hal_testcomp NAME [DELAY_MS]" waits DELAY_MS (so loadusr -W has something to
// wait for), makes NAME.in (float in), NAME.out (float out, = 2 * in) and NAME.beat
// (s32 out, counts 10 ms cycles), calls hal_ready and runs until SIGTERM/SIGINT.
#include <signal.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "hal.h"

namespace {

volatile sig_atomic_t stop_requested = 0;

void on_signal(int) { stop_requested = 1; }

struct Pins {
    hal_float_t* in;
    hal_float_t* out;
    hal_s32_t* beat;
};

}  // namespace

int main(int argc, char** argv)
{
    if (argc < 2 || argc > 3) {
        std::fprintf(stderr, "usage: hal_testcomp NAME [DELAY_MS]\n");
        return 1;
    }
    std::string name = argv[1];
    int delay_ms = argc == 3 ? std::atoi(argv[2]) : 0;
    signal(SIGTERM, on_signal);
    signal(SIGINT, on_signal);
    int id = hal_init(name.c_str());
    if (id < 0)
        return 1;
    usleep(static_cast<useconds_t>(delay_ms) * 1000);
    auto* p = static_cast<Pins*>(hal_malloc(sizeof(Pins)));
    if (!p || hal_pin_float_newf(HAL_IN, &p->in, id, "%s.in", name.c_str()) ||
        hal_pin_float_newf(HAL_OUT, &p->out, id, "%s.out", name.c_str()) ||
        hal_pin_s32_newf(HAL_OUT, &p->beat, id, "%s.beat", name.c_str())) {
        hal_exit(id);
        return 1;
    }
    hal_ready(id);
    while (!stop_requested) {
        *p->out = 2 * *p->in;
        *p->beat = *p->beat + 1;
        usleep(10000);
    }
    hal_exit(id);
    return 0;
}
