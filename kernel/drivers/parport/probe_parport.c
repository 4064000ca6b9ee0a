/* SPDX-License-Identifier: GPL-2.0-or-later */
/* probe_parport.c - kept so that EMC2-era .hal files that "loadrt probe_parport"
 * still load (small-boards.md §3.5). Its old job, activating BIOS-disabled PnP
 * parallel ports, is done by Linux's parport_pc today, and hal_parport claims ports
 * through it; the module creates no pins, parameters or functions. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("compatibility: parallel ports are probed by Linux's parport_pc");

static int comp_id;

int rtapi_app_main(void)
{
	comp_id = hal_init("probe_parport");
	if (comp_id < 0)
		return comp_id;
	hal_ready(comp_id);
	return 0;
}

void rtapi_app_exit(void)
{
	hal_exit(comp_id);
}
