/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hal_request_ul.c - userspace side of hal_request.h: every HAL call of a userspace
 * program that changes something becomes a request. In the simulated flavor it runs
 * here under the HAL mutex; in the kernel flavor the segment is read-only here and the
 * request goes to hal_lib.ko through /dev/rtapi (kernel/rtapi/hal_ulapi_kmod.c), which prints nothing:
 * its messages come back in the request and are printed here. ULAPI only. */
#include "hal_internal.h"
#include "rtapi_string.h"

/* The component hal_malloc() charges: the last one this process hal_init()ed. */
static int last_comp_id;

int hal_ul_submit(struct hal_req *r)
{
	struct hal_caller self = { .is_user = true };
	char name[16];
	int rc;

	if (hal_seg_is_kmod)
		return hal_kmod_request(r);
	self.pid = hal_os_self(name, sizeof(name));
	hal_lock();
	rc = hal_req_execute(r, &self);
	hal_unlock();
	return rc;
}

static void req_init(struct hal_req *r, enum hal_req_op op)
{
	memset(r, 0, sizeof(*r));
	r->op = op;
}

/* Copy a name into a request field; longer names are refused here with the core's
 * wording (the kernel checks again). */
static int set_name(char *field, const char *name)
{
	if (!name)
		return 0;
	if (strlen(name) >= HAL_REQ_NAME_LEN) {
		rtapi_print_msg(RTAPI_MSG_ERR, "name '%s' is longer than %d characters\n", name,
				HAL_NAME_LEN);
		return -EINVAL;
	}
	strcpy(field, name);
	return 0;
}

int hal_ul_names(enum hal_req_op op, const char *name, const char *name2, int arg)
{
	struct hal_req r;

	req_init(&r, op);
	if (set_name(r.name, name) || set_name(r.name2, name2))
		return -EINVAL;
	r.arg = arg;
	return hal_ul_submit(&r);
}

int hal_ul_set(enum hal_req_op op, const char *name, int type, rtapi_u64 raw)
{
	struct hal_req r;

	req_init(&r, op);
	if (set_name(r.name, name))
		return -EINVAL;
	r.type = type;
	r.value = raw;
	return hal_ul_submit(&r);
}

int hal_ul_set_own_param(const char *name, hal_type_t type, void *value_addr)
{
	union hal_data d;

	d.raw = 0;
	switch (type) {
	case HAL_BIT: d.b = *(int *)value_addr != 0; break;
	case HAL_S32: d.s = *(rtapi_s32 *)value_addr; break;
	case HAL_U32: d.u = *(rtapi_u32 *)value_addr; break;
	default: memcpy(&d.raw, value_addr, sizeof(d.raw)); break;	/* a double */
	}
	return hal_ul_set(HAL_REQ_PARAM_SET_OWN, name, type, d.raw);
}

int hal_ul_comp_new(const char *name)
{
	struct hal_req r;
	int rc;

	req_init(&r, HAL_REQ_COMP_NEW);
	if (set_name(r.name, name))
		return -EINVAL;
	r.value = (rtapi_u64)(unsigned long)hal_shmem_base;
	rc = hal_ul_submit(&r);
	if (rc > 0)
		last_comp_id = rc;
	return rc;
}

int hal_ul_comp_exit(int comp_id)
{
	struct hal_req r;
	int rc;

	req_init(&r, HAL_REQ_COMP_EXIT);
	r.comp_id = comp_id;
	rc = hal_ul_submit(&r);
	if (rc)
		return rc;
	if (last_comp_id == comp_id)
		last_comp_id = 0;
	if (r.arg)	/* this process's own: one local user less */
		hal_local_user_gone();
	return 0;
}

int hal_ul_comp_id_req(enum hal_req_op op, int comp_id)
{
	struct hal_req r;

	req_init(&r, op);
	r.comp_id = comp_id;
	return hal_ul_submit(&r);
}

void *hal_ul_malloc(long size)
{
	struct hal_req r;

	req_init(&r, HAL_REQ_MALLOC);
	r.comp_id = last_comp_id;
	r.value = (rtapi_u64)size;
	if (hal_ul_submit(&r) < 0)
		return 0;
	return hal_ptr(r.off);
}

int hal_ul_obj_new(enum hal_req_op op, const char *name, int type, int dir, volatile void *addr,
		   int comp_id)
{
	struct hal_req r;

	req_init(&r, op);
	if (set_name(r.name, name))
		return -EINVAL;
	if (!hal_in_segment(addr, 1)) {
		rtapi_print_msg(RTAPI_MSG_ERR, "'%s': its data is not in HAL shared memory (use hal_malloc)\n",
				name);
		return -EINVAL;
	}
	r.type = type;
	r.dir = dir;
	r.comp_id = comp_id;
	r.off = hal_off(addr);
	return hal_ul_submit(&r);
}
