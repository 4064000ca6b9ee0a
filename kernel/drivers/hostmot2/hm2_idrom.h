/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_idrom.h - decoding and checking what the FPGA says about itself: the fixed
 * locations, the IDROM header, module descriptors (MDs) and pin descriptors (PDs).
 * HAL-free and transport-free (callers pass the words they read), so GoogleTest
 * drives it directly. Every refusal writes one line into err (no board prefix: the
 * caller adds it) and returns -EINVAL. */
#ifndef HM2_IDROM_H
#define HM2_IDROM_H

#include "rtapi.h"

#define HM2_ADDR_IOCOOKIE	0x0100
#define HM2_ADDR_CONFIGNAME	0x0104
#define HM2_ADDR_IDROM_OFFSET	0x010C
#define HM2_IOCOOKIE		0x55AACAFEu
#define HM2_CONFIGNAME		"HOSTMOT2"
#define HM2_CONFIGNAME_LEN	8
#define HM2_IDROM_WORDS		16
#define HM2_MAX_MODULE_DESCRIPTORS 48
#define HM2_MAX_PIN_DESCRIPTORS	1000
#define HM2_MIN_CLOCK_HZ	1000000u

/* GTags (general function tags) of the modules this driver knows */
enum hm2_gtag {
	HM2_GTAG_END = 0, HM2_GTAG_WATCHDOG = 2, HM2_GTAG_IOPORT = 3, HM2_GTAG_ENCODER = 4,
	HM2_GTAG_STEPGEN = 5, HM2_GTAG_PWMGEN = 6, HM2_GTAG_SSI = 8, HM2_GTAG_UART_TX = 9,
	HM2_GTAG_UART_RX = 10, HM2_GTAG_TRAM = 11, HM2_GTAG_MUXED_ENCODER = 12,
	HM2_GTAG_MUXED_ENCODER_SEL = 13, HM2_GTAG_BSPI = 14, HM2_GTAG_TPPWM = 19,
	HM2_GTAG_BISS = 24, HM2_GTAG_FABS = 25, HM2_GTAG_HM2DPLL = 26,
	HM2_GTAG_PKTUART_TX = 27, HM2_GTAG_PKTUART_RX = 28, HM2_GTAG_INMUX = 30,
	HM2_GTAG_INM = 35, HM2_GTAG_XY2MOD = 43, HM2_GTAG_RCPWMGEN = 44, HM2_GTAG_OUTM = 45,
	HM2_GTAG_LED = 128, HM2_GTAG_RESOLVER = 192, HM2_GTAG_SMARTSERIAL = 193,
	HM2_GTAG_SSR = 195, HM2_GTAG_SMARTSERIALB = 198, HM2_GTAG_ONESHOT = 199,
	HM2_GTAG_PERIODM = 200,
};

struct hm2_idrom {
	rtapi_u32 idrom_type, offset_to_modules, offset_to_pin_desc;
	char board_name[9];		/* the 8 ASCII bytes, NUL added */
	rtapi_u32 fpga_size, fpga_pins, io_ports, io_width, port_width;
	rtapi_u32 clock_low, clock_high;
	rtapi_u32 instance_stride0, instance_stride1, register_stride0, register_stride1;
};

struct hm2_md {
	rtapi_u8 gtag, version, clock_tag, instances;
	rtapi_u16 base_address;
	rtapi_u8 num_registers;
	rtapi_u32 register_stride, instance_stride;
	rtapi_u32 multiple_registers;
	rtapi_u32 clock_freq;		/* Hz, from the clock the MD names */
};

struct hm2_pd {
	rtapi_u8 sec_pin;		/* bit 7: the module drives it */
	rtapi_u8 sec_tag;		/* 0: plain GPIO */
	rtapi_u8 sec_unit;		/* bit 7: shared by all instances */
	rtapi_u8 primary_tag;		/* always IOPort */
};

/* What the board driver declares, checked against the header. */
struct hm2_board_shape {
	int num_ioport_connectors;
	int pins_per_connector;
};

/* Checks 1 and 2: cookie and config name (the three words at 0x100..0x108). */
int hm2_idrom_check_cookie(const rtapi_u32 words[3], char *err, int errlen);
/* The IDROM offset from the word at 0x10C (low 16 bits). */
rtapi_u32 hm2_idrom_offset(rtapi_u32 word);
/* Decode the 16 header words and run the header checks in the documented order. */
int hm2_idrom_parse(const rtapi_u32 words[HM2_IDROM_WORDS], const struct hm2_board_shape *shape,
		    struct hm2_idrom *idrom, char *err, int errlen);
/* Decode one 3-word MD; returns 1 for the end-of-list entry, 0 for a module. */
int hm2_md_parse(const rtapi_u32 words[3], const struct hm2_idrom *idrom, struct hm2_md *md,
		 char *err, int errlen);
/* Decode one PD; pin is its index, for the message. */
int hm2_pd_parse(rtapi_u32 word, int pin, struct hm2_pd *pd, char *err, int errlen);

/* A driver's acceptance rule for one module type (table in hm2_idrom.c). */
int hm2_md_is_consistent(const struct hm2_md *md, char *err, int errlen);

/* The module name for messages ("encoder"), or NULL for a tag this driver ignores. */
const char *hm2_gtag_name(int gtag);
/* Address of register reg, instance inst of md. */
static inline rtapi_u32 hm2_md_addr(const struct hm2_md *md, int reg, int inst)
{
	return md->base_address + reg * md->register_stride + inst * md->instance_stride;
}
/* Connector pin number printed for IO index n of a port (odd pins of a 50-pin
 * header, DB25 order for 17-pin ports, n+1 otherwise). */
int hm2_connector_pin(int port_width, int bit);

#endif /* HM2_IDROM_H */
