/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_parport.c - hal_parport_get/hal_parport_release (hal_parport(3)), the rules
 * common to both flavors: a Linux port is claimed through Linux (the flavor's
 * rtapi_parport_linux_claim); any other address as the I/O regions base..base+7 and,
 * unless base_hi is -1, base_hi (or base + 0x400) ..+2. A probed high region that is
 * unavailable leaves base_hi 0; an explicit one that is unavailable fails. */
#include "rtapi.h"
#include "hal_parport.h"

#define NO_HIGH ((unsigned short)-1)

static void claim_high(hal_parport_t *port, unsigned short want)
{
	unsigned short hi = want ? want : port->base + 0x400;

	port->base_hi = 0;
	if (rtapi_request_region(hi, 3, port->owner)) {
		port->base_hi = hi;
		port->region_hi = hi;
	}
}

int hal_parport_get(int comp_id, hal_parport_t *port, unsigned short base,
		    unsigned short base_hi, unsigned int modes)
{
	unsigned short lbase = 0, lhi = 0;
	int rc;

	port->base = port->base_hi = 0;
	port->linux_handle = 0;
	port->region_base = port->region_hi = 0;
	rtapi_snprintf(port->owner, sizeof(port->owner), "hal_parport(comp %d)", comp_id);
	rc = rtapi_parport_linux_claim(base, base < 16, modes, port->owner, &lbase, &lhi,
				       &port->linux_handle);
	if (rc < 0)
		return rc;
	if (rc > 0) {
		port->base = lbase;
		if (base_hi == NO_HIGH)
			port->base_hi = 0;
		else if (lhi)
			port->base_hi = lhi;
		else
			claim_high(port, base_hi);
		return 0;
	}
	/* no Linux port at this address: raw regions */
	if (!rtapi_request_region(base, 8, port->owner)) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hal_parport: port 0x%x is busy or not accessible "
				"(see the message above)\n", base);
		return -EBUSY;
	}
	port->base = port->region_base = base;
	if (base_hi == NO_HIGH)
		return 0;
	claim_high(port, base_hi);
	if (base_hi && !port->base_hi) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hal_parport: high address 0x%x of port 0x%x is "
				"busy or not accessible\n", base_hi, base);
		hal_parport_release(port);
		return -EBUSY;
	}
	return 0;
}

void hal_parport_release(hal_parport_t *port)
{
	if (port->linux_handle)
		rtapi_parport_linux_release(port->linux_handle);
	if (port->region_hi)
		rtapi_release_region(port->region_hi, 3);
	if (port->region_base)
		rtapi_release_region(port->region_base, 8);
	port->linux_handle = 0;
	port->region_base = port->region_hi = 0;
}
