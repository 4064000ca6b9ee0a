// SPDX-License-Identifier: GPL-2.0-or-later
// input_device.hpp - one inputspec's device as HAL pins input.N.* (hal_input(1)):
// keys and buttons, absolute and relative axes, LEDs. The pins are made once, from
// the capabilities of the device first opened; when the device is unplugged the
// pins stay (keys read released) and a device matching the same spec that appears
// later is opened in its place.
#pragma once

#include <string>
#include <vector>

#include "hal.h"
#include "input_spec.hpp"

namespace hal::input {

struct KeyPins { int code; hal_bit_t* on; hal_bit_t* off; };
struct AbsPins {
    int code;
    hal_s32_t* counts; hal_float_t* position;
    hal_float_t scale, offset; hal_s32_t fuzz, flat, min, max;   // parameters
};
struct RelPins {
    int code;
    hal_s32_t* counts; hal_float_t* position; hal_bit_t* reset;
    hal_float_t scale; hal_s32_t absolute, precision, last;       // parameters
};
struct LedPins { int code; hal_bit_t* in; hal_bit_t invert; int sent; };

class InputDevice {
public:
    InputDevice(InputSpec spec, int number) : spec_(std::move(spec)), number_(number) {}
    ~InputDevice();
    InputDevice(const InputDevice&) = delete;
    InputDevice& operator=(const InputDevice&) = delete;

    // Opens the device (grabbing it for '+') and makes its pins. 0 or -errno with a
    // one-line message.
    int open_and_export(const DeviceInfo& d, int comp_id);
    // One cycle: read pending events into the pins, drive the LEDs; notices unplugging.
    void update();
    // Unplugged: look for the device again (cheap to call; scans at most once a second).
    void try_reopen();
    bool is_present() const { return fd_ >= 0; }

private:
    int open_device(const DeviceInfo& d);
    void read_initial_state();
    void handle(int type, int code, int value);
    void gone(const char* why);

    InputSpec spec_;
    int number_;
    int fd_ = -1;
    std::string devnode_;
    long long next_scan_ms_ = 0;
    std::vector<KeyPins*> keys_;
    std::vector<AbsPins*> abs_;
    std::vector<RelPins*> rel_;
    std::vector<LedPins*> leds_;
};

}  // namespace hal::input
