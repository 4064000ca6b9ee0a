/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hal_signal.c - signals and links (hal_signal_new(3hal)): a signal holds the
 * value; linking aims the pin's owner pointer at it. At most one writer. */
#include "hal_internal.h"

int hal_signal_new_locked(const char *name, hal_type_t type)
{
	struct hal_sig_rec *sig;
	union hal_data *value;
	int err;

	if (type != HAL_BIT && type != HAL_FLOAT && type != HAL_S32 && type != HAL_U32 &&
	    type != HAL_S64 && type != HAL_U64) {
		rtapi_print_msg(RTAPI_MSG_ERR, "signal '%s': invalid type %d\n", name, (int)type);
		return -EINVAL;
	}
	err = hal_check_lock(HAL_LOCK_CONFIG, "create signals");
	if (err)
		return err;
	sig = hal_object_new(HAL_KIND_SIG, sizeof(*sig), name, 0, &err);
	if (!sig)
		return err;
	value = hal_alloc_block(hal_seg, sizeof(*value), HAL_KIND_VALUE, 0);
	if (!value) {
		rtapi_print_msg(RTAPI_MSG_ERR, "HAL value memory is full: cannot create signal '%s'\n",
				name);
		hal_object_delete(&sig->hdr);
		return -ENOMEM;
	}
	sig->value_off = hal_off(value);
	sig->type = type;
	return 0;
}

int hal_signal_new(const char *signal_name, hal_type_t type)
{
	int rc;

	if (!hal_seg) {
		rtapi_print_msg(RTAPI_MSG_ERR, "signal '%s': call hal_init first\n", signal_name);
		return -EINVAL;
	}
#ifdef ULAPI
	return hal_ul_set(HAL_REQ_SIG_NEW, signal_name, type, 0);
#endif
	hal_lock();
	rc = hal_signal_new_locked(signal_name, type);
	hal_unlock();
	return rc;
}

int hal_signal_delete_locked(const char *name)
{
	struct hal_sig_rec *sig;
	struct hal_obj_hdr *o;
	rtapi_u32 sig_off;
	int err;

	err = hal_check_lock(HAL_LOCK_CONFIG, "delete signals");
	if (err)
		return err;
	sig = hal_find(HAL_KIND_SIG, name);
	if (!sig) {
		rtapi_print_msg(RTAPI_MSG_ERR, "signal '%s' does not exist\n", name);
		return -ENOENT;
	}
	sig_off = hal_off(sig);
	for (o = hal_first(HAL_KIND_PIN); o && sig->readers + sig->writers + sig->bidirs; o = hal_next(o))
		if (((struct hal_pin_rec *)o)->signal_off == sig_off)
			hal_pin_unlink_locked((struct hal_pin_rec *)o);
	hal_free_block(hal_seg, hal_sig_value(sig));
	hal_object_delete(&sig->hdr);
	return 0;
}

int hal_signal_delete(const char *signal_name)
{
	int rc;

	if (!hal_seg)
		return -EINVAL;
#ifdef ULAPI
	return hal_ul_names(HAL_REQ_SIG_DELETE, signal_name, 0, 0);
#endif
	hal_lock();
	rc = hal_signal_delete_locked(signal_name);
	hal_unlock();
	return rc;
}

/* Name of the pin that writes 'sig' (for messages), or "?" */
static const char *writer_of(struct hal_sig_rec *sig)
{
	rtapi_u32 sig_off = hal_off(sig);
	struct hal_obj_hdr *o;

	for (o = hal_first(HAL_KIND_PIN); o; o = hal_next(o)) {
		struct hal_pin_rec *p = (struct hal_pin_rec *)o;

		if (p->signal_off == sig_off && p->dir != HAL_IN)
			return o->name;
	}
	return "?";
}

int hal_link_locked(const char *pin_name, const char *sig_name)
{
	struct hal_pin_rec *pin;
	struct hal_sig_rec *sig;
	int err;

	err = hal_check_lock(HAL_LOCK_CONFIG, "link pins");
	if (err)
		return err;
	pin = hal_find(HAL_KIND_PIN, pin_name);
	if (!pin) {
		rtapi_print_msg(RTAPI_MSG_ERR, "pin '%s' does not exist\n", pin_name);
		return -ENOENT;
	}
	sig = hal_find(HAL_KIND_SIG, sig_name);
	if (!sig) {
		rtapi_print_msg(RTAPI_MSG_ERR, "signal '%s' does not exist\n", sig_name);
		return -ENOENT;
	}
	if (pin->signal_off == hal_off(sig))
		return 0;
	if (pin->signal_off) {
		rtapi_print_msg(RTAPI_MSG_ERR, "pin '%s' is already linked to signal '%s'\n", pin_name,
				((struct hal_obj_hdr *)hal_ptr(pin->signal_off))->name);
		return -EBUSY;
	}
	if (pin->type != sig->type) {
		rtapi_print_msg(RTAPI_MSG_ERR, "type mismatch: pin '%s' is %s but signal '%s' is %s\n",
				pin_name, hal_type_name(pin->type), sig_name, hal_type_name(sig->type));
		return -EINVAL;
	}
	if ((pin->dir == HAL_OUT && (sig->writers || sig->bidirs)) ||
	    (pin->dir == HAL_IO && sig->writers)) {
		rtapi_print_msg(RTAPI_MSG_ERR,
				"signal '%s' already has writer '%s': cannot add %s pin '%s'\n",
				sig_name, writer_of(sig), pin->dir == HAL_OUT ? "output" : "I/O",
				pin_name);
		return -EPERM;
	}
	/* The first pin on a signal gives it its value, so a setp before net is kept. */
	if (sig->readers + sig->writers + sig->bidirs == 0)
		hal_sig_value(sig)->raw = hal_pin_dummy(pin)->raw;
	pin->signal_off = hal_off(sig);
	hal_pin_aim(pin, hal_sig_value(sig));
	if (pin->dir == HAL_IN)
		sig->readers++;
	else if (pin->dir == HAL_OUT)
		sig->writers++;
	else
		sig->bidirs++;
	return 0;
}

int hal_link(const char *pin_name, const char *signal_name)
{
	int rc;

	if (!hal_seg)
		return -EINVAL;
#ifdef ULAPI
	return hal_ul_names(HAL_REQ_LINK, pin_name, signal_name, 0);
#endif
	hal_lock();
	rc = hal_link_locked(pin_name, signal_name);
	hal_unlock();
	return rc;
}

int hal_unlink_locked(const char *pin_name)
{
	struct hal_pin_rec *pin;
	int rc = hal_check_lock(HAL_LOCK_CONFIG, "unlink pins");

	if (rc)
		return rc;
	pin = hal_find(HAL_KIND_PIN, pin_name);
	if (!pin) {
		rtapi_print_msg(RTAPI_MSG_ERR, "pin '%s' does not exist\n", pin_name);
		return -ENOENT;
	}
	hal_pin_unlink_locked(pin);
	return 0;
}

int hal_unlink(const char *pin_name)
{
	int rc;

	if (!hal_seg)
		return -EINVAL;
#ifdef ULAPI
	return hal_ul_names(HAL_REQ_UNLINK, pin_name, 0, 0);
#endif
	hal_lock();
	rc = hal_unlink_locked(pin_name);
	hal_unlock();
	return rc;
}
