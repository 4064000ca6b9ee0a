// SPDX-License-Identifier: GPL-2.0-or-later
// rtapi_iosim_test - simulated port ranges: accesses reach the device (wide ones as
// bytes, lowest address first), claims inside a device are granted once, straddling
// claims are refused, an unregistered but claimed range never reaches hardware, and
// hal_parport_get claims a simulated port with its probed high range.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "rtapi.h"
#include "rtapi_iosim.h"
#include "hal_parport.h"

namespace {

struct Dev {
    unsigned char regs[8] = {};
    std::vector<std::string> log;
};

unsigned char dev_inb(void* d, unsigned int off)
{
    auto* dev = static_cast<Dev*>(d);
    dev->log.push_back("r" + std::to_string(off));
    return dev->regs[off];
}

void dev_outb(void* d, unsigned int off, unsigned char b)
{
    auto* dev = static_cast<Dev*>(d);
    dev->log.push_back("w" + std::to_string(off) + "=" + std::to_string(b));
    dev->regs[off] = b;
}

const rtapi_iosim_ops ops = {dev_inb, dev_outb};

TEST(RtapiIosim, AccessesReachTheDeviceAndWideOnesAreSplit)
{
    Dev dev;
    int h = rtapi_iosim_register(0x7000, 8, &ops, &dev, "dev");
    ASSERT_GE(h, 0);
    rtapi_outb(0x12, 0x7001);
    EXPECT_EQ(rtapi_inb(0x7001), 0x12);
    rtapi_outl(0x44332211u, 0x7004);
    EXPECT_EQ(rtapi_inw(0x7004), 0x2211);
    EXPECT_EQ(rtapi_inl(0x7004), 0x44332211u);
    std::vector<std::string> want = {"w1=18", "r1", "w4=17", "w5=34", "w6=51", "w7=68",
                                     "r4", "r5", "r4", "r5", "r6", "r7"};
    EXPECT_EQ(dev.log, want);
    rtapi_iosim_unregister(h);
}

TEST(RtapiIosim, OverlappingDevicesAreRefused)
{
    Dev a, b;
    int h = rtapi_iosim_register(0x7100, 8, &ops, &a, "a");
    ASSERT_GE(h, 0);
    testing::internal::CaptureStderr();
    EXPECT_EQ(rtapi_iosim_register(0x7104, 8, &ops, &b, "b"), -EBUSY);
    std::string err = testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("simulated device 'b' at 0x7104+8 overlaps 'a' at 0x7100+8"),
              std::string::npos) << err;
    rtapi_iosim_unregister(h);
}

TEST(RtapiIosim, ClaimsAreExclusiveAndMayNotStraddle)
{
    Dev dev;
    int h = rtapi_iosim_register(0x7200, 8, &ops, &dev, "dev");
    ASSERT_GE(h, 0);
    EXPECT_NE(rtapi_request_region(0x7200, 8, "drv"), nullptr);
    testing::internal::CaptureStderr();
    EXPECT_EQ(rtapi_request_region(0x7202, 2, "other"), nullptr);
    EXPECT_EQ(rtapi_request_region(0x71fc, 8, "edge"), nullptr);
    std::string err = testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("simulated device 'dev' is in use by 'drv'"), std::string::npos) << err;
    EXPECT_NE(err.find("straddles simulated device 'dev'"), std::string::npos) << err;
    rtapi_release_region(0x7200, 8);
    EXPECT_NE(rtapi_request_region(0x7202, 2, "other"), nullptr);
    rtapi_release_region(0x7202, 2);
    rtapi_iosim_unregister(h);
}

TEST(RtapiIosim, ClaimedRangeOutlivesItsDeviceWithoutReachingHardware)
{
    Dev dev;
    int h = rtapi_iosim_register(0x7300, 8, &ops, &dev, "dev");
    ASSERT_GE(h, 0);
    ASSERT_NE(rtapi_request_region(0x7300, 8, "drv"), nullptr);
    rtapi_iosim_unregister(h);
    dev.log.clear();
    EXPECT_EQ(rtapi_inb(0x7300), 0xff);  // no port I/O permission: real inb would crash
    rtapi_outb(1, 0x7300);
    EXPECT_TRUE(dev.log.empty());
    rtapi_release_region(0x7300, 8);
}

TEST(HalParport, GetClaimsASimulatedPortAndItsProbedHighRange)
{
    Dev lo, hi;
    int hl = rtapi_iosim_register(0x7400, 8, &ops, &lo, "lo");
    int hh = rtapi_iosim_register(0x7800, 3, &ops, &hi, "hi");
    ASSERT_GE(hl, 0);
    ASSERT_GE(hh, 0);
    hal_parport_t port;
    ASSERT_EQ(hal_parport_get(5, &port, 0x7400, 0, 0), 0);
    EXPECT_EQ(port.base, 0x7400);
    EXPECT_EQ(port.base_hi, 0x7800);
    hal_parport_t second;
    testing::internal::CaptureStderr();
    EXPECT_EQ(hal_parport_get(6, &second, 0x7400, 0, 0), -EBUSY);
    std::string err = testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("in use by 'hal_parport(comp 5)'"), std::string::npos) << err;
    hal_parport_release(&port);
    ASSERT_EQ(hal_parport_get(6, &second, 0x7400, (unsigned short)-1, 0), 0);
    EXPECT_EQ(second.base_hi, 0);  // -1: no high range wanted
    hal_parport_release(&second);
    rtapi_iosim_unregister(hh);
    rtapi_iosim_unregister(hl);
}

}  // namespace
