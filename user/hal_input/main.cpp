// SPDX-License-Identifier: GPL-2.0-or-later
// hal_input(1): Linux input devices as HAL pins. Finds each inputspec's device through
// libudev, makes its pins (component "hal_input", pins input.N.*), then about every 10 ms
// moves events into pins and LED pins out to the device until SIGTERM/SIGINT.
#include <signal.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <memory>
#include <vector>

#include "input_device.hpp"
#include "input_spec.hpp"
#include "input_udev.hpp"

namespace {

volatile sig_atomic_t stop_requested = 0;

void on_signal(int) { stop_requested = 1; }

}  // namespace

int main(int argc, char** argv)
{
    using namespace hal::input;
    for (int i = 1; i < argc; i++)
        if (std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0) {
            std::fputs(input_usage, stdout);
            return 0;
        }
    auto specs = parse_input_args(std::span<char* const>(argv, static_cast<size_t>(argc)));
    if (!specs) {
        std::fprintf(stderr, "hal_input: %s\n%s", specs.error().message.c_str(), input_usage);
        return 1;
    }
    std::vector<DeviceInfo> present = scan_input_devices();
    std::vector<DeviceInfo> chosen;
    for (const InputSpec& s : *specs) {
        auto d = select_device(s, present);
        if (!d) {
            std::fprintf(stderr, "hal_input: no input device matches '%s' (see /proc/bus/input/devices)\n",
                         s.text.c_str());
            return 1;
        }
        chosen.push_back(*d);
    }
    struct sigaction sa = {};
    sa.sa_handler = on_signal;
    sigaction(SIGTERM, &sa, nullptr);
    sigaction(SIGINT, &sa, nullptr);
    // "hal_input", the program's name: what "loadusr -W hal_input" in users' files
    // waits for (the pins are input.N.* all the same)
    int id = hal_init("hal_input");
    if (id < 0)
        return 1;
    std::vector<std::unique_ptr<InputDevice>> devices;
    for (size_t i = 0; i < specs->size(); i++) {
        devices.push_back(std::make_unique<InputDevice>((*specs)[i], static_cast<int>(i)));
        if (devices.back()->open_and_export(chosen[i], id) < 0) {
            devices.clear();
            hal_exit(id);
            return 1;
        }
    }
    hal_ready(id);
    while (!stop_requested) {
        for (auto& d : devices) {
            d->update();
            d->try_reopen();
        }
        usleep(10000);
    }
    devices.clear();              // ungrab and close before the pins go
    hal_exit(id);
    return 0;
}
