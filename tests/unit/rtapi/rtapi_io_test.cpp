// SPDX-License-Identifier: GPL-2.0-or-later
// rtapi_io_test - I/O regions: refused with one clear line when the process may not do
// port I/O, refused when overlapping a held region. No port is ever read or written.
#include <unistd.h>

#include <gtest/gtest.h>

#include "rtapi.h"

namespace {

// In a child that has given up root (and so CAP_SYS_RAWIO), every request is refused.
TEST(RtapiIoDeathTest, RequestWithoutIoPermissionIsRefused)
{
    EXPECT_EXIT(
        {
            if (geteuid() == 0 && setuid(65534) != 0)
                _exit(3);
            _exit(rtapi_request_region(0x378, 3, "parport") == nullptr ? 0 : 1);
        },
        testing::ExitedWithCode(0),
        "rtapi: request_region 0x378\\+3 for 'parport' refused: this process may not do port I/O "
        "\\(needs root / CAP_SYS_RAWIO\\)");
}

TEST(RtapiIo, EmptyOrWrappingRangesAreRefused)
{
    testing::internal::CaptureStderr();
    EXPECT_EQ(rtapi_request_region(0x300, 0, "none"), nullptr);
    EXPECT_EQ(rtapi_request_region(~0UL, 2, "wrap"), nullptr);
    std::string err = testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("rtapi: request_region 0x300+0 for 'none' refused: empty or wrapping range\n"),
              std::string::npos) << err;
}

// Only where this process may do port I/O (root with CAP_SYS_RAWIO on x86).
TEST(RtapiIo, OverlappingRequestsAreRefused)
{
    testing::internal::CaptureStderr();
    void* held = rtapi_request_region(0x2f8, 8, "first");  // a COM port range; never touched
    std::string err = testing::internal::GetCapturedStderr();
    if (!held)
        GTEST_SKIP() << "no port I/O permission here: " << err;
    testing::internal::CaptureStderr();
    EXPECT_EQ(rtapi_request_region(0x2fc, 2, "second"), nullptr);
    err = testing::internal::GetCapturedStderr();
    EXPECT_EQ(err, "rtapi: request_region 0x2fc+2 for 'second' refused: overlaps 0x2f8+8 held by 'first'\n");
    rtapi_release_region(0x2f8, 8);
    void* again = rtapi_request_region(0x2fc, 2, "second");
    EXPECT_NE(again, nullptr);
    rtapi_release_region(0x2fc, 2);
}

}  // namespace
