/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hal_param.c - parameters (hal_param_new(3hal)): creation, removal, and setting
 * a value by name as the owning component would. Compiled without SSE in the kernel
 * flavor like all of hal_lib: a float value is copied as its 64 bits, and the one
 * entry that receives a double in a register, hal_param_float_set, is in
 * hal_param_fp.c. */
#include "hal_internal.h"

int hal_param_new_locked(const char *name, hal_type_t type, hal_param_dir_t dir, volatile void *data_addr,
			 struct hal_comp_rec *comp)
{
	struct hal_param_rec *param;
	int err;

	if (type != HAL_BIT && type != HAL_FLOAT && type != HAL_S32 && type != HAL_U32 &&
	    type != HAL_S64 && type != HAL_U64) {
		rtapi_print_msg(RTAPI_MSG_ERR, "parameter '%s': invalid type %d\n", name, (int)type);
		return -EINVAL;
	}
	if (dir != HAL_RO && dir != HAL_RW) {
		rtapi_print_msg(RTAPI_MSG_ERR, "parameter '%s': invalid direction %d (HAL_RO or HAL_RW)\n",
				name, (int)dir);
		return -EINVAL;
	}
	if (!hal_in_segment(data_addr, type == HAL_BIT ? 1 : (type == HAL_S32 || type == HAL_U32) ? 4 : 8)) {
		rtapi_print_msg(RTAPI_MSG_ERR,
				"parameter '%s': its data is not in HAL shared memory (use hal_malloc)\n",
				name);
		return -EINVAL;
	}
	err = hal_check_lock(HAL_LOCK_LOAD, "create parameters");
	if (err)
		return err;
	param = hal_object_new(HAL_KIND_PARAM, sizeof(*param), name, comp ? hal_off(comp) : 0, &err);
	if (!param)
		return err;
	param->type = type;
	param->dir = dir;
	param->data_off = hal_off(data_addr);
	return 0;
}

void hal_param_delete_locked(struct hal_param_rec *param)
{
	hal_object_delete(&param->hdr);
}

int hal_param_new(const char *name, hal_type_t type, hal_param_dir_t dir, void *data_addr, int comp_id)
{
	struct hal_comp_rec *comp;
	int rc = -EINVAL;

	if (!hal_seg) {
		rtapi_print_msg(RTAPI_MSG_ERR, "parameter '%s': call hal_init first\n", name);
		return -EINVAL;
	}
#ifdef ULAPI
	return hal_ul_obj_new(HAL_REQ_PARAM_NEW, name, type, dir, data_addr, comp_id);
#endif
	hal_lock();
	comp = hal_comp_by_id(comp_id);
	if (comp)
		rc = hal_param_new_locked(name, type, dir, data_addr, comp);
	hal_unlock();
	if (!comp)
		rtapi_print_msg(RTAPI_MSG_ERR, "parameter '%s': component id %d does not exist\n",
				name, comp_id);
	return rc;
}

int hal_param_bit_new(const char *name, hal_param_dir_t dir, hal_bit_t *data_addr, int comp_id)
{
	return hal_param_new(name, HAL_BIT, dir, (void *)data_addr, comp_id);
}

int hal_param_float_new(const char *name, hal_param_dir_t dir, hal_float_t *data_addr, int comp_id)
{
	return hal_param_new(name, HAL_FLOAT, dir, (void *)data_addr, comp_id);
}

int hal_param_u32_new(const char *name, hal_param_dir_t dir, hal_u32_t *data_addr, int comp_id)
{
	return hal_param_new(name, HAL_U32, dir, (void *)data_addr, comp_id);
}

int hal_param_s32_new(const char *name, hal_param_dir_t dir, hal_s32_t *data_addr, int comp_id)
{
	return hal_param_new(name, HAL_S32, dir, (void *)data_addr, comp_id);
}

static int param_newfv(hal_type_t type, hal_param_dir_t dir, volatile void *data_addr, int comp_id,
		       const char *fmt, va_list ap)
{
	char name[HAL_NAME_LEN + 1];
	int err = hal_format_name(name, "parameter", fmt, ap);

	return err ? err : hal_param_new(name, type, dir, (void *)data_addr, comp_id);
}

int hal_param_bit_newf(hal_param_dir_t dir, hal_bit_t *data_addr, int comp_id, const char *fmt, ...)
{
	va_list ap;
	int rc;

	va_start(ap, fmt);
	rc = param_newfv(HAL_BIT, dir, data_addr, comp_id, fmt, ap);
	va_end(ap);
	return rc;
}

int hal_param_float_newf(hal_param_dir_t dir, hal_float_t *data_addr, int comp_id, const char *fmt, ...)
{
	va_list ap;
	int rc;

	va_start(ap, fmt);
	rc = param_newfv(HAL_FLOAT, dir, data_addr, comp_id, fmt, ap);
	va_end(ap);
	return rc;
}

int hal_param_u32_newf(hal_param_dir_t dir, hal_u32_t *data_addr, int comp_id, const char *fmt, ...)
{
	va_list ap;
	int rc;

	va_start(ap, fmt);
	rc = param_newfv(HAL_U32, dir, data_addr, comp_id, fmt, ap);
	va_end(ap);
	return rc;
}

int hal_param_s32_newf(hal_param_dir_t dir, hal_s32_t *data_addr, int comp_id, const char *fmt, ...)
{
	va_list ap;
	int rc;

	va_start(ap, fmt);
	rc = param_newfv(HAL_S32, dir, data_addr, comp_id, fmt, ap);
	va_end(ap);
	return rc;
}

/* Set by name with the owner's rights (RO parameters too). */
int hal_param_set(const char *name, hal_type_t type, void *value_addr)
{
	struct hal_param_rec *param;
	void *data;
	int rc = 0;

	if (!hal_seg)
		return -EINVAL;
#ifdef ULAPI
	return hal_ul_set_own_param(name, type, value_addr);
#endif
	hal_lock();
	param = hal_find(HAL_KIND_PARAM, name);
	if (!param) {
		rtapi_print_msg(RTAPI_MSG_ERR, "parameter '%s' does not exist\n", name);
		rc = -ENOENT;
	} else if (param->type != type) {
		rtapi_print_msg(RTAPI_MSG_ERR, "parameter '%s' is %s, not %s\n", name,
				hal_type_name(param->type), hal_type_name(type));
		rc = -EINVAL;
	} else {
		data = hal_ptr(param->data_off);
		switch (type) {
		case HAL_BIT: *(hal_bit_t *)data = *(int *)value_addr != 0; break;
		case HAL_FLOAT: *(volatile rtapi_u64 *)data = *(rtapi_u64 *)value_addr; break;
		case HAL_S32: *(hal_s32_t *)data = *(rtapi_s32 *)value_addr; break;
		case HAL_S64:
		case HAL_U64: rtapi_store_u64((rtapi_u64 *)data, *(rtapi_u64 *)value_addr); break;
		default: *(hal_u32_t *)data = *(rtapi_u32 *)value_addr; break;
		}
	}
	hal_unlock();
	return rc;
}

int hal_param_bit_set(const char *name, int value)
{
	return hal_param_set(name, HAL_BIT, &value);
}

int hal_param_u32_set(const char *name, unsigned long value)
{
	rtapi_u32 v = (rtapi_u32)value;

	return hal_param_set(name, HAL_U32, &v);
}

int hal_param_s32_set(const char *name, signed long value)
{
	rtapi_s32 v = (rtapi_s32)value;

	return hal_param_set(name, HAL_S32, &v);
}
