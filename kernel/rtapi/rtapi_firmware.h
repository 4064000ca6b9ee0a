/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_firmware.h - reading a firmware image (an FPGA bitstream a driver uploads to
 * its board) by name, in both flavors, from the kernel's firmware search path:
 * firmware_class.path if set, /lib/firmware/updates/<release>, /lib/firmware/updates,
 * /lib/firmware/<release>, /lib/firmware. The kernel flavor asks the kernel's loader
 * (request_firmware_direct: no user-helper fallback, no wait); the simulated flavor
 * reads the same directories itself, after the directories listed in the environment
 * variable HAL_FIRMWARE_PATH (colon-separated) of rtapi_app, so that a user or a test
 * can supply an image without root. Init code only (may sleep, allocates). */
#ifndef RTAPI_FIRMWARE_H
#define RTAPI_FIRMWARE_H

#include "rtapi.h"

#ifdef __cplusplus
extern "C" {
#endif

struct rtapi_firmware {
	unsigned long size;
	const unsigned char *data;
	void *priv;		/* the flavor's */
};

/* 'name' is relative to the search directories ("pluto/pluto_servo.rbf"); absolute
 * names and ".." components are refused (-EINVAL). Returns 0 with *fw set, -ENOENT
 * when no directory holds the file (nothing printed: the caller says where it
 * belongs), another -errno after a message. */
int rtapi_request_firmware(const struct rtapi_firmware **fw, const char *name);
void rtapi_release_firmware(const struct rtapi_firmware *fw);

#ifdef __cplusplus
}
#endif
#endif /* RTAPI_FIRMWARE_H */
