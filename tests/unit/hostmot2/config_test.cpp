// The hostmot2 config string parser (hm2_config.c): every keyword, every refusal.
#include <gtest/gtest.h>
#include <string>

extern "C" {
#include "hm2_config.h"
}

namespace {

struct Parsed {
    int rc;
    hm2_config cfg;
    std::string err;
};

Parsed parse(const char *s)
{
    Parsed p{};
    char err[200] = "";
    p.rc = hm2_config_parse(s, &p.cfg, err, sizeof err);
    p.err = err;
    return p;
}

TEST(Hm2Config, Defaults)
{
    for (const char *s : {static_cast<const char *>(nullptr), "", "   \t "}) {
        Parsed p = parse(s);
        ASSERT_EQ(p.rc, 0);
        for (int k = 0; k < HM2_NUM_KEYS; k++)
            EXPECT_EQ(p.cfg.num[k], -1) << hm2_config_count_name(static_cast<hm2_count_key>(k));
        EXPECT_EQ(p.cfg.stepgen_width, 2);
        EXPECT_EQ(p.cfg.enable_raw, 0);
        EXPECT_EQ(p.cfg.firmware[0], 0);
        EXPECT_EQ(p.cfg.num_sserials, 0);
    }
}

TEST(Hm2Config, EveryCountKeyword)
{
    for (int k = 0; k < HM2_NUM_KEYS; k++) {
        std::string s = std::string(hm2_config_count_name(static_cast<hm2_count_key>(k))) + "=3";
        Parsed p = parse(s.c_str());
        ASSERT_EQ(p.rc, 0) << s << ": " << p.err;
        EXPECT_EQ(p.cfg.num[k], 3) << s;
    }
    Parsed p = parse("num_encoders=0x2 num_stepgens=-1 num_pwmgens=0");
    ASSERT_EQ(p.rc, 0) << p.err;
    EXPECT_EQ(p.cfg.num[HM2_NUM_ENCODERS], 2);
    EXPECT_EQ(p.cfg.num[HM2_NUM_STEPGENS], -1);
    EXPECT_EQ(p.cfg.num[HM2_NUM_PWMGENS], 0);
}

TEST(Hm2Config, OtherKeywords)
{
    Parsed p = parse("firmware=hm2/5i20/SVST8_4.BIT stepgen_width=6 enable_raw "
                     "sserial_port_0=0120xxxx sserial_port_2=1 ssi_chan_3=pos%24g "
                     "biss_chan_0=x%32u fanuc_chan_31=AA64");
    ASSERT_EQ(p.rc, 0) << p.err;
    EXPECT_STREQ(p.cfg.firmware, "hm2/5i20/SVST8_4.BIT");
    EXPECT_EQ(p.cfg.stepgen_width, 6);
    EXPECT_EQ(p.cfg.enable_raw, 1);
    EXPECT_STREQ(p.cfg.sserial_modes[0], "0120xxxx");
    EXPECT_STREQ(p.cfg.sserial_modes[2], "1");
    EXPECT_EQ(p.cfg.num_sserials, 3);
    EXPECT_STREQ(p.cfg.ssi_format[3], "pos%24g");
    EXPECT_STREQ(p.cfg.biss_format[0], "x%32u");
    EXPECT_STREQ(p.cfg.fanuc_format[31], "AA64");
}

TEST(Hm2Config, Refusals)
{
    struct Case {
        const char *in, *msg;
    } cases[] = {
        {"num_encoder=2", "config: unknown keyword 'num_encoder=2' (see hostmot2(9), config modparam)"},
        {"num_encoders", "config: unknown keyword 'num_encoders' (see hostmot2(9), config modparam)"},
        {"num_encoders=", "config: 'num_encoders=' needs a number"},
        {"num_encoders=two", "config: 'num_encoders=two': expected an integer -1..1000"},
        {"num_encoders=3x", "config: 'num_encoders=3x': expected an integer -1..1000"},
        {"num_pwmgens=-2", "config: 'num_pwmgens=-2': expected an integer -1..1000"},
        {"stepgen_width=9", "config: 'stepgen_width=9': expected an integer 0..8"},
        {"enable_raw=1", "config: unknown keyword 'enable_raw=1' (see hostmot2(9), config modparam)"},
        {"firmware=", "config: 'firmware=': the firmware name must be 1..30 characters"},
        {"firmware=hm2/5i20/a_very_long_firmware_name.BIT",
         "config: 'firmware=hm2/5i20/a_very_long_firmware_name.BIT': the firmware name must be 1..30 characters"},
        {"sserial_port_4=0", "config: 'sserial_port_4=0': expected sserial_port_N=MODES with N 0..3"},
        {"sserial_port_0=012345678", "config: 'sserial_port_0=012345678': 1..8 mode characters expected"},
        {"sserial_port_1=01y", "config: 'sserial_port_1=01y': mode 'y' is not 0-9 or x"},
        {"ssi_chan_32=a%1b", "config: 'ssi_chan_32=a%1b': expected ssi_chan_N=FORMAT with N 0..31"},
        {"biss_chan_x=a%1b", "config: 'biss_chan_x=a%1b': expected biss_chan_N=FORMAT with N 0..31"},
        {"fanuc_chan_1=", "config: 'fanuc_chan_1=': the format must be 1..63 characters"},
        {"ssi_chan_1=a%1b ssi_chan_1=b%1b", "config: 'ssi_chan_1=b%1b': channel 1 is given twice"},
    };
    for (const auto &c : cases) {
        Parsed p = parse(c.in);
        EXPECT_EQ(p.rc, -EINVAL) << c.in;
        EXPECT_EQ(p.err, c.msg) << c.in;
    }
    std::string longtok(200, 'a');
    Parsed p = parse(longtok.c_str());
    EXPECT_EQ(p.rc, -EINVAL);
    EXPECT_NE(p.err.find("is longer than 128 characters"), std::string::npos) << p.err;
}

TEST(Hm2Config, InstancesAgainstFirmware)
{
    Parsed p = parse("num_encoders=3 num_stepgens=0");
    ASSERT_EQ(p.rc, 0);
    char err[200] = "";
    EXPECT_EQ(hm2_config_instances(&p.cfg, HM2_NUM_ENCODERS, 8, err, sizeof err), 3);
    EXPECT_EQ(hm2_config_instances(&p.cfg, HM2_NUM_STEPGENS, 4, err, sizeof err), 0);
    EXPECT_EQ(hm2_config_instances(&p.cfg, HM2_NUM_PWMGENS, 8, err, sizeof err), 8);
    EXPECT_EQ(hm2_config_instances(&p.cfg, HM2_NUM_ENCODERS, 2, err, sizeof err), -EINVAL);
    EXPECT_STREQ(err, "config: num_encoders=3, but the firmware has only 2");
}

}  // namespace
