/* SPDX-License-Identifier: GPL-2.0-or-later */
/* pluto_common.h - what pluto_servo and pluto_step share (pluto.md §2, §3): load-time
 * checks of the common module parameters, claiming the port, the firmware upload in
 * SPP mode, the EPP check, and the EPP register accesses of the read/write functions.
 * Integer code only, included by both drivers' glue and FP files. */
#ifndef PLUTO_COMMON_H
#define PLUTO_COMMON_H

#include "rtapi.h"
#include "rtapi_firmware.h"
#include "hal.h"
#include "hal_parport.h"

#define PLUTO_IMAGE_FILE  19897	/* an EP1K10 .rbf */
#define PLUTO_IMAGE_SENT  19895	/* what the board takes; the last 2 bytes are padding */

/* Port registers relative to the base, and the ECR relative to the high base. */
#define PLUTO_DATA     0
#define PLUTO_STATUS   1
#define PLUTO_CONTROL  2
#define PLUTO_EPP_ADDR 3
#define PLUTO_EPP_DATA 4
#define PLUTO_ECR      2

/* Init code: the common module parameters. 0, or -EINVAL after a message. */
static inline int pluto_check_params(const char *drv, int ioaddr, int ioaddr_hi,
				     int epp_wide, int watchdog)
{
	if (ioaddr <= 0 || ioaddr > 0xfff8) {
		rtapi_print_msg(RTAPI_MSG_ERR, "%s: ioaddr=0x%x: must be the parallel port's "
				"address (e.g. 0x378), at most 0xfff8\n", drv, ioaddr);
		return -EINVAL;
	}
	if (ioaddr_hi < -1 || ioaddr_hi > 0xfffd) {
		rtapi_print_msg(RTAPI_MSG_ERR, "%s: ioaddr_hi=%d: must be -1 (none), 0 (ioaddr + "
				"0x400) or an address up to 0xfffd\n", drv, ioaddr_hi);
		return -EINVAL;
	}
	if (epp_wide != 0 && epp_wide != 1) {
		rtapi_print_msg(RTAPI_MSG_ERR, "%s: epp_wide=%d: must be 0 or 1\n", drv, epp_wide);
		return -EINVAL;
	}
	if (watchdog != 0 && watchdog != 1) {
		rtapi_print_msg(RTAPI_MSG_ERR, "%s: watchdog=%d: must be 0 or 1\n", drv, watchdog);
		return -EINVAL;
	}
	return 0;
}

/* Different chips clear the EPP timeout flag on different actions: do them all. */
static inline void pluto_clear_timeout(unsigned int base)
{
	unsigned char s = rtapi_inb(base + PLUTO_STATUS);

	rtapi_outb(s | 0x01, base + PLUTO_STATUS);
	rtapi_outb(s & 0xfe, base + PLUTO_STATUS);
}

static inline int pluto_timed_out(unsigned int base)
{
	return rtapi_inb(base + PLUTO_STATUS) & 0x01;
}

static inline void pluto_addr(unsigned int base, unsigned char addr)
{
	rtapi_outb(addr, base + PLUTO_EPP_ADDR);
}

/* 32-bit reads start 4-aligned; every data cycle advances the board's address. */
static inline rtapi_u32 pluto_read32(unsigned int base, int wide)
{
	rtapi_u32 v = 0;
	int i;

	if (wide)
		return rtapi_inl(base + PLUTO_EPP_DATA);
	for (i = 0; i < 4; i++)
		v |= (rtapi_u32)rtapi_inb(base + PLUTO_EPP_DATA) << (8 * i);
	return v;
}

static inline void pluto_write16(unsigned int base, int wide, rtapi_u16 v)
{
	if (wide) {
		rtapi_outw(v, base + PLUTO_EPP_DATA);
	} else {
		rtapi_outb(v & 0xff, base + PLUTO_EPP_DATA);
		rtapi_outb(v >> 8, base + PLUTO_EPP_DATA);
	}
}

static inline void pluto_write32(unsigned int base, int wide, rtapi_u32 v)
{
	if (wide) {
		rtapi_outl(v, base + PLUTO_EPP_DATA);
	} else {
		pluto_write16(base, 0, v & 0xffff);
		pluto_write16(base, 0, v >> 16);
	}
}

/* SPP bit-banging (pluto.md §2): nInit low resets the FPGA, then each bit, LSB first,
 * on all data lines with one pulse of control bit 0 as its clock. */
static inline void pluto_upload(const hal_parport_t *pp, const unsigned char *image)
{
	unsigned int base = pp->base;
	int i, bit;

	rtapi_outb(0x04, base + PLUTO_CONTROL);
	if (pp->base_hi)
		rtapi_outb(0x00, pp->base_hi + PLUTO_ECR);	/* SPP mode */
	for (i = 0; i < 4; i++)			/* >= 2 us of nConfig low */
		rtapi_outb(0x00, base + PLUTO_CONTROL);
	for (i = 0; i < 20; i++)		/* >= 10 us until the FPGA is ready */
		rtapi_outb(0x04, base + PLUTO_CONTROL);
	for (i = 0; i < PLUTO_IMAGE_SENT; i++)
		for (bit = 0; bit < 8; bit++) {
			rtapi_outb((image[i] >> bit) & 1 ? 0xff : 0x00, base + PLUTO_DATA);
			rtapi_outb(0x04, base + PLUTO_CONTROL);
			rtapi_outb(0x05, base + PLUTO_CONTROL);
			rtapi_outb(0x04, base + PLUTO_CONTROL);
		}
	if (pp->base_hi)
		rtapi_outb(0x80, pp->base_hi + PLUTO_ECR);	/* EPP mode */
}

/* Init code: reads the firmware image 'fw' (e.g. "pluto/pluto_servo.rbf"), claims the
 * port, uploads the image and checks that the new design answers an EPP read. 0 with
 * the port held, or a negative errno after a message with nothing held. */
static inline int pluto_setup(const char *drv, const char *fw_name, int comp_id,
			      hal_parport_t *pp, int ioaddr, int ioaddr_hi)
{
	const struct rtapi_firmware *fw;
	int rc = rtapi_request_firmware(&fw, fw_name);

	if (rc == -ENOENT) {
		rtapi_print_msg(RTAPI_MSG_ERR, "%s: firmware %s not found (HAL does not "
				"ship it): put the .rbf (%d bytes) at /lib/firmware/%s or, "
				"simulated flavor, under HAL_FIRMWARE_PATH\n", drv, fw_name, PLUTO_IMAGE_FILE, fw_name);
		return rc;
	}
	if (rc)
		return rc;
	if (fw->size < PLUTO_IMAGE_SENT || fw->size > PLUTO_IMAGE_FILE) {
		rtapi_print_msg(RTAPI_MSG_ERR, "%s: firmware %s is %lu bytes, not a Pluto-P "
				"image (%d bytes)\n", drv, fw_name, fw->size, PLUTO_IMAGE_FILE);
		rtapi_release_firmware(fw);
		return -EINVAL;
	}
	rc = hal_parport_get(comp_id, pp, ioaddr,
			     ioaddr_hi == -1 ? (unsigned short)-1 : (unsigned short)ioaddr_hi,
			     HAL_PARPORT_MODE_EPP);
	if (rc) {
		rtapi_release_firmware(fw);
		return rc;
	}
	pluto_upload(pp, fw->data);
	rtapi_release_firmware(fw);
	pluto_clear_timeout(pp->base);
	pluto_addr(pp->base, 0);
	rtapi_inb(pp->base + PLUTO_EPP_DATA);
	if (pluto_timed_out(pp->base)) {
		rtapi_print_msg(RTAPI_MSG_ERR, "%s: no answer over EPP from a Pluto-P at 0x%x "
				"after the firmware upload (EPP timeout): is the board connected "
				"and powered, and the port in EPP mode (BIOS setup)?\n",
				drv, pp->base);
		hal_parport_release(pp);
		return -EIO;
	}
	return 0;
}

/* Init code, all of it both drivers share: hal_init(drv), the driver's block of
 * 'size' bytes of HAL memory (its hal_parport_t at 'port_offset'), pluto_setup().
 * 0 with *comp_id and *block set and the port held, or a negative errno after a
 * message with nothing left. */
static inline int pluto_open(const char *drv, const char *fw_name, unsigned long size,
			     unsigned long port_offset, int ioaddr, int ioaddr_hi,
			     int *comp_id, void **block)
{
	int id = hal_init(drv), rc;
	char *mem;

	if (id < 0)
		return id;
	mem = hal_malloc(size);
	if (!mem) {
		rtapi_print_msg(RTAPI_MSG_ERR, "%s: out of HAL memory\n", drv);
		hal_exit(id);
		return -ENOMEM;
	}
	rc = pluto_setup(drv, fw_name, id, (hal_parport_t *)(mem + port_offset), ioaddr,
			 ioaddr_hi);
	if (rc) {
		hal_exit(id);
		return rc;
	}
	*comp_id = id;
	*block = mem;
	return 0;
}

/* Undoes pluto_open(): exit, or an init step after it that failed. */
static inline void pluto_close(hal_parport_t *pp, int comp_id)
{
	hal_parport_release(pp);
	hal_exit(comp_id);
}

#endif /* PLUTO_COMMON_H */
