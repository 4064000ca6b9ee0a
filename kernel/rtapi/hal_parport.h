/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hal_parport.h - claiming a parallel port for a HAL component (hal_parport(3)).
 * hal_parport_get() takes a Linux parport number (base < 16) or an address; a port
 * Linux knows is claimed through Linux, any other address as raw I/O regions (or on
 * a simulated device, rtapi_iosim.h). Init/exit code only. */
#ifndef HAL_PARPORT_H
#define HAL_PARPORT_H

#include "rtapi.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Modes a driver may ask for; the values of <linux/parport.h>'s PARPORT_MODE_*. */
#define HAL_PARPORT_MODE_PCSPP    (1 << 0)
#define HAL_PARPORT_MODE_TRISTATE (1 << 1)
#define HAL_PARPORT_MODE_EPP      (1 << 2)
#define HAL_PARPORT_MODE_ECP      (1 << 3)

typedef struct {
	unsigned short base;	/* the data register */
	unsigned short base_hi;	/* the ECP registers (ECR at base_hi + 2), 0 if none */
	/* private to hal_parport_get/release */
	void *linux_handle;	/* a Linux-owned port's claim, else NULL */
	unsigned short region_base, region_hi;	/* raw regions held (0: none) */
	char owner[RTAPI_NAME_LEN + 1];
} hal_parport_t;

/* Returns 0, or a negative errno after printing why (no such port, busy, no
 * permission). base_hi: 0 probes base + 0x400, (unsigned short)-1 means none. */
int hal_parport_get(int comp_id, hal_parport_t *port, unsigned short base,
		    unsigned short base_hi, unsigned int modes);
/* Always succeeds; safe on a port whose get failed or that was zeroed. */
void hal_parport_release(hal_parport_t *port);

/* --- the flavor's Linux parport access (rtapi_parport_{kmod,uspace}.c) --- */
/* Looks a Linux parport up by number (is_number) or base address and claims it for
 * exclusive use: 1 with *base, *base_hi (0 if Linux knows none) and *handle set;
 * 0 when Linux has no port at that address; -errno after a message otherwise. */
int rtapi_parport_linux_claim(unsigned int which, int is_number, unsigned int modes,
			      const char *owner, unsigned short *base,
			      unsigned short *base_hi, void **handle);
void rtapi_parport_linux_release(void *handle);

#ifdef __cplusplus
}
#endif
#endif /* HAL_PARPORT_H */
