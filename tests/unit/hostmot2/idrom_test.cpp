// The IDROM checks of hm2_idrom.c, in the documented order, each with its message.
#include <gtest/gtest.h>
#include <string>

extern "C" {
#include "hm2_idrom.h"
}

namespace {

struct Header {
    rtapi_u32 w[HM2_IDROM_WORDS] = {3,    0x40,       0x1C0,     0x4153454D, 0x30324935, 200, 208, 3,
                                    72,   24,         33333333,  100000000,  4,          0x40, 0x100, 0x100};
};

std::string parse(const Header &h, int ports = 3, int width = 24, int *rc = nullptr)
{
    hm2_board_shape shape{ports, width};
    hm2_idrom id{};
    char err[200] = "";
    int r = hm2_idrom_parse(h.w, &shape, &id, err, sizeof err);
    if (rc)
        *rc = r;
    return err;
}

TEST(Hm2Idrom, GoodHeaderDecodes)
{
    Header h;
    hm2_board_shape shape{3, 24};
    hm2_idrom id{};
    char err[200] = "";
    ASSERT_EQ(hm2_idrom_parse(h.w, &shape, &id, err, sizeof err), 0) << err;
    EXPECT_STREQ(id.board_name, "MESA5I20");
    EXPECT_EQ(id.io_width, 72u);
    EXPECT_EQ(id.clock_low, 33333333u);
    EXPECT_EQ(id.offset_to_pin_desc, 0x1C0u);
}

TEST(Hm2Idrom, CookieAndName)
{
    char err[200] = "";
    rtapi_u32 good[3] = {0x55AACAFE, 0x54534F48, 0x32544F4D};
    EXPECT_EQ(hm2_idrom_check_cookie(good, err, sizeof err), 0);
    rtapi_u32 nocookie[3] = {0, 0x54534F48, 0x32544F4D};
    EXPECT_EQ(hm2_idrom_check_cookie(nocookie, err, sizeof err), -EINVAL);
    EXPECT_NE(std::string(err).find("FPGA failed to initialize"), std::string::npos) << err;
    rtapi_u32 badname[3] = {0x55AACAFE, 0x54534F48, 0x33544F4D};
    EXPECT_EQ(hm2_idrom_check_cookie(badname, err, sizeof err), -EINVAL);
    EXPECT_NE(std::string(err).find("'HOSTMOT3', expected 'HOSTMOT2'"), std::string::npos) << err;
    EXPECT_EQ(hm2_idrom_offset(0xABCD0400), 0x400u);
}

TEST(Hm2Idrom, RefusalsInOrder)
{
    int rc;
    Header h;
    h.w[0] = 0x1234;
    h.w[9] = 29;	// also bad, but the type is checked first
    EXPECT_EQ(parse(h, 3, 24, &rc), "invalid IDROM type 4660, expected 2 or 3");
    EXPECT_EQ(rc, -EINVAL);

    h = Header();
    h.w[9] = 29;
    EXPECT_EQ(parse(h), "IDROM PortWidth is 29, this board has 24 pins per connector");
    h = Header();
    h.w[8] = 99;
    EXPECT_EQ(parse(h), "IDROM IOWidth is 99, but IOPorts (3) x PortWidth (24) is 72");
    h = Header();
    h.w[7] = 2;
    h.w[8] = 48;
    EXPECT_EQ(parse(h), "IDROM IOPorts is 2, this board has 3 connectors");
    h = Header();
    h.w[7] = 42;
    h.w[8] = 42 * 24;
    EXPECT_EQ(parse(h, 42, 24), "IDROM IOWidth is 1008, the driver handles at most 1000 pins");
    h = Header();
    h.w[10] = 12345;
    EXPECT_EQ(parse(h), "IDROM ClockLow is 12345 Hz, below the minimum of 1000000 Hz");
    h = Header();
    h.w[11] = 0;
    EXPECT_EQ(parse(h), "IDROM ClockHigh is 0 Hz, below the minimum of 1000000 Hz");
    h = Header();
    h.w[0] = 2;	// type 2 is accepted too
    EXPECT_EQ(parse(h, 3, 24, &rc), "");
    EXPECT_EQ(rc, 0);
}

TEST(Hm2Idrom, ModuleDescriptor)
{
    Header h;
    hm2_board_shape shape{3, 24};
    hm2_idrom id{};
    char err[200] = "";
    ASSERT_EQ(hm2_idrom_parse(h.w, &shape, &id, err, sizeof err), 0);
    // SVST8_4's encoder: tag 4, v2, ClockLow, 8 instances at 0x3000, 5 registers
    rtapi_u32 enc[3] = {0x08010204, 0x00053000, 0x3};
    hm2_md md{};
    ASSERT_EQ(hm2_md_parse(enc, &id, &md, err, sizeof err), 0) << err;
    EXPECT_EQ(md.gtag, 4);
    EXPECT_EQ(md.version, 2);
    EXPECT_EQ(md.instances, 8);
    EXPECT_EQ(md.base_address, 0x3000);
    EXPECT_EQ(md.num_registers, 5);
    EXPECT_EQ(md.clock_freq, 33333333u);
    EXPECT_EQ(md.instance_stride, 4u);
    EXPECT_EQ(md.register_stride, 0x100u);
    EXPECT_EQ(hm2_md_addr(&md, 1, 3), 0x310Cu);
    EXPECT_EQ(hm2_md_is_consistent(&md, err, sizeof err), 0) << err;
    // PWM on ClockHigh
    rtapi_u32 pwm[3] = {0x08020006, 0x00054000, 0x3};
    ASSERT_EQ(hm2_md_parse(pwm, &id, &md, err, sizeof err), 0);
    EXPECT_EQ(md.clock_freq, 100000000u);
    // end of list
    rtapi_u32 end[3] = {0, 0, 0};
    EXPECT_EQ(hm2_md_parse(end, &id, &md, err, sizeof err), 1);
    // bad clock tag, bad stride selector
    rtapi_u32 badclk[3] = {0x08070204, 0x00053000, 0x3};
    EXPECT_EQ(hm2_md_parse(badclk, &id, &md, err, sizeof err), -EINVAL);
    EXPECT_NE(std::string(err).find("invalid clock tag 7"), std::string::npos) << err;
    rtapi_u32 badstride[3] = {0x08010204, 0x20053000, 0x3};
    EXPECT_EQ(hm2_md_parse(badstride, &id, &md, err, sizeof err), -EINVAL);
    EXPECT_NE(std::string(err).find("instance stride selector 2"), std::string::npos) << err;
}

TEST(Hm2Idrom, ConsistencyRules)
{
    char err[200] = "";
    hm2_md md{};
    md.gtag = HM2_GTAG_ENCODER;
    md.version = 2;
    md.num_registers = 4;
    md.instance_stride = 4;
    md.multiple_registers = 3;
    EXPECT_EQ(hm2_md_is_consistent(&md, err, sizeof err), -EINVAL);
    EXPECT_NE(std::string(err).find("encoder: inconsistent module descriptor: 4 registers"),
              std::string::npos) << err;
    md.num_registers = 5;
    md.version = 7;
    EXPECT_EQ(hm2_md_is_consistent(&md, err, sizeof err), -EINVAL);
    EXPECT_EQ(std::string(err), "encoder: unsupported module version 7");
    md.version = 0x83;	// v3 + probe
    EXPECT_EQ(hm2_md_is_consistent(&md, err, sizeof err), 0);
    md.gtag = 99;	// not ours: accepted (ignored by the caller)
    EXPECT_EQ(hm2_md_is_consistent(&md, err, sizeof err), 0);
    EXPECT_EQ(hm2_gtag_name(99), nullptr);
    EXPECT_STREQ(hm2_gtag_name(HM2_GTAG_STEPGEN), "stepgen");
}

TEST(Hm2Idrom, UartAcceptsEitherInstanceStride)
{
    char err[200] = "";
    hm2_md md{};
    md.gtag = HM2_GTAG_UART_TX;
    md.num_registers = 4;
    md.multiple_registers = 0x0F;
    for (rtapi_u32 stride : {0x10u, 0x40u}) {
        md.instance_stride = stride;
        EXPECT_EQ(hm2_md_is_consistent(&md, err, sizeof err), 0) << err;
    }
    md.instance_stride = 4;
    EXPECT_EQ(hm2_md_is_consistent(&md, err, sizeof err), -EINVAL);
    md.gtag = HM2_GTAG_BSPI;	// BSPI: 0x40 only
    md.num_registers = 3;
    md.multiple_registers = 0x07;
    md.instance_stride = 0x10;
    EXPECT_EQ(hm2_md_is_consistent(&md, err, sizeof err), -EINVAL);
    md.instance_stride = 0x40;
    EXPECT_EQ(hm2_md_is_consistent(&md, err, sizeof err), 0) << err;
}

TEST(Hm2Idrom, PinDescriptors)
{
    char err[200] = "";
    hm2_pd pd{};
    EXPECT_EQ(hm2_pd_parse(0x03000581, 0, &pd, err, sizeof err), 0);
    EXPECT_EQ(pd.sec_tag, 5);
    EXPECT_EQ(pd.sec_pin, 0x81);
    EXPECT_EQ(pd.sec_unit, 0);
    EXPECT_EQ(hm2_pd_parse(0, 7, &pd, err, sizeof err), -EINVAL);
    EXPECT_EQ(std::string(err),
              "pin descriptor 7: found end-of-list sentinel early (IOWidth promises more pins)");
    EXPECT_EQ(hm2_pd_parse(0x04000000, 2, &pd, err, sizeof err), -EINVAL);
    EXPECT_EQ(std::string(err), "pin descriptor 2: primary tag 4, expected 3 (IOPort)");
}

TEST(Hm2Idrom, ConnectorPins)
{
    EXPECT_EQ(hm2_connector_pin(24, 0), 1);
    EXPECT_EQ(hm2_connector_pin(24, 23), 47);
    EXPECT_EQ(hm2_connector_pin(17, 0), 1);
    EXPECT_EQ(hm2_connector_pin(17, 1), 14);
    EXPECT_EQ(hm2_connector_pin(17, 16), 13);
    EXPECT_EQ(hm2_connector_pin(32, 5), 6);
}

}  // namespace
