/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_config.h - the hostmot2 config string (hostmot2(9), "config modparam"), parsed
 * into a struct before the board is touched. HAL-free for GoogleTest. */
#ifndef HM2_CONFIG_H
#define HM2_CONFIG_H

#include "rtapi.h"

#define HM2_FIRMWARE_NAME_MAX	30	/* longest firmware= value the driver requests */
#define HM2_SSERIAL_PORTS	4
#define HM2_SSERIAL_CHANNELS	8
#define HM2_ABS_CHANNELS	32	/* ssi_chan_N, biss_chan_N, fanuc_chan_N: N < 32 */
#define HM2_ABS_FORMAT_MAX	63
#define HM2_MAX_COUNT		1000	/* largest num_X= accepted */

/* The module-count keywords, in the order of the num[] array. -1 = all. */
enum hm2_count_key {
	HM2_NUM_ENCODERS, HM2_NUM_PWMGENS, HM2_NUM_STEPGENS, HM2_NUM_3PWMGENS,
	HM2_NUM_RCPWMGENS, HM2_NUM_RESOLVERS, HM2_NUM_BSPIS, HM2_NUM_UARTS, HM2_NUM_PKTUARTS,
	HM2_NUM_INMS, HM2_NUM_INMUXS, HM2_NUM_OUTMS, HM2_NUM_SSRS, HM2_NUM_ONESHOTS,
	HM2_NUM_PERIODMS, HM2_NUM_XY2MODS, HM2_NUM_DPLLS, HM2_NUM_LEDS,
	HM2_NUM_KEYS
};

struct hm2_config {
	char firmware[HM2_FIRMWARE_NAME_MAX + 1];	/* "" = none */
	int num[HM2_NUM_KEYS];
	int stepgen_width;				/* default 2 */
	int enable_raw;
	char sserial_modes[HM2_SSERIAL_PORTS][HM2_SSERIAL_CHANNELS + 1];
	int num_sserials;				/* highest port with a mode + 1 */
	/* absolute-encoder format strings: "" = channel not used */
	char ssi_format[HM2_ABS_CHANNELS][HM2_ABS_FORMAT_MAX + 1];
	char biss_format[HM2_ABS_CHANNELS][HM2_ABS_FORMAT_MAX + 1];
	char fanuc_format[HM2_ABS_CHANNELS][HM2_ABS_FORMAT_MAX + 1];
};

/* The keyword of a count ("num_encoders"). */
const char *hm2_config_count_name(enum hm2_count_key key);

/* Parse s (NULL or "" = all defaults). 0, or -EINVAL with one line in err naming
 * the token and what is accepted. */
int hm2_config_parse(const char *s, struct hm2_config *cfg, char *err, int errlen);

/* How many instances to use of a module the firmware has 'available' of:
 * -1 -> all; N <= available -> N; else -EINVAL with a message naming the keyword
 * and the firmware's number. */
int hm2_config_instances(const struct hm2_config *cfg, enum hm2_count_key key, int available,
			 char *err, int errlen);

#endif /* HM2_CONFIG_H */
