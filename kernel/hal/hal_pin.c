/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hal_pin.c - pins (hal_pin_new(3hal)): creation, the owner's data pointer that
 * aims at a signal or at the pin's own dummy storage, and removal. */
#include "hal_internal.h"

static bool type_valid(int type)
{
	return type == HAL_BIT || type == HAL_FLOAT || type == HAL_S32 || type == HAL_U32 ||
	       type == HAL_S64 || type == HAL_U64;
}

void hal_pin_aim(struct hal_pin_rec *pin, volatile void *target)
{
	struct hal_comp_rec *owner = hal_ptr(pin->hdr.owner_off);
	rtapi_u64 *ptr = hal_ptr(pin->data_ptr_off);
	rtapi_u64 base = owner ? owner->mem_base : hal_seg->rt_mem_base;	/* thread pins */

	/* The owner dereferences this in its own address space (kernel or rtapi_app). */
	__atomic_store_n(ptr, base + hal_off(target), __ATOMIC_RELEASE);
}

union hal_data *hal_pin_value(struct hal_pin_rec *pin)
{
	struct hal_sig_rec *sig = hal_ptr(pin->signal_off);

	return sig ? hal_sig_value(sig) : hal_pin_dummy(pin);
}

int hal_pin_new_locked(const char *name, hal_type_t type, hal_pin_dir_t dir, void **data_ptr_addr,
		       struct hal_comp_rec *comp)
{
	struct hal_pin_rec *pin;
	union hal_data *dummy;
	int err;

	if (!type_valid(type)) {
		rtapi_print_msg(RTAPI_MSG_ERR, "pin '%s': invalid type %d\n", name, (int)type);
		return -EINVAL;
	}
	if (dir != HAL_IN && dir != HAL_OUT && dir != HAL_IO) {
		rtapi_print_msg(RTAPI_MSG_ERR, "pin '%s': invalid direction %d\n", name, (int)dir);
		return -EINVAL;
	}
	if (!hal_in_segment(data_ptr_addr, sizeof(*data_ptr_addr))) {
		rtapi_print_msg(RTAPI_MSG_ERR,
				"pin '%s': its data pointer is not in HAL shared memory (use hal_malloc)\n",
				name);
		return -EINVAL;
	}
	err = hal_check_lock(HAL_LOCK_LOAD, "create pins");
	if (err)
		return err;
	pin = hal_object_new(HAL_KIND_PIN, sizeof(*pin), name, comp ? hal_off(comp) : 0, &err);
	if (!pin)
		return err;
	dummy = hal_alloc_block(hal_seg, sizeof(*dummy), HAL_KIND_VALUE, comp ? hal_off(comp) : 0);
	if (!dummy) {
		rtapi_print_msg(RTAPI_MSG_ERR, "HAL value memory is full: cannot create pin '%s'\n", name);
		hal_object_delete(&pin->hdr);
		return -ENOMEM;
	}
	pin->dummy_off = hal_off(dummy);
	pin->type = type;
	pin->dir = dir;
	pin->data_ptr_off = hal_off(data_ptr_addr);
	hal_pin_aim(pin, dummy);
	return 0;
}

void hal_pin_unlink_locked(struct hal_pin_rec *pin)
{
	struct hal_sig_rec *sig = hal_ptr(pin->signal_off);

	if (!sig)
		return;
	/* The pin keeps the signal's last value, as if still connected. */
	hal_pin_dummy(pin)->raw = hal_sig_value(sig)->raw;
	hal_pin_aim(pin, hal_pin_dummy(pin));
	pin->signal_off = 0;
	if (pin->dir == HAL_IN)
		sig->readers--;
	else if (pin->dir == HAL_OUT)
		sig->writers--;
	else
		sig->bidirs--;
}

void hal_pin_delete_locked(struct hal_pin_rec *pin)
{
	hal_pin_unlink_locked(pin);
	hal_free_block(hal_seg, hal_pin_dummy(pin));
	hal_object_delete(&pin->hdr);
}

/* The public constructors: one lock, one component check. */
int hal_pin_new(const char *name, hal_type_t type, hal_pin_dir_t dir, void **data_ptr_addr, int comp_id)
{
	struct hal_comp_rec *comp;
	int rc = -EINVAL;

	if (!hal_seg) {
		rtapi_print_msg(RTAPI_MSG_ERR, "pin '%s': call hal_init first\n", name);
		return -EINVAL;
	}
#ifdef ULAPI
	return hal_ul_obj_new(HAL_REQ_PIN_NEW, name, type, dir, data_ptr_addr, comp_id);
#endif
	hal_lock();
	comp = hal_comp_by_id(comp_id);
	if (comp)
		rc = hal_pin_new_locked(name, type, dir, data_ptr_addr, comp);
	hal_unlock();
	if (!comp) {
		rtapi_print_msg(RTAPI_MSG_ERR, "pin '%s': component id %d does not exist\n", name, comp_id);
		rc = -EINVAL;
	}
	return rc;
}

int hal_pin_bit_new(const char *name, hal_pin_dir_t dir, hal_bit_t **data_ptr_addr, int comp_id)
{
	return hal_pin_new(name, HAL_BIT, dir, (void **)data_ptr_addr, comp_id);
}

int hal_pin_float_new(const char *name, hal_pin_dir_t dir, hal_float_t **data_ptr_addr, int comp_id)
{
	return hal_pin_new(name, HAL_FLOAT, dir, (void **)data_ptr_addr, comp_id);
}

int hal_pin_u32_new(const char *name, hal_pin_dir_t dir, hal_u32_t **data_ptr_addr, int comp_id)
{
	return hal_pin_new(name, HAL_U32, dir, (void **)data_ptr_addr, comp_id);
}

int hal_pin_s32_new(const char *name, hal_pin_dir_t dir, hal_s32_t **data_ptr_addr, int comp_id)
{
	return hal_pin_new(name, HAL_S32, dir, (void **)data_ptr_addr, comp_id);
}

static int pin_newfv(hal_type_t type, hal_pin_dir_t dir, void **data_ptr_addr, int comp_id,
		     const char *fmt, va_list ap)
{
	char name[HAL_NAME_LEN + 1];
	int err = hal_format_name(name, "pin", fmt, ap);

	return err ? err : hal_pin_new(name, type, dir, data_ptr_addr, comp_id);
}

int hal_pin_bit_newf(hal_pin_dir_t dir, hal_bit_t **data_ptr_addr, int comp_id, const char *fmt, ...)
{
	va_list ap;
	int rc;

	va_start(ap, fmt);
	rc = pin_newfv(HAL_BIT, dir, (void **)data_ptr_addr, comp_id, fmt, ap);
	va_end(ap);
	return rc;
}

int hal_pin_float_newf(hal_pin_dir_t dir, hal_float_t **data_ptr_addr, int comp_id, const char *fmt, ...)
{
	va_list ap;
	int rc;

	va_start(ap, fmt);
	rc = pin_newfv(HAL_FLOAT, dir, (void **)data_ptr_addr, comp_id, fmt, ap);
	va_end(ap);
	return rc;
}

int hal_pin_u32_newf(hal_pin_dir_t dir, hal_u32_t **data_ptr_addr, int comp_id, const char *fmt, ...)
{
	va_list ap;
	int rc;

	va_start(ap, fmt);
	rc = pin_newfv(HAL_U32, dir, (void **)data_ptr_addr, comp_id, fmt, ap);
	va_end(ap);
	return rc;
}

int hal_pin_s32_newf(hal_pin_dir_t dir, hal_s32_t **data_ptr_addr, int comp_id, const char *fmt, ...)
{
	va_list ap;
	int rc;

	va_start(ap, fmt);
	rc = pin_newfv(HAL_S32, dir, (void **)data_ptr_addr, comp_id, fmt, ap);
	va_end(ap);
	return rc;
}
