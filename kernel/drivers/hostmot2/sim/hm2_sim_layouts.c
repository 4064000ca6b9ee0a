/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_sim_layouts.c - the firmware layouts hm2_sim can present, and the faults it can
 * put into their IDROM (one per refusal the driver makes, like LinuxCNC's hm2_test
 * patterns). Pin descriptor words: primary tag 3 (IOPort) << 24 | unit << 16 |
 * secondary tag << 8 | secondary pin (bit 7 = output). */
#include "rtapi.h"
#include "rtapi_string.h"
#include "hm2_sim_model.h"

#define PD(tag, unit, pin) ((3u << 24) | ((rtapi_u32)(unit) << 16) | ((rtapi_u32)(tag) << 8) | (pin))
#define GPIO PD(0, 0, 0)
#define STEP(u) PD(5, u, 0x81), PD(5, u, 0x82)
#define STEP6(u) PD(5, u, 0x81), PD(5, u, 0x82), PD(5, u, 0x83), PD(5, u, 0x84), PD(5, u, 0x85), \
	PD(5, u, 0x86)
#define PWM(u) PD(6, u, 0x81), PD(6, u, 0x82), PD(6, u, 0x83)
#define ENC(u) PD(4, u, 1), PD(4, u, 2), PD(4, u, 3)
#define MUXENC(u) PD(12, u, 1), PD(12, u, 2), PD(12, u, 3)
#define MUXSEL0 PD(13, 0x80, 0x81)
#define TPPWM(u) PD(19, u, 0x81), PD(19, u, 0x82), PD(19, u, 0x83), PD(19, u, 0x84), \
	PD(19, u, 0x85), PD(19, u, 0x86), PD(19, u, 0x87), PD(19, u, 0x08)
#define BSPI(u) PD(14, u, 0x81), PD(14, u, 0x82), PD(14, u, 0x83), PD(14, u, 0x04), \
	PD(14, u, 0x85), PD(14, u, 0x86), PD(14, u, 0x87), PD(14, u, 0x88), PD(14, u, 0x89), \
	PD(14, u, 0x8A), PD(14, u, 0x8B), PD(14, u, 0x8C)
#define UART(u) PD(9, u, 0x81), PD(9, u, 0x82), PD(10, u, 0x01)
#define GPIO4 GPIO, GPIO, GPIO, GPIO
#define GPIO8 GPIO4, GPIO4
#define SERVO4(u0) ENC(u0), ENC(u0 + 1), ENC(u0 + 2), ENC(u0 + 3), PWM(u0), PWM(u0 + 1), \
	PWM(u0 + 2), PWM(u0 + 3)

/* A 5i25 running the 7i76 step/dir firmware: five step/dir stepgens, a spindle
 * encoder and PWM on P2, the DPLL; P3's 17 pins as GPIO (the real 7i76 field I/O
 * is smart serial, not modelled). */
static const struct sim_layout layout_5i25 = {
	.board = "5i25", .firmware = "7i76 step/dir (5 stepgens, 1 encoder, 1 pwmgen)",
	.idrom_name = "MESA5I25", .ports = 2, .port_width = 17, .num_leds = 2,
	.connector = { "P2", "P3" },
	.clock_low = 33333333, .clock_high = 200000000, .fpga_size = 9, .fpga_pins = 144,
	.md = {
		{ 2, 0, 1, 1, 0x0C00, 3, 0, 0x0 },		/* watchdog */
		{ 3, 0, 1, 2, 0x1000, 5, 0, 0x1F },		/* ioport */
		{ 4, 2, 1, 1, 0x3000, 5, 0, 0x03 },		/* encoder */
		{ 5, 0x42, 1, 5, 0x2000, 10, 0, 0x1FF },	/* stepgen (swap step/dir) */
		{ 6, 1, 2, 1, 0x4000, 5, 0, 0x03 },		/* pwmgen (dither) */
		{ 26, 0, 1, 1, 0x7000, 7, 0, 0x0 },		/* hm2dpll */
		{ 128, 0, 1, 1, 0x0200, 1, 0, 0x0 },		/* led */
	},
	.pd = {
		STEP(0), STEP(1), STEP(2), STEP(3), STEP(4), PWM(0), ENC(0), GPIO,
		GPIO, GPIO, GPIO, GPIO, GPIO, GPIO, GPIO, GPIO, GPIO, GPIO, GPIO, GPIO, GPIO, GPIO,
		GPIO, GPIO, GPIO,
	},
};

/* A 5i20 running SVST8_4: eight servo channels (encoder + PWM) on P2 and P3, four
 * stepgens with six table-mode pins each on P4 (stepgen_width masks the extras). */
static const struct sim_layout layout_5i20 = {
	.board = "5i20", .firmware = "SVST8_4 (8 encoders, 8 pwmgens, 4 stepgens)",
	.idrom_name = "MESA5I20", .ports = 3, .port_width = 24, .num_leds = 8,
	.connector = { "P2", "P3", "P4" },
	.clock_low = 33333333, .clock_high = 100000000, .fpga_size = 200, .fpga_pins = 208,
	.md = {
		{ 2, 0, 1, 1, 0x0C00, 3, 0, 0x0 },
		{ 3, 0, 1, 3, 0x1000, 5, 0, 0x1F },
		{ 4, 2, 1, 8, 0x3000, 5, 0, 0x03 },
		{ 6, 0, 2, 8, 0x4000, 5, 0, 0x03 },
		{ 5, 2, 1, 4, 0x2000, 10, 0, 0x1FF },
		{ 128, 0, 1, 1, 0x0200, 1, 0, 0x0 },
	},
	.pd = {
		ENC(0), ENC(1), ENC(2), ENC(3), PWM(0), PWM(1), PWM(2), PWM(3),
		ENC(4), ENC(5), ENC(6), ENC(7), PWM(4), PWM(5), PWM(6), PWM(7),
		STEP6(0), STEP6(1), STEP6(2), STEP6(3),
	},
};

/* A 5i23 with a 7i65 servo card on P2's buffered SPI (its DACs, ADC and CPLD), a
 * UART beside it, eight multiplexed encoders on P3 (four pin sets and a select
 * line: an outside multiplexer), one three-phase PWM generator on P4. */
static const struct sim_layout layout_5i23 = {
	.board = "5i23", .firmware = "7i65 + muxed encoders + 3pwmgen + UART",
	.idrom_name = "MESA5I23", .ports = 3, .port_width = 24, .num_leds = 2,
	.connector = { "P2", "P3", "P4" }, .bspi_7i65 = 1,
	.clock_low = 48000000, .clock_high = 96000000, .fpga_size = 400, .fpga_pins = 208,
	.md = {
		{ 2, 0, 1, 1, 0x0C00, 3, 0, 0x0 },		/* watchdog */
		{ 3, 0, 1, 3, 0x1000, 5, 0, 0x1F },		/* ioport */
		{ 12, 4, 1, 8, 0x3500, 5, 0, 0x03 },		/* muxed encoder (skew) */
		{ 19, 0, 2, 1, 0x4500, 4, 0, 0x03 },		/* 3pwmgen */
		{ 14, 0, 1, 1, 0x5400, 3, 1, 0x07 },		/* bspi, instance stride 0x40 */
		{ 9, 0, 1, 1, 0x6000, 4, 1, 0x0F },		/* uart tx */
		{ 10, 0, 1, 1, 0x6400, 4, 1, 0x0F },		/* uart rx */
		{ 128, 0, 1, 1, 0x0200, 1, 0, 0x0 },		/* led */
	},
	.pd = {
		BSPI(0), UART(0), GPIO4, GPIO4, GPIO,
		MUXENC(0), MUXENC(1), MUXENC(2), MUXENC(3), MUXSEL0, GPIO4, GPIO4, GPIO, GPIO, GPIO,
		TPPWM(0), GPIO4, GPIO4, GPIO4, GPIO4,
	},
};

/* A 5i22 (four 24-pin connectors): eight servo channels on P2 and P3, four step/dir
 * stepgens on P4, P5 all GPIO. */
static const struct sim_layout layout_5i22 = {
	.board = "5i22", .firmware = "8 servo channels, 4 stepgens",
	.idrom_name = "MESA5I22", .ports = 4, .port_width = 24, .num_leds = 8,
	.connector = { "P2", "P3", "P4", "P5" },
	.clock_low = 48000000, .clock_high = 96000000, .fpga_size = 1000, .fpga_pins = 320,
	.md = {
		{ 2, 0, 1, 1, 0x0C00, 3, 0, 0x0 },
		{ 3, 0, 1, 4, 0x1000, 5, 0, 0x1F },
		{ 4, 2, 1, 8, 0x3000, 5, 0, 0x03 },
		{ 6, 0, 2, 8, 0x4000, 5, 0, 0x03 },
		{ 5, 2, 1, 4, 0x2000, 10, 0, 0x1FF },
		{ 128, 0, 1, 1, 0x0200, 1, 0, 0x0 },
	},
	.pd = {
		SERVO4(0), SERVO4(4), STEP(0), STEP(1), STEP(2), STEP(3), GPIO8, GPIO8,
		GPIO8, GPIO8, GPIO8,
	},
};

/* A 5i21 (one 64-pin P1, two 32-bit IOPorts): four servo channels and four
 * step/dir stepgens, the rest GPIO. */
static const struct sim_layout layout_5i21 = {
	.board = "5i21", .firmware = "4 servo channels, 4 stepgens",
	.idrom_name = "MESA5I21", .ports = 2, .port_width = 32, .num_leds = 8,
	.connector = { "P1", "P1" },
	.clock_low = 48000000, .clock_high = 96000000, .fpga_size = 400, .fpga_pins = 208,
	.md = {
		{ 2, 0, 1, 1, 0x0C00, 3, 0, 0x0 },
		{ 3, 0, 1, 2, 0x1000, 5, 0, 0x1F },
		{ 4, 2, 1, 4, 0x3000, 5, 0, 0x03 },
		{ 6, 0, 2, 4, 0x4000, 5, 0, 0x03 },
		{ 5, 2, 1, 4, 0x2000, 10, 0, 0x1FF },
		{ 128, 0, 1, 1, 0x0200, 1, 0, 0x0 },
	},
	.pd = {
		SERVO4(0), GPIO8, STEP(0), STEP(1), STEP(2), STEP(3), GPIO8, GPIO8, GPIO8,
	},
};

/* A 3x20 (six 24-pin connectors, no LEDs): eight servo channels on P4 and P5, four
 * step/dir stepgens on P6, the rest GPIO. */
static const struct sim_layout layout_3x20 = {
	.board = "3x20", .firmware = "8 servo channels, 4 stepgens",
	.idrom_name = "MESA3X20", .ports = 6, .port_width = 24, .num_leds = 0,
	.connector = { "P4", "P5", "P6", "P9", "P8", "P7" },
	.clock_low = 50000000, .clock_high = 100000000, .fpga_size = 1000, .fpga_pins = 456,
	.md = {
		{ 2, 0, 1, 1, 0x0C00, 3, 0, 0x0 },
		{ 3, 0, 1, 6, 0x1000, 5, 0, 0x1F },
		{ 4, 2, 1, 8, 0x3000, 5, 0, 0x03 },
		{ 6, 0, 2, 8, 0x4000, 5, 0, 0x03 },
		{ 5, 2, 1, 4, 0x2000, 10, 0, 0x1FF },
	},
	.pd = {
		SERVO4(0), SERVO4(4), STEP(0), STEP(1), STEP(2), STEP(3), GPIO8, GPIO8,
		GPIO8, GPIO8, GPIO8, GPIO8, GPIO8, GPIO8, GPIO8, GPIO8, GPIO8,
	},
};

/* A 7i43 running SVST4_4: four servo channels (encoder + PWM) on P4, four stepgens
 * with six table-mode pins each on P3. The board behind a simulated parallel port
 * (sim_parport board=7i43, kernel/drivers/sim/sim_7i43.c) and hm2_sim board=7i43. */
static const struct sim_layout layout_7i43 = {
	.board = "7i43", .firmware = "SVST4_4 (4 encoders, 4 pwmgens, 4 stepgens)",
	.idrom_name = "MESA7I43", .ports = 2, .port_width = 24, .num_leds = 8,
	.connector = { "P4", "P3" },
	.clock_low = 50000000, .clock_high = 100000000, .fpga_size = 200, .fpga_pins = 144,
	.md = {
		{ 2, 0, 1, 1, 0x0C00, 3, 0, 0x0 },
		{ 3, 0, 1, 2, 0x1000, 5, 0, 0x1F },
		{ 4, 2, 1, 4, 0x3000, 5, 0, 0x03 },
		{ 6, 0, 2, 4, 0x4000, 5, 0, 0x03 },
		{ 5, 2, 1, 4, 0x2000, 10, 0, 0x1FF },
		{ 128, 0, 1, 1, 0x0200, 1, 0, 0x0 },
	},
	.pd = {
		ENC(0), ENC(1), ENC(2), ENC(3), PWM(0), PWM(1), PWM(2), PWM(3),
		STEP6(0), STEP6(1), STEP6(2), STEP6(3),
	},
};

static const struct sim_layout *const layouts[] = { &layout_5i25, &layout_5i20, &layout_5i23,
						    &layout_5i22, &layout_5i21, &layout_3x20,
						    &layout_7i43 };

const struct sim_layout *hm2_sim_layout_find(const char *board)
{
	unsigned i;

	for (i = 0; i < sizeof(layouts) / sizeof(layouts[0]); i++)
		if (strcmp(layouts[i]->board, board) == 0)
			return layouts[i];
	return 0;
}

const struct sim_layout *hm2_sim_layout_shaped(int ports, int port_width)
{
	unsigned i;

	for (i = 0; i < sizeof(layouts) / sizeof(layouts[0]); i++)
		if (layouts[i]->ports == ports && layouts[i]->port_width == port_width)
			return layouts[i];
	return 0;
}

const char *hm2_sim_layout_names(void)
{
	return "5i25 (7i76 step/dir), 5i20 (SVST8_4 servo), 5i23 (7i65 on BSPI, muxed encoders, "
	       "3pwmgen, UART), 5i22, 5i21 and 3x20 (servo + step/dir), 7i43 (SVST4_4)";
}

static const char *const fault_names[SIM_FAULT_COUNT] = {
	"none", "no-cookie", "bad-name", "idrom-offset-0", "idrom-type", "port-width",
	"io-width", "io-ports", "clock-low", "clock-high", "pd-sentinel", "no-ioport",
	"md-inconsistent", "clock-tag", "duplicate-md",
};

int hm2_sim_fault_find(const char *name)
{
	int i;

	for (i = 0; i < SIM_FAULT_COUNT; i++)
		if (strcmp(fault_names[i], name) == 0)
			return i;
	return -1;
}

const char *hm2_sim_fault_names(void)
{
	return "none, no-cookie, bad-name, idrom-offset-0, idrom-type, port-width, io-width, "
	       "io-ports, clock-low, clock-high, pd-sentinel, no-ioport, md-inconsistent, "
	       "clock-tag, duplicate-md";
}
