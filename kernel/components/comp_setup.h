/* SPDX-License-Identifier: GPL-2.0-or-later */
/* comp_setup.h - the start and end every hand-written component's rtapi_app_main()
 * shares: hal_init() plus one hal_malloc() block, and "remove what was made, or
 * hal_ready()". Init code only. */
#ifndef COMP_SETUP_H
#define COMP_SETUP_H

#include "rtapi.h"
#include "hal.h"

/* hal_init(name) and a zeroed block of 'size' bytes of HAL memory for it. Returns
 * the block with *err = 0, or NULL with *err set after logging, leaving nothing behind. */
static inline void *comp_setup(const char *name, long size, int *comp_id, int *err)
{
	void *mem;

	*err = 0;
	*comp_id = hal_init(name);
	if (*comp_id < 0) {
		*err = *comp_id;
		return 0;
	}
	mem = hal_malloc(size);
	if (!mem) {
		rtapi_print_msg(RTAPI_MSG_ERR, "%s: out of HAL memory (%ld bytes)\n", name, size);
		hal_exit(*comp_id);
		*err = -ENOMEM;
	}
	return mem;
}

/* End of rtapi_app_main(): on error remove every pin, param and function made so
 * far (hal_exit), else mark the component ready. Returns err. */
static inline int comp_finish(int comp_id, int err)
{
	if (err)
		hal_exit(comp_id);
	else
		hal_ready(comp_id);
	return err;
}

#endif /* COMP_SETUP_H */
