// SPDX-License-Identifier: GPL-2.0-or-later
// split_test.cpp - a realtime component with floating-point functions is generated as
// two translation units (gen_c.cpp): each part is compiled here on its own, with the
// project's warnings, and the two are linked, so a part that needs something only the
// other defines fails. Covers what the tree's components do not all use: a nofp
// function beside fp ones, a default that only the FP part can compute (a macro of the
// user's code), extra_setup/extra_cleanup/get_count and module parameters.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "gen_c.hpp"
#include "parser.hpp"

using namespace hal::comp;
namespace fs = std::filesystem;

namespace {

const char* kMixed =
    "component fpmix \"x\";\npin in float in;\npin out float out = SCALE;\n"
    "param rw float gain = 2.0;\nvariable double acc = SCALE;\nmodparam int depth = 3 \"d\";\n"
    "option extra_setup yes;\noption extra_cleanup yes;\noption count_function yes;\n"
    "function update fp;\nfunction tick nofp;\nlicense \"GPL\";\n;;\n"
    "#define SCALE 0.5\n"
    "static int get_count(void) { return depth; }\n"
    "EXTRA_SETUP() { (void)__comp_inst; (void)prefix; (void)extra_arg; return 0; }\n"
    "EXTRA_CLEANUP() { }\n"
    "FUNCTION(update) { out = in * gain + acc; acc = acc + fperiod; }\n"
    "FUNCTION(tick) { (void)__comp_inst; (void)period; }\n";

const char* kIntOnly =
    "component intonly;\npin in bit a;\npin out bit b;\nfunction _ nofp;\nlicense \"GPL\";\n;;\n"
    "FUNCTION(_) { b = a; (void)period; }\n";

class Split : public ::testing::Test {
protected:
    void SetUp() override
    {
        dir_ = fs::temp_directory_path() / ("comp_split_" + std::to_string(::getpid()));
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    fs::path write(const std::string& name, const char* text)
    {
        auto c = parse_comp(text, name + ".comp");
        EXPECT_TRUE(c.has_value());
        fs::path p = dir_ / (name + ".c");
        std::ofstream(p) << generate_c(*c);
        return p;
    }
    // cc with the realtime flags of the simulated flavor plus 'extra'; exit status
    int cc(const std::string& extra)
    {
        std::string cmd = "cc -std=gnu11 -Wall -Wextra -Werror -fPIC -DRTAPI -I" HAL_SOURCE_DIR
                          "/kernel/rtapi -I" HAL_SOURCE_DIR "/kernel/hal " + extra + " 2>" +
                          (dir_ / "cc.err").string();
        int rc = std::system(cmd.c_str());
        std::ifstream f(dir_ / "cc.err");
        err_.assign(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
        return rc;
    }
    std::string run(const std::string& cmd) const
    {
        std::string out;
        if (FILE* f = ::popen(cmd.c_str(), "r")) {
            char buf[256];
            while (std::fgets(buf, sizeof(buf), f))
                out += buf;
            ::pclose(f);
        }
        return out;
    }
    fs::path dir_;
    std::string err_;  // the last cc's messages
};

}  // namespace

TEST_F(Split, EachPartCompilesAloneAndTheyLink)
{
    fs::path c = write("fpmix", kMixed);
    std::string d = dir_.string();
    ASSERT_EQ(cc("-c -D__COMP_PART_FP -o " + d + "/fp.o " + c.string()), 0) << err_;
    ASSERT_EQ(cc("-c -D__COMP_PART_GLUE -o " + d + "/glue.o " + c.string()), 0) << err_;
    ASSERT_EQ(cc("-c -o " + d + "/whole.o " + c.string()), 0) << err_;  // neither: both at once
    ASSERT_EQ(cc("-shared -o " + d + "/fpmix.so " + d + "/fp.o " + d + "/glue.o"), 0) << err_;
    // everything one part calls in the other is resolved inside the module
    std::string undef = run("nm -u " + d + "/fpmix.so");
    for (const char* sym : {"__comp_", "extra_setup", "extra_cleanup", "comp_id", "depth", "get_count"})
        EXPECT_EQ(undef.find(sym), std::string::npos) << sym << " unresolved:\n" << undef;
    // the user's code is in the FP part only; init/exit in the glue only
    std::string fp = run("nm " + d + "/fp.o"), glue = run("nm " + d + "/glue.o");
    EXPECT_NE(fp.find(" t update"), std::string::npos) << fp;
    EXPECT_EQ(glue.find(" t update"), std::string::npos) << glue;
    EXPECT_NE(glue.find(" T rtapi_app_main"), std::string::npos) << glue;
    EXPECT_EQ(fp.find("rtapi_app_main"), std::string::npos) << fp;
    EXPECT_NE(fp.find(" T __comp_defaults"), std::string::npos) << fp;  // SCALE: FP part only
}

TEST_F(Split, KernelBuildMustChooseAPart)
{
    fs::path mixed = write("fpmix", kMixed), ints = write("intonly", kIntOnly);
    // an FP component built whole for the kernel, or an integer one as an FP part: #error
    EXPECT_NE(cc("-E -D__KERNEL__ -o /dev/null " + mixed.string()), 0);
    EXPECT_NE(cc("-E -D__COMP_PART_FP -o /dev/null " + ints.string()), 0);
    EXPECT_EQ(cc("-E -o /dev/null " + ints.string()), 0);
}
