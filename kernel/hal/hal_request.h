/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hal_request.h - configuration requests from userspace programs to the HAL core
 * (docs/kernel-security.md). Userspace (ulapi) turns every change it makes - net,
 * setp, addf, a userspace component's hal_init/hal_pin_new/hal_ready/hal_exit - into
 * one of these; the simulated flavor executes it in the process (hal_req_execute),
 * the kernel flavor hands it to hal_lib.ko through a /dev/rtapi ioctl, which checks
 * it and executes the same function. Only fixed-width fields: a 32-bit tool and a
 * 64-bit kernel agree on the layout. Shared by kernel/hal, hal_lib_kmod.c and the
 * userspace side; nothing here is an address. */
#ifndef HAL_REQUEST_H
#define HAL_REQUEST_H

#ifdef __KERNEL__
#include <linux/types.h>
#include <linux/ioctl.h>
#else
#include <linux/types.h>
#include <sys/ioctl.h>
#endif

#define HAL_REQ_NAME_LEN 64	/* HAL_NAME_LEN + 1 */
#define HAL_REQ_MSG_LEN 1024

enum hal_req_op {
	HAL_REQ_COMP_NEW = 1,	/* name; value = the caller's mapping base -> result comp id */
	HAL_REQ_COMP_READY,	/* comp_id */
	HAL_REQ_COMP_EXIT,	/* comp_id: the caller's, or one whose process is gone */
	HAL_REQ_MALLOC,		/* comp_id, value = size -> off */
	HAL_REQ_PIN_NEW,	/* name, type, dir, comp_id, off = the pointer slot */
	HAL_REQ_PARAM_NEW,	/* name, type, dir, comp_id, off = the value */
	HAL_REQ_PARAM_SET_OWN,	/* name, type, value: a userspace component sets its own */
	HAL_REQ_SIG_NEW,	/* name, type */
	HAL_REQ_SIG_DELETE,	/* name */
	HAL_REQ_LINK,		/* name = pin, name2 = signal */
	HAL_REQ_UNLINK,		/* name = pin */
	HAL_REQ_ADDF,		/* name = function, name2 = thread, arg = position */
	HAL_REQ_DELF,		/* name = function, name2 = thread */
	HAL_REQ_START,
	HAL_REQ_STOP,
	HAL_REQ_SET_LOCK,	/* arg = HAL_LOCK_* bits */
	HAL_REQ_SET_PIN,	/* name, value: setp on a pin */
	HAL_REQ_SET_PARAM,	/* name, value: setp on a parameter */
	HAL_REQ_SET_SIG,	/* name, value: sets */
	HAL_REQ_MODULE_RELEASE,	/* name = module ("" all): take its functions off every thread */
	HAL_REQ_ALIAS,		/* arg = 0 pin / 1 param, name = it, name2 = alias ("": remove all) */
	HAL_REQ_UNALIAS,	/* arg = 0 pin / 1 param, name = an alias or a pin/param */
	HAL_REQ_SET_EXACT,	/* setexact_for_test_suite_only (before the first thread) */
	HAL_REQ_COMP_REMOVE_DEAD,	/* comp_id (0: every one) of a process that is gone */
	HAL_REQ_COMP_UNREADY,	/* comp_id */
	HAL_REQ_OP_END
};

struct hal_req {
	__u32 op;		/* enum hal_req_op */
	__s32 comp_id;
	__s32 type;		/* hal_type_t */
	__s32 dir;		/* hal_pin_dir_t / hal_param_dir_t */
	__s32 arg;
	__u32 off;		/* a segment offset (checked against the caller's memory) */
	__u64 value;		/* raw value bits (union hal_data), a size or a mapping base */
	char name[HAL_REQ_NAME_LEN];	/* NUL-terminated inside the field, else refused */
	char name2[HAL_REQ_NAME_LEN];
	__s32 result;		/* out: >= 0 or -errno */
	__u32 pad;
	char msg[HAL_REQ_MSG_LEN];	/* out: the messages printed while it ran */
};

/* The HAL segment as /dev/rtapi offers it. */
struct hal_dev_info {
	__u32 size;		/* bytes, a multiple of the page size */
	__u32 val_start;	/* [0, val_start) maps read-only, [val_start, size) writable */
	__u32 layout_version;	/* HAL_LAYOUT_VERSION */
	__u32 pad;
};

/* ioctls of /dev/rtapi (rtapi_shmem_kmod.h) that rtapi.ko hands to hal_lib.ko */
#define HAL_IOC_MAGIC 0xb8
#define HAL_IOC_INFO _IOR(HAL_IOC_MAGIC, 1, struct hal_dev_info)
#define HAL_IOC_REQUEST _IOWR(HAL_IOC_MAGIC, 2, struct hal_req)
#define HAL_IOC_LOCK _IO(HAL_IOC_MAGIC, 3)	/* take the HAL mutex for reading records */
#define HAL_IOC_UNLOCK _IO(HAL_IOC_MAGIC, 4)
#define HAL_IOC_RECOVER _IO(HAL_IOC_MAGIC, 5)	/* halcmd -R: free it if its holder is gone */

#endif /* HAL_REQUEST_H */
