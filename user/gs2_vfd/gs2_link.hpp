// SPDX-License-Identifier: GPL-2.0-or-later
// gs2_link.hpp - the Modbus RTU connection to one GS2 drive through libmodbus: opened
// lazily, closed after a serial error (device gone, I/O error) and opened again on
// the next poll, so an unplugged cable or a USB adapter that comes back does not
// end the component.
#pragma once

#include <modbus.h>

#include <cstdint>
#include <string>

#include "gs2_options.hpp"

namespace hal::gs2 {

class Gs2Link {
public:
    explicit Gs2Link(const Gs2Options& o) : opts_(o) {}
    ~Gs2Link() { close(); }
    Gs2Link(const Gs2Link&) = delete;
    Gs2Link& operator=(const Gs2Link&) = delete;

    // Each returns 0 or a negative errno (libmodbus's codes included); a serial error
    // closes the connection so that the next call reopens it.
    int read_registers(int addr, int count, uint16_t* out);
    int write_register(int addr, uint16_t value);
    bool is_open() const { return ctx_ != nullptr; }
    // Drops the connection: the caller re-sends its commands after reopening.
    void close();

private:
    int open();
    int failed();      // classify errno after a failed call

    Gs2Options opts_;
    modbus_t* ctx_ = nullptr;
};

}  // namespace hal::gs2
