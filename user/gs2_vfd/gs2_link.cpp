// SPDX-License-Identifier: GPL-2.0-or-later
// gs2_link.cpp - Gs2Link: libmodbus RTU with reconnection; see gs2_link.hpp.
#include "gs2_link.hpp"

#include <cerrno>

namespace hal::gs2 {

int Gs2Link::open()
{
    if (ctx_)
        return 0;
    modbus_t* ctx = modbus_new_rtu(opts_.device.c_str(), opts_.rate, opts_.parity, opts_.bits, opts_.stopbits);
    if (!ctx)
        return -(errno ? errno : EINVAL);
    modbus_set_debug(ctx, opts_.debug ? TRUE : FALSE);
    modbus_set_response_timeout(ctx, 0, 500000);     // a GS2 answers within a few ms
    if (modbus_set_slave(ctx, opts_.target) < 0 || modbus_connect(ctx) < 0) {
        int e = errno ? errno : EIO;
        modbus_free(ctx);
        return -e;
    }
    ctx_ = ctx;
    return 0;
}

void Gs2Link::close()
{
    if (!ctx_)
        return;
    modbus_close(ctx_);
    modbus_free(ctx_);
    ctx_ = nullptr;
}

int Gs2Link::failed()
{
    int e = errno ? errno : EIO;
    // A timeout or a Modbus exception/CRC error leaves the port usable; anything else
    // (EIO, ENXIO, EBADF: the device went away) means reopen.
    if (e != ETIMEDOUT && e < MODBUS_ENOBASE) {
        close();
    } else if (ctx_) {
        modbus_flush(ctx_);
    }
    return -e;
}

int Gs2Link::read_registers(int addr, int count, uint16_t* out)
{
    if (int rc = open(); rc < 0)
        return rc;
    errno = 0;
    if (modbus_read_registers(ctx_, addr, count, out) != count)
        return failed();
    return 0;
}

int Gs2Link::write_register(int addr, uint16_t value)
{
    if (int rc = open(); rc < 0)
        return rc;
    errno = 0;
    if (modbus_write_register(ctx_, addr, value) != 1)
        return failed();
    return 0;
}

}  // namespace hal::gs2
