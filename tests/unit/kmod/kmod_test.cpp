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
    EXPECT_EQ(bad.error().message, "HAL_FLAVOR='rtai': must be kernel or sim");
    setenv("HAL_FLAVOR", "kernel", 1);
    EXPECT_EQ(hal::kmod::detect_flavor()->flavor, hal::kmod::Flavor::kmod);
    setenv("HAL_FLAVOR", "sim", 1);
    EXPECT_EQ(hal::kmod::detect_flavor()->flavor, hal::kmod::Flavor::uspace);
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

// --- load_module / unload_module: the checks made before the helper runs ---

// A fake .ko: only its modinfo strings matter to declared_params().
void write_fake_ko(const std::string& name)
{
    mkdir((dir + "/modules").c_str(), 0755);
    std::ofstream f(dir + "/modules/" + name + ".ko", std::ios::binary);
    using namespace std::string_literals;
    f << "\0\x7f" "ELF junk\0parm=count:number\0parmtype=count:int\0"s
      << "parmtype=names:array of charp\0name="s << name << '\0';
}

class KmodModules : public Kmod {
protected:
    void SetUp() override
    {
        Kmod::SetUp();
        write_fake_ko("and2");
        write_fake_ko("broken");
        setenv("HAL_KMOD_DIR", (dir + "/modules").c_str(), 1);
    }
    void TearDown() override
    {
        unsetenv("HAL_KMOD_DIR");
        Kmod::TearDown();
    }
};

TEST_F(KmodModules, DeclaredParamsFromModinfo)
{
    auto p = hal::kmod::declared_params(dir + "/modules/and2.ko");
    ASSERT_TRUE(p) << p.error().message;
    EXPECT_EQ(*p, (std::vector<std::string>{"count", "names"}));
    EXPECT_FALSE(hal::kmod::declared_params(dir + "/modules/none.ko"));
}

TEST_F(KmodModules, MissingModuleWordedAsInTheSimulatedFlavor)
{
    auto r = hal::kmod::load_module("nosuch", {});
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, -ENOENT);
    EXPECT_EQ(r.error().message, "nosuch: no such realtime module (nosuch.ko is not in the module directory)");
    EXPECT_EQ(read_log(), "");
    EXPECT_FALSE(hal::kmod::load_module("rtapi", {}));   // not a component
    EXPECT_EQ(hal::kmod::load_module("Bad/name", {}).error().message,
              "Bad/name: invalid module name (use 1 to 31 of a-z, 0-9 and _)");
}

TEST_F(KmodModules, UndeclaredParameterIsRefusedBeforeInsmod)
{
    auto r = hal::kmod::load_module("and2", {"count=1", "bogus=3"});
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().message, "and2: unknown parameter 'bogus'");
    EXPECT_EQ(read_log(), "");
    EXPECT_EQ(hal::kmod::load_module("and2", {"count"}).error().message,
              "and2: parameter 'count' has no value (use count=VALUE)");
}

TEST_F(KmodModules, LoadPassesArgumentsQuotingBlanks)
{
    if (hal::kmod::module_loaded("rtapi"))
        GTEST_SKIP() << "rtapi.ko is loaded on this machine";
    auto r = hal::kmod::load_module("and2", {"names=a b", "count=2"});
    ASSERT_TRUE(r) << r.error().message;
    EXPECT_EQ(read_log(), "insert rtapi\ninsert hal_lib\ninsert and2 names=\"a b\" count=2 "
                          "hal_loadrt_args=\"names='a b' count=2\"\n");
}

TEST_F(KmodModules, FailedInsertWithoutRingCarriesTheHelperMessage)
{
    if (hal::kmod::module_loaded("rtapi"))
        GTEST_SKIP() << "rtapi.ko is loaded on this machine";
    auto r = hal::kmod::load_module("broken", {"count=0"});
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().message, "broken: insmod: ERROR: could not insert module: Invalid parameters");
}

TEST_F(KmodModules, UnloadOfAModuleNotLoaded)
{
    auto r = hal::kmod::unload_module("and2");
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().message, "and2: not loaded");
    EXPECT_TRUE(hal::kmod::unload_module("all"));    // nothing loaded: nothing to do
    EXPECT_EQ(read_log(), "");
}

}  // namespace
