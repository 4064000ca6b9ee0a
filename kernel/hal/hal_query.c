/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hal_query.c - the tool-side view of the HAL (hal_query.h): snapshots of every
 * object and checked writes by name, for halcmd, halsampler, halmeter. ULAPI only. */
#include "hal_internal.h"
#include "hal_query.h"
#include "rtapi_string.h"

static bool attached;

int hal_attach(void)
{
	int rc;

	if (attached)
		return 0;
	rc = hal_segment_map();
	if (rc < 0)
		return rc;
	attached = true;
	hal_local_user_new();
	return 0;
}

void hal_detach(void)
{
	if (!attached)
		return;
	attached = false;
	hal_local_user_gone();
}

void hal_release_mutex(void)
{
	if (!hal_seg)
		return;
	if (hal_seg_is_kmod) {	/* the kernel frees it only from a holder that is gone */
		hal_kmod_recover();
		return;
	}
	hal_lock_give(hal_seg);
}

static int need_segment(void)
{
	if (hal_seg)
		return 0;
	rtapi_print_msg(RTAPI_MSG_ERR, "HAL is not attached (call hal_attach first)\n");
	return -EINVAL;
}

static void copy_name(char *dst, const char *src)
{
	rtapi_snprintf(dst, HAL_NAME_LEN + 1, "%s", src);
}

/* A value is read and written through a pointer to its own type, never as a union
 * hal_data member: a parameter is only as aligned as its type (a hal_s32_t inside a
 * component's struct may sit at 4 bytes), and an access through the 8-byte union
 * type at such an address is undefined behaviour (issue 19, item 10). */
static void read_value(union hal_value *v, int type, const volatile void *d)
{
	v->f = 0;
	switch (type) {
	case HAL_BIT: v->b = *(const volatile hal_bit_t *)d; break;
	case HAL_S32: v->s = *(const volatile hal_s32_t *)d; break;
	case HAL_U32: v->u = *(const volatile hal_u32_t *)d; break;
	case HAL_S64: v->ls = (long long)rtapi_load_u64((const volatile rtapi_u64 *)d); break;
	case HAL_U64: v->lu = rtapi_load_u64((const volatile rtapi_u64 *)d); break;
	default: v->f = *(const volatile hal_float_t *)d; break;
	}
}

static void write_value(volatile void *d, int type, const union hal_value *v)
{
	switch (type) {
	case HAL_BIT: *(volatile hal_bit_t *)d = v->b; break;
	case HAL_S32: *(volatile hal_s32_t *)d = v->s; break;
	case HAL_U32: *(volatile hal_u32_t *)d = v->u; break;
	case HAL_S64: rtapi_store_u64((volatile rtapi_u64 *)d, (rtapi_u64)v->ls); break;
	case HAL_U64: rtapi_store_u64((volatile rtapi_u64 *)d, v->lu); break;
	default: *(volatile hal_float_t *)d = v->f; break;
	}
}

static const char *owner_name(const struct hal_obj_hdr *o, int *id)
{
	const struct hal_comp_rec *c = hal_ptr(o->owner_off);

	*id = c ? c->comp_id : 0;
	return c ? c->hdr.name : "hal_lib";	/* threads and their pins: the realtime host */
}

static void comp_info(const struct hal_comp_rec *c, struct hal_comp_info *out)
{
	out->id = c->comp_id;
	copy_name(out->name, c->hdr.name);
	out->is_realtime = c->is_realtime;
	out->is_ready = c->is_ready;
	out->pid = c->pid;
	copy_name(out->module, c->module);
	rtapi_snprintf(out->args, sizeof(out->args), "%s",
		       c->args_off ? (const char *)hal_ptr(c->args_off) : "");
}

static void pin_info(struct hal_pin_rec *p, struct hal_pin_info *out)
{
	const struct hal_obj_hdr *sig = hal_ptr(p->signal_off);

	copy_name(out->name, p->hdr.name);
	copy_name(out->owner, owner_name(&p->hdr, &out->owner_id));
	out->type = p->type;
	out->dir = p->dir;
	read_value(&out->value, p->type, hal_pin_value(p));
	copy_name(out->signal, sig ? sig->name : "");
}

static void param_info(const struct hal_param_rec *p, struct hal_param_info *out)
{
	copy_name(out->name, p->hdr.name);
	copy_name(out->owner, owner_name(&p->hdr, &out->owner_id));
	out->type = p->type;
	out->dir = p->dir;
	read_value(&out->value, p->type, hal_ptr(p->data_off));
}

static void sig_info(const struct hal_sig_rec *s, struct hal_sig_info *out)
{
	copy_name(out->name, s->hdr.name);
	out->type = s->type;
	read_value(&out->value, s->type, hal_sig_value(s));
	out->readers = s->readers;
	out->writers = s->writers;
	out->bidirs = s->bidirs;
}

static void funct_info(const struct hal_funct_rec *f, struct hal_funct_info *out)
{
	copy_name(out->name, f->hdr.name);
	copy_name(out->owner, owner_name(&f->hdr, &out->owner_id));
	out->code_addr = f->funct;
	out->arg = f->arg;
	out->uses_fp = f->uses_fp;
	out->reentrant = f->reentrant;
	out->users = f->users;
}

static void thread_info(struct hal_thread_rec *t, struct hal_thread_info *out)
{
	char time_pin[HAL_NAME_LEN + 8];
	const struct hal_thread_rt *rt;
	struct hal_pin_rec *pin;
	int id;

	copy_name(out->name, t->hdr.name);
	copy_name(out->owner, owner_name(&t->hdr, &id));
	out->period_ns = t->period_ns;
	out->priority = t->priority;
	out->uses_fp = t->uses_fp;
	out->time = 0;
	rtapi_snprintf(time_pin, sizeof(time_pin), "%s.time", t->hdr.name);
	pin = hal_find(HAL_KIND_PIN, time_pin);
	if (pin)	/* time_ptr is the owner's pointer: read through the pin record */
		out->time = hal_pin_value(pin)->s;
	rt = hal_ptr(t->rt_off);
	out->tmax = rt ? rt->tmax : 0;
	out->cycles = rt ? rtapi_load_u64(&rt->cycles) : 0;
	out->cpu_ns = rt ? rtapi_load_u64(&rt->run_ns) : 0;
	out->overruns = rt ? (long long)rtapi_load_u64(&rt->overruns) : 0;
}

/* Each query walks one kind list under the lock; the callbacks copy and return. */
int hal_query_comps(int (*cb)(const struct hal_comp_info *, void *), void *ctx)
{
	struct hal_comp_info info;
	struct hal_obj_hdr *o;
	int n = 0, rc = need_segment();

	if (rc)
		return rc;
	hal_lock();
	for (o = hal_first(HAL_KIND_COMP); o; o = hal_next(o)) {
		comp_info((struct hal_comp_rec *)o, &info);
		n++;
		if (cb(&info, ctx))
			break;
	}
	hal_unlock();
	return n;
}

int hal_query_pins(int (*cb)(const struct hal_pin_info *, void *), void *ctx)
{
	struct hal_pin_info info;
	struct hal_obj_hdr *o;
	int n = 0, rc = need_segment();

	if (rc)
		return rc;
	hal_lock();
	for (o = hal_first(HAL_KIND_PIN); o; o = hal_next(o)) {
		pin_info((struct hal_pin_rec *)o, &info);
		n++;
		if (cb(&info, ctx))
			break;
	}
	hal_unlock();
	return n;
}

int hal_query_params(int (*cb)(const struct hal_param_info *, void *), void *ctx)
{
	struct hal_param_info info;
	struct hal_obj_hdr *o;
	int n = 0, rc = need_segment();

	if (rc)
		return rc;
	hal_lock();
	for (o = hal_first(HAL_KIND_PARAM); o; o = hal_next(o)) {
		param_info((struct hal_param_rec *)o, &info);
		n++;
		if (cb(&info, ctx))
			break;
	}
	hal_unlock();
	return n;
}

int hal_query_sigs(int (*cb)(const struct hal_sig_info *, void *), void *ctx)
{
	struct hal_sig_info info;
	struct hal_obj_hdr *o;
	int n = 0, rc = need_segment();

	if (rc)
		return rc;
	hal_lock();
	for (o = hal_first(HAL_KIND_SIG); o; o = hal_next(o)) {
		sig_info((struct hal_sig_rec *)o, &info);
		n++;
		if (cb(&info, ctx))
			break;
	}
	hal_unlock();
	return n;
}

int hal_query_functs(int (*cb)(const struct hal_funct_info *, void *), void *ctx)
{
	struct hal_funct_info info;
	struct hal_obj_hdr *o;
	int n = 0, rc = need_segment();

	if (rc)
		return rc;
	hal_lock();
	for (o = hal_first(HAL_KIND_FUNCT); o; o = hal_next(o)) {
		funct_info((struct hal_funct_rec *)o, &info);
		n++;
		if (cb(&info, ctx))
			break;
	}
	hal_unlock();
	return n;
}

int hal_query_threads(int (*cb)(const struct hal_thread_info *, void *), void *ctx)
{
	struct hal_thread_info info;
	struct hal_obj_hdr *o;
	int n = 0, rc = need_segment();

	if (rc)
		return rc;
	hal_lock();
	for (o = hal_first(HAL_KIND_THREAD); o; o = hal_next(o)) {
		thread_info((struct hal_thread_rec *)o, &info);
		n++;
		if (cb(&info, ctx))
			break;
	}
	hal_unlock();
	return n;
}

int hal_query_thread_functs(const char *thread_name, int (*cb)(const char *, void *), void *ctx)
{
	struct hal_thread_rec *t;
	rtapi_u32 off;
	int n = 0, rc = need_segment();

	if (rc)
		return rc;
	hal_lock();
	t = hal_find(HAL_KIND_THREAD, thread_name);
	for (off = t ? t->first_entry_off : 0; off;) {
		struct hal_entry_rec *e = hal_ptr(off);

		n++;
		if (cb(((struct hal_obj_hdr *)hal_ptr(e->funct_off))->name, ctx))
			break;
		off = e->next_off;
	}
	hal_unlock();
	return t ? n : -ENOENT;
}

/* Single lookups: the object's record copied under the lock, or -ENOENT. */
int hal_find_comp(const char *name, struct hal_comp_info *out)
{
	struct hal_comp_rec *r;

	if (need_segment())
		return -EINVAL;
	hal_lock();
	r = hal_find(HAL_KIND_COMP, name);
	if (r)
		comp_info(r, out);
	hal_unlock();
	return r ? 0 : -ENOENT;
}

int hal_find_pin(const char *name, struct hal_pin_info *out)
{
	struct hal_pin_rec *r;

	if (need_segment())
		return -EINVAL;
	hal_lock();
	r = hal_find(HAL_KIND_PIN, name);
	if (r)
		pin_info(r, out);
	hal_unlock();
	return r ? 0 : -ENOENT;
}

int hal_find_param(const char *name, struct hal_param_info *out)
{
	struct hal_param_rec *r;

	if (need_segment())
		return -EINVAL;
	hal_lock();
	r = hal_find(HAL_KIND_PARAM, name);
	if (r)
		param_info(r, out);
	hal_unlock();
	return r ? 0 : -ENOENT;
}

int hal_find_sig(const char *name, struct hal_sig_info *out)
{
	struct hal_sig_rec *r;

	if (need_segment())
		return -EINVAL;
	hal_lock();
	r = hal_find(HAL_KIND_SIG, name);
	if (r)
		sig_info(r, out);
	hal_unlock();
	return r ? 0 : -ENOENT;
}

int hal_find_funct(const char *name, struct hal_funct_info *out)
{
	struct hal_funct_rec *r;

	if (need_segment())
		return -EINVAL;
	hal_lock();
	r = hal_find(HAL_KIND_FUNCT, name);
	if (r)
		funct_info(r, out);
	hal_unlock();
	return r ? 0 : -ENOENT;
}

int hal_find_thread(const char *name, struct hal_thread_info *out)
{
	struct hal_thread_rec *r;

	if (need_segment())
		return -EINVAL;
	hal_lock();
	r = hal_find(HAL_KIND_THREAD, name);
	if (r)
		thread_info(r, out);
	hal_unlock();
	return r ? 0 : -ENOENT;
}

/* Raw storage bits of a value of 'type' (union hal_data): requests carry no FP. */
static rtapi_u64 raw_of(int type, const union hal_value *v)
{
	union hal_data d;

	d.raw = 0;
	write_value(&d, type, v);
	return d.raw;
}

/* The object's type decides how the value is stored: look it up first. */
int hal_set_pin_value(const char *name, const union hal_value *v)
{
	struct hal_pin_info info;

	if (need_segment())
		return -EINVAL;
	info.type = HAL_TYPE_UNSPECIFIED;
	hal_find_pin(name, &info);	/* a missing pin is reported by the request */
	return hal_ul_set(HAL_REQ_SET_PIN, name, info.type, raw_of(info.type, v));
}

int hal_set_param_value(const char *name, const union hal_value *v)
{
	struct hal_param_info info;

	if (need_segment())
		return -EINVAL;
	info.type = HAL_TYPE_UNSPECIFIED;
	hal_find_param(name, &info);
	return hal_ul_set(HAL_REQ_SET_PARAM, name, info.type, raw_of(info.type, v));
}

int hal_set_sig_value(const char *name, const union hal_value *v)
{
	struct hal_sig_info info;

	if (need_segment())
		return -EINVAL;
	info.type = HAL_TYPE_UNSPECIFIED;
	hal_find_sig(name, &info);
	return hal_ul_set(HAL_REQ_SET_SIG, name, info.type, raw_of(info.type, v));
}

int hal_release_module(const char *module)
{
	if (need_segment())
		return -EINVAL;
	return hal_ul_names(HAL_REQ_MODULE_RELEASE, module, 0, 0);
}

bool hal_threads_running(void)
{
	return hal_seg && __atomic_load_n(&hal_seg->threads_running, __ATOMIC_ACQUIRE);
}

long long hal_base_period(void)
{
	return hal_seg ? hal_seg->base_period_ns : 0;
}

int hal_memory_usage(unsigned long *used, unsigned long *total)
{
	if (need_segment())
		return -EINVAL;
	*used = hal_seg->heap_start + hal_seg->bytes_used + hal_seg->val_bytes_used;
	*total = hal_seg->size;
	return 0;
}

int hal_set_exact_periods(void)
{
	if (need_segment())
		return -EINVAL;
	return hal_ul_names(HAL_REQ_SET_EXACT, 0, 0, 0);
}

int hal_object_counts(struct hal_counts *out)
{
	if (need_segment())
		return -EINVAL;
	hal_lock();
	out->comps = (int)hal_seg->count[HAL_KIND_COMP];
	out->pins = (int)hal_seg->count[HAL_KIND_PIN];
	out->params = (int)hal_seg->count[HAL_KIND_PARAM];
	out->aliases = (int)hal_seg->alias_count;
	out->sigs = (int)hal_seg->count[HAL_KIND_SIG];
	out->functs = (int)hal_seg->count[HAL_KIND_FUNCT];
	out->threads = (int)hal_seg->count[HAL_KIND_THREAD];
	hal_unlock();
	return 0;
}
