// SPDX-License-Identifier: GPL-2.0-or-later
// kmod_test.cpp - hal::kmod with a fake emc_module_helper (EMC_MODULE_HELPER): the
// calls it makes, and how its refusals and failures come back as hal::Error.
#include "hal/kmod.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <sys/stat.h>

namespace {

const std::string dir = KMOD_TEST_DIR;
const std::string fake = dir + "/fake_helper";
const std::string log = dir + "/fake_helper.log";

// A helper that logs its arguments, refuses "evil" (exit 2) and fails "broken" (exit 1).
void write_fake()
{
    std::ofstream f(fake);
    f << "#!/bin/sh\n"
         "echo \"$*\" >> '" << log << "'\n"
         "case \"$2\" in\n"
         "evil) echo 'emc_module_helper: evil: not a HAL realtime module' >&2; exit 2;;\n"
         "broken) echo 'insmod: ERROR: could not insert module: Invalid parameters' >&2; exit 1;;\n"
         "esac\nexit 0\n";
    f.close();
    chmod(fake.c_str(), 0755);
}

std::string read_log()
{
    std::ifstream f(log);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

class Kmod : public ::testing::Test {
protected:
    void SetUp() override
    {
        write_fake();
        std::remove(log.c_str());
        setenv("EMC_MODULE_HELPER", fake.c_str(), 1);
    }
    void TearDown() override
    {
        unsetenv("EMC_MODULE_HELPER");
        unsetenv("HAL_FLAVOR");
    }
};

TEST_F(Kmod, HelperPathFromEnvironment)
{
    EXPECT_EQ(hal::kmod::helper_path(), fake);
}

TEST_F(Kmod, LoadInsertsCoreModulesFirstWhenMissing)
{
    if (hal::kmod::module_loaded("rtapi"))
        GTEST_SKIP() << "rtapi.ko is loaded on this machine";
    auto r = hal::kmod::load("and2", {"count=2", "names=a,b"});
    ASSERT_TRUE(r) << r.error().message;
    EXPECT_EQ(read_log(), "insert rtapi\ninsert hal_lib\ninsert and2 count=2 names=a,b\n");
}

TEST_F(Kmod, RefusalBecomesEperm)
{
    auto r = hal::kmod::load("evil");
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, -EPERM);
    EXPECT_EQ(r.error().message, "loadrt evil: emc_module_helper: evil: not a HAL realtime module");
}

TEST_F(Kmod, InsmodFailureCarriesItsMessage)
{
    auto r = hal::kmod::load("broken", {"count=0"});
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, -EIO);
    EXPECT_NE(r.error().message.find("Invalid parameters"), std::string::npos);
}

TEST_F(Kmod, UnloadRemoves)
{
    ASSERT_TRUE(hal::kmod::unload("and2"));
    EXPECT_EQ(read_log(), "remove and2\n");
    auto r = hal::kmod::unload("evil");
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().message, "unloadrt evil: emc_module_helper: evil: not a HAL realtime module");
}

TEST_F(Kmod, MissingHelperIsAnError)
{
    setenv("EMC_MODULE_HELPER", (dir + "/no-such-helper").c_str(), 1);
    auto r = hal::kmod::unload("and2");
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().message.find("cannot run"), std::string::npos);
}

TEST_F(Kmod, FlavorFromEnvironment)
{
    setenv("HAL_FLAVOR", "kmod", 1);
    auto k = hal::kmod::detect_flavor();
    ASSERT_TRUE(k);
    EXPECT_EQ(k->flavor, hal::kmod::Flavor::kmod);
    setenv("HAL_FLAVOR", "uspace", 1);
    auto u = hal::kmod::detect_flavor();
    ASSERT_TRUE(u);
    EXPECT_EQ(u->flavor, hal::kmod::Flavor::uspace);
    setenv("HAL_FLAVOR", "rtai", 1);
    auto bad = hal::kmod::detect_flavor();
    ASSERT_FALSE(bad);
    EXPECT_EQ(bad.error().message, "HAL_FLAVOR='rtai': must be kmod or uspace");
}

TEST_F(Kmod, FlavorDefaultsToUspaceWithoutModules)
{
    if (hal::kmod::module_loaded("rtapi"))
        GTEST_SKIP() << "rtapi.ko is loaded on this machine";
    auto f = hal::kmod::detect_flavor();
    ASSERT_TRUE(f);
    if (f->flavor == hal::kmod::Flavor::kmod)	// a machine with the modules installed
        EXPECT_NE(f->reason.find("installed"), std::string::npos) << f->reason;
    else
        EXPECT_NE(f->reason.find("no kernel modules"), std::string::npos) << f->reason;
}

}  // namespace
