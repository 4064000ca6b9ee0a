// SPDX-License-Identifier: GPL-2.0-or-later
// gen_test.cpp - the generated C (names, defaults, macros) and man page. Whether the
// C compiles and runs is proven by the HAL-level tests (tests/comp, tests/lowpass ...).
#include <gtest/gtest.h>

#include "gen_c.hpp"
#include "gen_doc.hpp"
#include "parser.hpp"

using namespace hal::comp;

namespace {

Component parse(const std::string& text)
{
    auto c = parse_comp(text, "x.comp");
    EXPECT_TRUE(c.has_value()) << (c ? "" : c.error().message);
    return c ? *c : Component{};
}

bool contains(const std::string& hay, const std::string& needle)
{
    return hay.find(needle) != std::string::npos;
}

const char* kConv =
    "component conv_bit_s32 \"Convert a value from bit to s32\";\n"
    "pin in bit in_;\npin out s32 out;\n"
    "function _ nofp \"Update 'out' based on 'in'\";\nlicense \"GPL\";\n;;\n"
    "FUNCTION(_) { out = in_; }\n";

}  // namespace

TEST(CompGenerate, PrefixUsesDashesAndFunctionIsThePrefix)
{
    std::string c = generate_c(parse(kConv));
    EXPECT_TRUE(contains(c, "\"conv-bit-s32.%d\", i)"));
    EXPECT_TRUE(contains(c, "hal_init(\"conv_bit_s32\")"));
    EXPECT_TRUE(contains(c, "hal_pin_bit_newf(HAL_IN, &inst->in_, comp_id, \"%s.in\", prefix)"));
    EXPECT_TRUE(contains(c, "rtapi_snprintf(buf, sizeof(buf), \"%s\", prefix)"));
    EXPECT_TRUE(contains(c, "hal_export_funct(buf, __comp_funct__, inst, 0, 0, comp_id)"));
    EXPECT_TRUE(contains(c, "#define in_ (0+*__comp_inst->in_)"));   // inputs are rvalues
    EXPECT_TRUE(contains(c, "#define out (*__comp_inst->out)"));
    EXPECT_TRUE(contains(c, "#line 7 \"x.comp\"\nFUNCTION(_)"));
    EXPECT_TRUE(contains(c, "MODULE_LICENSE(\"GPL\");"));
    EXPECT_TRUE(contains(c, "count= and names= are mutually exclusive"));
    EXPECT_FALSE(contains(c, "#include <"));  // realtime: no libc headers
}

TEST(CompGenerate, NamedFunctionsArraysAndDefaults)
{
    std::string c = generate_c(parse(
        "component m;\npin out bit out-#[8];\npin in float x = 1.5;\n"
        "param rw bit flag = TRUE;\nvariable double last = 0.25;\n"
        "function update_freq fp;\nlicense \"GPL\";\n;;\n"));
    EXPECT_TRUE(contains(c, "\"%s.update-freq\", prefix"));
    EXPECT_TRUE(contains(c, "hal_export_funct(buf, __comp_funct_update_freq, inst, 1, 0, comp_id)"));
    EXPECT_TRUE(contains(c, "hal_bit_t *out[8];"));
    EXPECT_TRUE(contains(c, "\"%s.out-%01d\", prefix, j)"));
    EXPECT_TRUE(contains(c, "#define out(i) (*(__comp_inst->out[i]))"));
    // float defaults are stored as bit patterns: no FP instructions in init code
    EXPECT_TRUE(contains(c, "rtapi_store_u64((volatile __u64 *)&(*inst->x), 0x3ff8000000000000ULL)"));
    EXPECT_TRUE(contains(c, "inst->flag = 1;"));
    EXPECT_TRUE(contains(c, "0x3fd0000000000000ULL"));  // 0.25
}

TEST(CompGenerate, SingletonPersonalityAndOptions)
{
    std::string s = generate_c(parse(
        "component charge_pump;\noption singleton yes;\npin out bit out;\nfunction _ nofp;\n"
        "license \"GPL\";\n;;\n"));
    EXPECT_TRUE(contains(s, "\"%s\", \"charge-pump\""));
    EXPECT_FALSE(contains(s, "RTAPI_MP_INT(count"));
    std::string p = generate_c(parse(
        "component logic;\noption personality;\noption extra_setup;\noption extra_cleanup;\n"
        "pin in bit in-##[16 : personality & 0xff];\npin out bit and if personality & 0x100;\n"
        "modparam int depth = 3 \"d\";\nfunction _ nofp;\nlicense \"GPL\";\n;;\n"));
    EXPECT_TRUE(contains(p, "#define __COMP_MAX_PERSONALITIES 64\n"));
    EXPECT_TRUE(contains(p, "RTAPI_MP_ARRAY_INT(personality, __COMP_MAX_PERSONALITIES"));
    EXPECT_TRUE(contains(p, "for (j = 0; j < (personality & 0xff); j++)"));
    EXPECT_TRUE(contains(p, "if (personality & 0x100) {"));
    EXPECT_TRUE(contains(p, "r = extra_setup(inst, prefix, extra_arg);"));
    EXPECT_TRUE(contains(p, "\textra_cleanup();\n\thal_exit(comp_id);"));
    EXPECT_TRUE(contains(p, "static int depth = 3;\nRTAPI_MP_INT(depth, \"d\");"));
}

TEST(CompGenerate, LoneFunctionBodyWithoutFunctionMacroIsWrapped)
{
    std::string body = generate_c(parse(
        "component twice;\npin in s32 in;\npin out s32 out;\nfunction _ nofp;\nlicense \"GPL\";\n;;\n"
        "out = 2 * in;\n"));
    EXPECT_TRUE(contains(body, "FUNCTION(_) {\n#line 7 "));
    EXPECT_TRUE(contains(body, "out = 2 * in;\n}\n"));
    std::string full = generate_c(parse(
        "component twice;\npin out s32 out;\nfunction _ nofp;\nlicense \"GPL\";\n;;\n"
        "FUNCTION(_) { out = 2; }\n"));
    EXPECT_FALSE(contains(full, "FUNCTION(_) {\n#line"));
}

TEST(CompGenerate, UserspaceHasMainAndNoModuleParams)
{
    std::string u = generate_c(parse(
        "component ui;\noption userspace;\noption userinit;\npin out s32 n;\nlicense \"GPL\";\n;;\n"));
    EXPECT_TRUE(contains(u, "int main(int argc_, char **argv_)"));
    EXPECT_TRUE(contains(u, "userinit(argc, argv);"));
    EXPECT_TRUE(contains(u, "user_mainloop();"));
    EXPECT_FALSE(contains(u, "RTAPI_MP_"));
    EXPECT_FALSE(contains(u, "rtapi_app.h"));
}

TEST(CompGenerate, FloatBitsOnlyForNumbers)
{
    unsigned long long b = 0;
    EXPECT_TRUE(float_bits("1.0", &b));
    EXPECT_EQ(b, 0x3ff0000000000000ULL);
    EXPECT_TRUE(float_bits("-2", &b));
    EXPECT_EQ(b, 0xc000000000000000ULL);
    EXPECT_TRUE(float_bits("0x10", &b));
    EXPECT_EQ(b, 0x4030000000000000ULL);
    EXPECT_FALSE(float_bits("M_PI", &b));
}

TEST(CompDocument, ManPageHasTheReferenceSections)
{
    Component c = parse(
        "component logic \"Experimental logic\";\noption personality;\n"
        "pin in bit in-##[16 : personality & 0xff];\npin out bit and if personality & 0x100;\n"
        "param rw float gain = 1.0 \"the gain\";\n"
        "function _ nofp \"Do it\";\ndescription \"Long text\";\nauthor \"Me\";\nlicense \"GPL\";\n;;\n");
    std::string d = generate_doc(c, "2011-08-27");
    EXPECT_TRUE(contains(d, ".TH LOGIC \"9\" \"2011-08-27\" \"EMC Documentation\" \"HAL Component\""));
    EXPECT_TRUE(contains(d, ".SH NAME\nlogic \\- Experimental logic\n"));
    EXPECT_EQ(synopsis_text(c), "loadrt logic [count=N|names=name1[,name2...]] [personality=P,P,...]");
    EXPECT_TRUE(contains(d, ".SH FUNCTIONS\n.TP\n\\fBlogic.\\fIN\\fB\\fR\nDo it\n"));
    EXPECT_TRUE(contains(d, ".B logic.\\fIN\\fB.in-MM\\fR bit in (MM=00..personality & 0xff)"));
    EXPECT_TRUE(contains(d, ".B logic.\\fIN\\fB.and\\fR bit out [if personality & 0x100]"));
    EXPECT_TRUE(contains(d, ".SH PARAMETERS\n.TP\n.B logic.\\fIN\\fB.gain\\fR float rw (default: \\fI1.0\\fR)\nthe gain\n"));
    EXPECT_TRUE(contains(d, ".SH DESCRIPTION\nLong text\n"));
    EXPECT_TRUE(contains(d, ".SH AUTHOR\nMe\n"));
    EXPECT_TRUE(contains(d, ".SH LICENSE\nGPL\n"));
}

TEST(CompDocument, SynopsisOfSingletonAndUserspace)
{
    EXPECT_EQ(synopsis_text(parse("component charge_pump;\noption singleton;\nfunction _;\n;;\n")),
              "loadrt charge_pump");
    EXPECT_EQ(synopsis_text(parse("component ui;\noption userspace;\n;;\n")), "loadusr ui");
}
