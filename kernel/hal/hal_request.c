/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hal_request.c - the one place where configuration requests from userspace are
 * checked and carried out (hal_request.h). The simulated flavor's ulapi calls
 * hal_req_execute() in the process; the kernel flavor's hal_lib.ko calls it from the
 * /dev/rtapi ioctl for a user who may be hostile, so everything in the request is
 * checked here: names terminated, types and directions known, offsets inside the
 * caller's own userspace-component memory, components the caller's own. Values travel
 * as raw bits: no floating point here (the kernel builds this file without SSE).
 * Caller holds the HAL mutex. */
#include "hal_internal.h"
#include "rtapi_string.h"

static bool name_ok(const char *field, const char *what)
{
	if (memchr(field, 0, HAL_REQ_NAME_LEN))
		return true;
	rtapi_print_msg(RTAPI_MSG_ERR, "HAL request: the %s is not a string of at most %d characters\n",
			what, HAL_NAME_LEN);
	return false;
}

static bool type_ok(int type)
{
	return type == HAL_BIT || type == HAL_FLOAT || type == HAL_S32 || type == HAL_U32 ||
	       type == HAL_S64 || type == HAL_U64;
}

/* Store raw bits as a value of 'type' (a bit is normalised to 0/1), through a pointer
 * to the value's own type: a parameter is only as aligned as its type, so an access
 * through union hal_data (8-byte aligned) would be undefined behaviour. */
static void store_raw(volatile void *d, int type, rtapi_u64 raw)
{
	switch (type) {
	case HAL_BIT: *(volatile hal_bit_t *)d = (raw & 0xff) != 0; break;
	case HAL_S32: *(volatile hal_s32_t *)d = (rtapi_s32)(rtapi_u32)raw; break;
	case HAL_U32: *(volatile hal_u32_t *)d = (rtapi_u32)raw; break;
	default: rtapi_store_u64((volatile rtapi_u64 *)d, raw); break;	/* 64 bits: no tearing */
	}
}

/* A userspace component of the caller's, or NULL with a message. */
static struct hal_comp_rec *own_comp(int comp_id, const struct hal_caller *c, const char *what)
{
	struct hal_comp_rec *comp = hal_comp_by_id(comp_id);

	if (!comp) {
		rtapi_print_msg(RTAPI_MSG_ERR, "%s: component id %d does not exist\n", what, comp_id);
		return 0;
	}
	if (comp->is_realtime || comp->pid != c->pid) {
		rtapi_print_msg(RTAPI_MSG_ERR, "%s: component '%s' is not this process's\n", what,
				comp->hdr.name);
		return 0;
	}
	return comp;
}

/* 'off' .. off+len inside hal_malloc() memory of the caller's component 'comp'. */
static bool own_memory(struct hal_comp_rec *comp, rtapi_u32 off, rtapi_u32 len, const char *name)
{
	if (off % 4 == 0 && hal_umalloc_owned(hal_seg, hal_off(comp), off, len))
		return true;
	rtapi_print_msg(RTAPI_MSG_ERR, "'%s': its data is not in hal_malloc memory of component '%s'\n",
			name, comp->hdr.name);
	return false;
}

static int value_size(int type)
{
	return type == HAL_BIT ? 1 : (type == HAL_S32 || type == HAL_U32) ? 4 : 8;
}

static int comp_exit(struct hal_req *r, const struct hal_caller *c)
{
	struct hal_comp_rec *comp = hal_comp_by_id(r->comp_id);

	if (!comp) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hal_exit: component id %d does not exist\n", r->comp_id);
		return -EINVAL;
	}
	if (comp->is_realtime) {
		rtapi_print_msg(RTAPI_MSG_ERR,
				"component '%s' is realtime: unload it with unloadrt\n", comp->hdr.name);
		return -EPERM;
	}
	/* Another process's component only once that process is gone (halcmd cleans up
	 * after a userspace component that died without hal_exit). */
	if (c->is_user && comp->pid != c->pid && hal_os_pid_alive(comp->pid)) {
		rtapi_print_msg(RTAPI_MSG_ERR,
				"component '%s' belongs to process %d, which is running: stop it instead\n",
				comp->hdr.name, (int)comp->pid);
		return -EPERM;
	}
	r->arg = comp->pid == c->pid;	/* out: was it the caller's own (a local user) */
	hal_comp_delete_locked(comp);
	return 0;
}

static int comp_ready(struct hal_req *r, const struct hal_caller *c, int ready)
{
	const char *what = ready ? "hal_ready" : "hal_unready";
	struct hal_comp_rec *comp = c->is_user ? own_comp(r->comp_id, c, what)
					       : hal_comp_by_id(r->comp_id);

	if (!comp)
		return -EINVAL;
	comp->is_ready = ready;
	return 0;
}

static int user_malloc(struct hal_req *r, const struct hal_caller *c)
{
	struct hal_comp_rec *comp = own_comp(r->comp_id, c, "hal_malloc");
	void *p;

	if (!comp)
		return -EINVAL;
	if (r->value == 0 || r->value >= hal_seg->size) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hal_malloc: bad size %llu\n", (unsigned long long)r->value);
		return -EINVAL;
	}
	p = hal_alloc_block(hal_seg, (rtapi_u32)r->value, HAL_KIND_UMALLOC, hal_off(comp));
	if (!p) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hal_malloc: HAL value memory is full (%llu bytes wanted)\n",
				(unsigned long long)r->value);
		return -ENOMEM;
	}
	r->off = hal_off(p);
	return 0;
}

static int obj_new(struct hal_req *r, const struct hal_caller *c)
{
	bool pin = r->op == HAL_REQ_PIN_NEW;
	struct hal_comp_rec *comp = own_comp(r->comp_id, c, r->name);

	if (!comp)
		return -EINVAL;
	if (!type_ok(r->type)) {
		rtapi_print_msg(RTAPI_MSG_ERR, "'%s': invalid type %d\n", r->name, r->type);
		return -EINVAL;
	}
	if (!own_memory(comp, r->off, pin ? 8 : (rtapi_u32)value_size(r->type), r->name))
		return -EINVAL;
	if (pin)
		return hal_pin_new_locked(r->name, r->type, r->dir, hal_ptr(r->off), comp);
	return hal_param_new_locked(r->name, r->type, r->dir, hal_ptr(r->off), comp);
}

/* hal_query.h promises -EACCES for a locked HAL, so halcmd can tell it from -EPERM. */
static int params_locked(const char *what)
{
	return hal_check_lock(HAL_LOCK_PARAMS, what) ? -EACCES : 0;
}

static bool same_type(const char *kind, const char *name, int have, int want)
{
	if (have == want)
		return true;
	rtapi_print_msg(RTAPI_MSG_ERR, "%s '%s' is %s, not %s\n", kind, name, hal_type_name(have),
			hal_type_name(want));
	return false;
}

static int set_pin(struct hal_req *r)
{
	struct hal_pin_rec *pin;
	int rc = params_locked("set pins");

	if (rc)
		return rc;
	pin = hal_find(HAL_KIND_PIN, r->name);
	if (!pin) {
		rtapi_print_msg(RTAPI_MSG_ERR, "pin '%s' does not exist\n", r->name);
		return -ENOENT;
	}
	if (pin->dir == HAL_OUT) {
		rtapi_print_msg(RTAPI_MSG_ERR, "pin '%s' is an output: only its component sets it\n",
				r->name);
		return -EPERM;
	}
	if (pin->signal_off) {
		rtapi_print_msg(RTAPI_MSG_ERR, "pin '%s' is linked to signal '%s': use sets instead\n",
				r->name, ((struct hal_obj_hdr *)hal_ptr(pin->signal_off))->name);
		return -EBUSY;
	}
	if (!same_type("pin", r->name, pin->type, r->type))
		return -EINVAL;
	store_raw(hal_pin_dummy(pin), pin->type, r->value);
	return 0;
}

/* setp on a parameter; with 'owner' (hal_param_set from its userspace component) also
 * read-only ones, but only the caller's own. */
static int set_param(struct hal_req *r, const struct hal_caller *owner)
{
	struct hal_param_rec *param;
	int rc = owner ? 0 : params_locked("set parameters");

	if (rc)
		return rc;
	param = hal_find(HAL_KIND_PARAM, r->name);
	if (!param) {
		rtapi_print_msg(RTAPI_MSG_ERR, "parameter '%s' does not exist\n", r->name);
		return -ENOENT;
	}
	if (owner) {
		struct hal_comp_rec *oc = hal_ptr(param->hdr.owner_off);

		if (!oc || !own_comp(oc->comp_id, owner, r->name))
			return -EPERM;
	}
	if (!owner && param->dir != HAL_RW) {
		rtapi_print_msg(RTAPI_MSG_ERR, "parameter '%s' is read-only\n", r->name);
		return -EPERM;
	}
	if (!same_type("parameter", r->name, param->type, r->type))
		return -EINVAL;
	store_raw(hal_ptr(param->data_off), param->type, r->value);
	return 0;
}

static int set_sig(struct hal_req *r)
{
	struct hal_sig_rec *sig;
	int rc = params_locked("set signals");

	if (rc)
		return rc;
	sig = hal_find(HAL_KIND_SIG, r->name);
	if (!sig) {
		rtapi_print_msg(RTAPI_MSG_ERR, "signal '%s' does not exist\n", r->name);
		return -ENOENT;
	}
	if (sig->writers) {
		rtapi_print_msg(RTAPI_MSG_ERR, "signal '%s' already has a writer: cannot set it\n",
				r->name);
		return -EPERM;
	}
	if (!same_type("signal", r->name, sig->type, r->type))
		return -EINVAL;
	store_raw(hal_sig_value(sig), sig->type, r->value);
	return 0;
}

/* Before a module is unloaded: its functions leave every thread (and the threads are
 * quiesced), so the module references those entries hold are dropped. */
static int module_release(struct hal_req *r)
{
	struct hal_obj_hdr *o;
	int n = 0;

	for (o = hal_first(HAL_KIND_COMP); o; o = hal_next(o)) {
		struct hal_comp_rec *comp = (struct hal_comp_rec *)o;

		if (comp->is_realtime && (!r->name[0] || strcmp(comp->module, r->name) == 0)) {
			hal_comp_functs_remove_from_threads(hal_off(comp));
			n++;
		}
	}
	hal_threads_quiesce();	/* drops the module references of the removed entries */
	return n;
}

/* halcmd's crash clean-up: a userspace component whose process is gone (comp_id 0:
 * every such component; the result is how many were removed). No message: -ENOENT no
 * such component, -EPERM realtime, -EBUSY its process is alive. */
static int remove_dead_one(struct hal_comp_rec *comp, const struct hal_caller *c)
{
	if (comp->is_realtime)
		return -EPERM;
	if (comp->pid == c->pid || hal_os_pid_alive(comp->pid))
		return -EBUSY;
	hal_comp_delete_locked(comp);
	return 0;
}

static int comp_remove_dead(struct hal_req *r, const struct hal_caller *c)
{
	struct hal_obj_hdr *o, *next;
	struct hal_comp_rec *comp;
	int removed = 0;

	if (r->comp_id) {
		comp = hal_comp_by_id(r->comp_id);
		return comp ? remove_dead_one(comp, c) : -ENOENT;
	}
	for (o = hal_first(HAL_KIND_COMP); o; o = next) {
		next = hal_next(o);
		if (remove_dead_one((struct hal_comp_rec *)o, c) == 0)
			removed++;
	}
	return removed;
}

static int alias_kind(int arg, enum hal_kind *kind)
{
	if (arg != 0 && arg != 1) {
		rtapi_print_msg(RTAPI_MSG_ERR, "HAL request: alias kind %d is not valid\n", arg);
		return -EINVAL;
	}
	*kind = arg ? HAL_KIND_PARAM : HAL_KIND_PIN;
	return 0;
}

int hal_req_execute(struct hal_req *r, const struct hal_caller *c)
{
	enum hal_kind kind;

	r->msg[0] = 0;
	if (!name_ok(r->name, "name") || !name_ok(r->name2, "second name"))
		return -EINVAL;
	switch (r->op) {
	case HAL_REQ_COMP_NEW:
		/* value: where the caller maps the segment; only its own pins point there */
		return hal_comp_new_locked(r->name, false, c->pid, r->value);
	case HAL_REQ_COMP_READY:
		return comp_ready(r, c, 1);
	case HAL_REQ_COMP_UNREADY:
		return comp_ready(r, c, 0);
	case HAL_REQ_COMP_EXIT:
		return comp_exit(r, c);
	case HAL_REQ_MALLOC:
		return user_malloc(r, c);
	case HAL_REQ_PIN_NEW:
	case HAL_REQ_PARAM_NEW:
		return obj_new(r, c);
	case HAL_REQ_PARAM_SET_OWN:
		return set_param(r, c);
	case HAL_REQ_SIG_NEW:
		return hal_signal_new_locked(r->name, r->type);
	case HAL_REQ_SIG_DELETE:
		return hal_signal_delete_locked(r->name);
	case HAL_REQ_LINK:
		return hal_link_locked(r->name, r->name2);
	case HAL_REQ_UNLINK:
		return hal_unlink_locked(r->name);
	case HAL_REQ_ADDF:
		return hal_add_funct_locked(r->name, r->name2, r->arg);
	case HAL_REQ_DELF:
		return hal_del_funct_locked(r->name, r->name2);
	case HAL_REQ_START:
	case HAL_REQ_STOP:
		return hal_set_running_locked(r->op == HAL_REQ_START);
	case HAL_REQ_SET_LOCK:
		if (r->arg < 0 || r->arg > HAL_LOCK_ALL) {
			rtapi_print_msg(RTAPI_MSG_ERR, "HAL request: lock level %d is not valid\n", r->arg);
			return -EINVAL;
		}
		return hal_set_lock_locked((unsigned)r->arg);
	case HAL_REQ_SET_PIN:
		return set_pin(r);
	case HAL_REQ_SET_PARAM:
		return set_param(r, 0);
	case HAL_REQ_SET_SIG:
		return set_sig(r);
	case HAL_REQ_MODULE_RELEASE:
		return module_release(r);
	case HAL_REQ_ALIAS:
		if (alias_kind(r->arg, &kind))
			return -EINVAL;
		return hal_alias_set_locked(kind, r->name, r->name2);
	case HAL_REQ_UNALIAS:
		if (alias_kind(r->arg, &kind))
			return -EINVAL;
		return hal_unalias_locked(kind, r->name);
	case HAL_REQ_SET_EXACT:
		return hal_set_exact_periods_locked();
	case HAL_REQ_COMP_REMOVE_DEAD:
		return comp_remove_dead(r, c);
	default:
		rtapi_print_msg(RTAPI_MSG_ERR, "HAL request: unknown operation %u\n", (unsigned)r->op);
		return -EINVAL;
	}
}
