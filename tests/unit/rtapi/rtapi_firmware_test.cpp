// SPDX-License-Identifier: GPL-2.0-or-later
// rtapi_firmware_test - rtapi_request_firmware in the simulated flavor: names are
// checked, HAL_FIRMWARE_PATH's directories come first and in order, a missing file is
// -ENOENT without a message, the image is the file's bytes.
#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "rtapi.h"
#include "rtapi_firmware.h"

namespace {

namespace fs = std::filesystem;

class RtapiFirmware : public testing::Test {
protected:
    void SetUp() override
    {
        char tmpl[] = "/tmp/rtapi_fw_XXXXXX";
        ASSERT_NE(mkdtemp(tmpl), nullptr);
        dir_ = tmpl;
        fs::create_directories(dir_ / "a" / "pluto");
        fs::create_directories(dir_ / "b" / "pluto");
    }
    void TearDown() override
    {
        unsetenv("HAL_FIRMWARE_PATH");
        fs::remove_all(dir_);
    }
    void write(const fs::path& p, const std::string& bytes)
    {
        std::ofstream(p, std::ios::binary) << bytes;
    }
    fs::path dir_;
};

TEST_F(RtapiFirmware, FirstDirectoryOfThePathWins)
{
    write(dir_ / "b" / "pluto" / "x.rbf", std::string("b\0\xff", 3));
    std::string path = (dir_ / "missing").string() + ":" + (dir_ / "a").string() + ":" +
                       (dir_ / "b").string();
    setenv("HAL_FIRMWARE_PATH", path.c_str(), 1);
    const rtapi_firmware* fw = nullptr;
    ASSERT_EQ(rtapi_request_firmware(&fw, "pluto/x.rbf"), 0);
    EXPECT_EQ(std::string(reinterpret_cast<const char*>(fw->data), fw->size),
              std::string("b\0\xff", 3));
    rtapi_release_firmware(fw);

    write(dir_ / "a" / "pluto" / "x.rbf", "from a");
    ASSERT_EQ(rtapi_request_firmware(&fw, "pluto/x.rbf"), 0);
    EXPECT_EQ(std::string(reinterpret_cast<const char*>(fw->data), fw->size), "from a");
    rtapi_release_firmware(fw);
}

TEST_F(RtapiFirmware, MissingFileIsEnoentWithoutMessage)
{
    setenv("HAL_FIRMWARE_PATH", (dir_ / "a").c_str(), 1);
    const rtapi_firmware* fw = nullptr;
    testing::internal::CaptureStderr();
    EXPECT_EQ(rtapi_request_firmware(&fw, "pluto/hal-unit-test-no-such-image.rbf"), -ENOENT);
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

TEST_F(RtapiFirmware, AbsoluteAndDotDotNamesAreRefused)
{
    write(dir_ / "a" / "pluto" / "x.rbf", "x");
    setenv("HAL_FIRMWARE_PATH", (dir_ / "a" / "pluto").c_str(), 1);
    const rtapi_firmware* fw = nullptr;
    for (const char* bad : {"/etc/passwd", "../pluto/x.rbf", "pluto/../../x", "..", ""}) {
        testing::internal::CaptureStderr();
        EXPECT_EQ(rtapi_request_firmware(&fw, bad), -EINVAL) << bad;
        EXPECT_NE(testing::internal::GetCapturedStderr().find("must be relative"),
                  std::string::npos) << bad;
    }
    EXPECT_EQ(rtapi_request_firmware(&fw, "x.rbf"), 0);  // a plain name is fine
    rtapi_release_firmware(fw);
}

TEST_F(RtapiFirmware, DirectoryIsNotAnImage)
{
    setenv("HAL_FIRMWARE_PATH", dir_.c_str(), 1);
    const rtapi_firmware* fw = nullptr;
    testing::internal::CaptureStderr();
    EXPECT_EQ(rtapi_request_firmware(&fw, "a"), -EINVAL);
    EXPECT_NE(testing::internal::GetCapturedStderr().find("not a regular file"), std::string::npos);
}

}  // namespace
