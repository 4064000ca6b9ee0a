// SPDX-License-Identifier: GPL-2.0-or-later
// hal_rt_host_helper.cpp - a tiny realtime host for hal_query_ul_test: in its own
// process (own mapping of the segment) it makes a realtime component with pins,
// params, a function and a thread, then answers one command per stdin line:
//   in     print the value its pin rthost.in reads through its own pointer
//   gain   print its parameter rthost.gain
//   quit   hal_exit and leave (also on end of input)
#include <cstdio>
#include <cstring>

#include "hal.h"
#include "hal_host.h"

namespace {

struct HostData {
    hal_float_t* in;
    hal_bit_t* out;
    hal_float_t gain;
    hal_s32_t ro;
};

void update(void* arg, long)
{
    auto* d = static_cast<HostData*>(arg);
    *d->out = *d->in > 0;
}

int make_objects(int comp, HostData** out)
{
    auto* d = static_cast<HostData*>(hal_malloc(sizeof(HostData)));
    if (!d)
        return -ENOMEM;
    int err = hal_pin_float_new("rthost.in", HAL_IN, &d->in, comp);
    if (!err)
        err = hal_pin_bit_new("rthost.out", HAL_OUT, &d->out, comp);
    if (!err)
        err = hal_param_float_new("rthost.gain", HAL_RW, &d->gain, comp);
    if (!err)
        err = hal_param_s32_new("rthost.ro", HAL_RO, &d->ro, comp);
    if (!err)
        err = hal_export_funct("rthost.update", update, d, 1, 0, comp);
    if (!err)
        err = hal_create_thread("rthost.thread", 1000000, 1);
    if (!err)
        err = hal_add_funct_to_thread("rthost.update", "rthost.thread", 1);
    *out = d;
    return err;
}

}  // namespace

int main()
{
    int comp = hal_init("rthost");
    if (comp < 0) {
        std::printf("error %d\n", comp);
        return 1;
    }
    HostData* d = nullptr;
    int err = make_objects(comp, &d);
    if (err) {
        std::printf("error %d\n", err);
        hal_exit(comp);
        return 1;
    }
    hal_ready(comp);
    std::printf("ready\n");
    std::fflush(stdout);

    char line[64];
    while (std::fgets(line, sizeof(line), stdin)) {
        if (std::strncmp(line, "in", 2) == 0)
            std::printf("%.17g\n", static_cast<double>(*d->in));
        else if (std::strncmp(line, "gain", 4) == 0)
            std::printf("%.17g\n", static_cast<double>(d->gain));
        else if (std::strncmp(line, "quit", 4) == 0)
            break;
        else
            std::printf("unknown\n");
        std::fflush(stdout);
    }
    hal_exit(comp);
    hal_exit_threads();  // the host's job when it shuts down: threads outlive components
    std::printf("bye\n");
    return 0;
}
