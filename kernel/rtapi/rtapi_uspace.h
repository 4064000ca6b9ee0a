/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_uspace.h - private glue between the rtapi_*_uspace.c files (simulated-realtime
 * flavor). Not for components or tools. */
#ifndef RTAPI_USPACE_H
#define RTAPI_USPACE_H

#include "rtapi.h"

#define RTAPI_MAX_MODULES 128	/* module ids are 1..RTAPI_MAX_MODULES, per process */

/* 1 when module_id came from rtapi_init() and has not been through rtapi_exit(). */
int rtapi_module_is_valid(int module_id);

/* Detach every shared memory block module_id still holds (called by rtapi_exit). */
void rtapi_shmem_module_exit(int module_id);

#endif /* RTAPI_USPACE_H */
