/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hal_funct.c - realtime functions (hal_export_funct(3hal)) and their places in
 * threads (hal_add_funct_to_thread(3hal)). Every function gets a <name>.time pin
 * and a <name>.tmax parameter (RULINGS.md "function timing"). */
#include "hal_internal.h"
#include "rtapi_string.h"

int hal_timing_objects_new(const char *name, hal_s32_t **time_ptr, rtapi_s32 *tmax,
			   struct hal_comp_rec *comp)
{
	char buf[HAL_NAME_LEN + 8];
	int err;

	rtapi_snprintf(buf, sizeof(buf), "%s.time", name);
	err = hal_pin_new_locked(buf, HAL_S32, HAL_OUT, (void **)time_ptr, comp);
	if (err)
		return err;
	rtapi_snprintf(buf, sizeof(buf), "%s.tmax", name);
	err = hal_param_new_locked(buf, HAL_S32, HAL_RW, tmax, comp);
	if (err) {
		rtapi_snprintf(buf, sizeof(buf), "%s.time", name);
		hal_pin_delete_locked(hal_find(HAL_KIND_PIN, buf));
	}
	return err;
}

void hal_timing_objects_delete(const char *name)
{
	char buf[HAL_NAME_LEN + 8];
	struct hal_pin_rec *pin;
	struct hal_param_rec *param;

	rtapi_snprintf(buf, sizeof(buf), "%s.time", name);
	pin = hal_find(HAL_KIND_PIN, buf);
	if (pin)
		hal_pin_delete_locked(pin);
	rtapi_snprintf(buf, sizeof(buf), "%s.tmax", name);
	param = hal_find(HAL_KIND_PARAM, buf);
	if (param)
		hal_param_delete_locked(param);
}

static int export_locked(const char *name, hal_funct_t funct, void *arg, int uses_fp, int reentrant,
			 struct hal_comp_rec *comp)
{
	struct hal_funct_rec *f;
	int err;

	if (!funct) {
		rtapi_print_msg(RTAPI_MSG_ERR, "function '%s': code address is NULL\n", name);
		return -EINVAL;
	}
	err = hal_check_lock(HAL_LOCK_LOAD, "export functions");
	if (err)
		return err;
	f = hal_object_new(HAL_KIND_FUNCT, sizeof(*f), name, hal_off(comp), &err);
	if (!f)
		return err;
	f->funct = (rtapi_u64)(unsigned long)funct;
	f->arg = (rtapi_u64)(unsigned long)arg;
	f->module = hal_load_module();
	f->uses_fp = uses_fp != 0;
	f->reentrant = reentrant != 0;
	err = hal_timing_objects_new(name, &f->time_ptr, &f->tmax, comp);
	if (err)
		hal_object_delete(&f->hdr);
	return err;
}

int hal_export_funct(const char *name, hal_funct_t funct, void *arg, int uses_fp, int reentrant, int comp_id)
{
	struct hal_comp_rec *comp;
	int rc = -EINVAL;

#ifdef ULAPI
	rtapi_print_msg(RTAPI_MSG_ERR,
			"function '%s': only realtime components can export functions\n", name);
	return -EINVAL;
#endif
	if (!hal_seg) {
		rtapi_print_msg(RTAPI_MSG_ERR, "function '%s': call hal_init first\n", name);
		return -EINVAL;
	}
	hal_lock();
	comp = hal_comp_by_id(comp_id);
	if (comp)
		rc = export_locked(name, funct, arg, uses_fp, reentrant, comp);
	hal_unlock();
	if (!comp)
		rtapi_print_msg(RTAPI_MSG_ERR, "function '%s': component id %d does not exist\n",
				name, comp_id);
	return rc;
}

void hal_funct_delete_locked(struct hal_funct_rec *f)
{
	hal_funct_remove_from_threads(f);
	if (f->puts_pending)
		hal_threads_quiesce();
	hal_timing_objects_delete(f->hdr.name);
	hal_object_delete(&f->hdr);
}

/* Unlink from thread 't' every entry whose function is 'f' or, with f NULL, is
 * owned by component 'owner_off'. One pass; count and tail are rebuilt on the way,
 * then the dispatch table. The caller quiesces (the old table, module references). */
static void remove_entries(struct hal_thread_rec *t, struct hal_funct_rec *f, rtapi_u32 owner_off)
{
	rtapi_u32 *link = &t->first_entry_off, before = t->entry_count;

	t->entry_count = 0;
	t->last_entry_off = 0;
	while (*link) {
		struct hal_entry_rec *e = hal_ptr(*link);
		struct hal_funct_rec *ef = hal_ptr(e->funct_off);

		if (f ? ef == f : ef->hdr.owner_off == owner_off) {
			__atomic_store_n(link, e->next_off, __ATOMIC_RELEASE);
			hal_free_block(hal_seg, e);
			ef->users--;
			ef->puts_pending++;	/* hal_threads_quiesce() drops its module reference */
		} else {
			t->entry_count++;
			t->last_entry_off = *link;
			link = &e->next_off;
		}
	}
	if (t->entry_count != before)
		hal_dispatch_shrink(t);
}

void hal_funct_remove_from_threads(struct hal_funct_rec *f)
{
	struct hal_obj_hdr *o;

	for (o = hal_first(HAL_KIND_THREAD); o && f->users > 0; o = hal_next(o))
		remove_entries((struct hal_thread_rec *)o, f, 0);
}

void hal_comp_functs_remove_from_threads(rtapi_u32 comp_off)
{
	struct hal_obj_hdr *o;

	for (o = hal_first(HAL_KIND_THREAD); o; o = hal_next(o))
		remove_entries((struct hal_thread_rec *)o, 0, comp_off);
}

/* Take entry 'e' out of the list of 't' and free it (not yet in any dispatch table). */
static void unlink_entry(struct hal_thread_rec *t, struct hal_entry_rec *e)
{
	rtapi_u32 *link = &t->first_entry_off, prev = 0;

	while (*link && *link != hal_off(e)) {
		prev = *link;
		link = &((struct hal_entry_rec *)hal_ptr(*link))->next_off;
	}
	*link = e->next_off;
	if (t->last_entry_off == hal_off(e))
		t->last_entry_off = prev;
	t->entry_count--;
	hal_free_block(hal_seg, e);
}

int hal_add_funct_locked(const char *funct_name, const char *thread_name, int position)
{
	struct hal_funct_rec *f;
	struct hal_thread_rec *t;
	struct hal_entry_rec *e;
	rtapi_u32 *link;
	int n = 0, index, err;

	err = hal_check_lock(HAL_LOCK_CONFIG, "add functions to threads");
	if (err)
		return err;
	f = hal_find(HAL_KIND_FUNCT, funct_name);
	if (!f) {
		rtapi_print_msg(RTAPI_MSG_ERR, "function '%s' does not exist\n", funct_name);
		return -ENOENT;
	}
	t = hal_find(HAL_KIND_THREAD, thread_name);
	if (!t) {
		rtapi_print_msg(RTAPI_MSG_ERR, "thread '%s' does not exist\n", thread_name);
		return -ENOENT;
	}
	if (f->users > 0 && !f->reentrant) {
		rtapi_print_msg(RTAPI_MSG_ERR,
				"function '%s' is already on a thread and is not reentrant\n", funct_name);
		return -EBUSY;
	}
	if (f->uses_fp && !t->uses_fp) {
		rtapi_print_msg(RTAPI_MSG_ERR,
				"function '%s' uses floating point but thread '%s' was created without it\n",
				funct_name, thread_name);
		return -EINVAL;
	}
	n = (int)t->entry_count;
	/* position: +1 first, +k k-th; -1 last, -k k-th from the end; 0 illegal */
	index = position > 0 ? position - 1 : n + 1 + position;
	if (position == 0 || index < 0 || index > n) {
		rtapi_print_msg(RTAPI_MSG_ERR,
				"position %d is not valid for thread '%s' with %d functions\n",
				position, thread_name, n);
		return -EINVAL;
	}
	/* While on a thread, the function's module cannot be unloaded (kernel flavor). */
	err = hal_os_code_get(f->module);
	if (err) {
		rtapi_print_msg(RTAPI_MSG_ERR, "function '%s': its module is being unloaded\n",
				funct_name);
		return err;
	}
	e = hal_alloc_block(hal_seg, sizeof(*e), HAL_KIND_ENTRY, 0);
	if (!e) {
		hal_os_code_put(f->module);
		rtapi_print_msg(RTAPI_MSG_ERR, "HAL shared memory is full: cannot add '%s' to '%s'\n",
				funct_name, thread_name);
		return -ENOMEM;
	}
	if (index == n && n > 0) {	/* appending, as addf does: O(1) */
		link = &((struct hal_entry_rec *)hal_ptr(t->last_entry_off))->next_off;
	} else {
		for (link = &t->first_entry_off; index > 0; index--)
			link = &((struct hal_entry_rec *)hal_ptr(*link))->next_off;
	}
	e->funct_off = hal_off(f);
	e->next_off = *link;
	*link = hal_off(e);
	if (e->next_off == 0)
		t->last_entry_off = hal_off(e);
	t->entry_count++;
	/* The thread runs the dispatch table, not the list: addf takes effect here. */
	err = e->next_off == 0 ? hal_dispatch_append(t) : hal_dispatch_rebuild(t);
	if (err) {
		unlink_entry(t, e);
		hal_os_code_put(f->module);
		rtapi_print_msg(RTAPI_MSG_ERR, "HAL shared memory is full: cannot add '%s' to '%s'\n",
				funct_name, thread_name);
		return err;
	}
	if (t->retired_off)
		hal_threads_quiesce();	/* the replaced table */
	f->users++;
	return 0;
}

int hal_add_funct_to_thread(const char *funct_name, const char *thread_name, int position)
{
	int rc;

	if (!hal_seg)
		return -EINVAL;
#ifdef ULAPI
	return hal_ul_names(HAL_REQ_ADDF, funct_name, thread_name, position);
#endif
	hal_lock();
	rc = hal_add_funct_locked(funct_name, thread_name, position);
	hal_unlock();
	return rc;
}

int hal_del_funct_locked(const char *funct_name, const char *thread_name)
{
	struct hal_funct_rec *f;
	struct hal_thread_rec *t;
	rtapi_u32 *link, prev = 0;
	int err;

	err = hal_check_lock(HAL_LOCK_CONFIG, "remove functions from threads");
	if (err)
		return err;
	f = hal_find(HAL_KIND_FUNCT, funct_name);
	if (!f) {
		rtapi_print_msg(RTAPI_MSG_ERR, "function '%s' does not exist\n", funct_name);
		return -ENOENT;
	}
	t = hal_find(HAL_KIND_THREAD, thread_name);
	if (!t) {
		rtapi_print_msg(RTAPI_MSG_ERR, "thread '%s' does not exist\n", thread_name);
		return -ENOENT;
	}
	for (link = &t->first_entry_off; *link; link = &((struct hal_entry_rec *)hal_ptr(*link))->next_off) {
		struct hal_entry_rec *e = hal_ptr(*link);

		if (e->funct_off == hal_off(f)) {
			*link = e->next_off;
			if (t->last_entry_off == hal_off(e))
				t->last_entry_off = prev;
			t->entry_count--;
			f->users--;
			f->puts_pending++;
			hal_free_block(hal_seg, e);	/* the thread reads the table, not entries */
			hal_dispatch_shrink(t);
			hal_threads_quiesce();	/* then the old table and the module may go */
			return 0;
		}
		prev = *link;
	}
	rtapi_print_msg(RTAPI_MSG_ERR, "function '%s' is not on thread '%s'\n", funct_name, thread_name);
	return -ENOENT;
}

int hal_del_funct_from_thread(const char *funct_name, const char *thread_name)
{
	int rc;

	if (!hal_seg)
		return -EINVAL;
#ifdef ULAPI
	return hal_ul_names(HAL_REQ_DELF, funct_name, thread_name, 0);
#endif
	hal_lock();
	rc = hal_del_funct_locked(funct_name, thread_name);
	hal_unlock();
	return rc;
}
