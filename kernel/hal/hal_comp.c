/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hal_comp.c - components: hal_init, hal_ready, hal_exit, hal_malloc,
 * hal_set_constructor, and the module host's hooks (hal_host.h). */
#include "hal_internal.h"
#include "hal_host.h"
#include "hal_query.h"
#include "rtapi_string.h"

rtapi_u32 hal_current_comp_off;

/* Set by the module host around rtapi_app_main(); recorded by hal_init(). */
static char load_module[HAL_NAME_LEN + 1];
static const char *load_args;

static int comp_ids_issued;	/* for names of anonymous components */

struct hal_comp_rec *hal_comp_by_id(int comp_id)
{
	struct hal_obj_hdr *o;

	for (o = hal_first(HAL_KIND_COMP); o; o = hal_next(o))
		if (((struct hal_comp_rec *)o)->comp_id == comp_id)
			return (struct hal_comp_rec *)o;
	return 0;
}

const char *hal_type_name(int type)
{
	switch (type) {
	case HAL_BIT: return "bit";
	case HAL_FLOAT: return "float";
	case HAL_S32: return "s32";
	case HAL_U32: return "u32";
	case HAL_S64: return "s64";
	case HAL_U64: return "u64";
	default: return "invalid-type";
	}
}

const char *hal_dir_name(int dir)
{
	switch (dir) {
	case HAL_IN: return "IN";
	case HAL_OUT: return "OUT";
	case HAL_IO: return "I/O";
	case HAL_RO: return "RO";
	case HAL_RW: return "RW";
	default: return "invalid-direction";
	}
}

void hal_set_load_context(const char *module, const char *args)
{
	if (module)
		rtapi_snprintf(load_module, sizeof(load_module), "%s", module);
	else
		load_module[0] = 0;
	load_args = args;
}

static void record_load_context(struct hal_comp_rec *comp)
{
	rtapi_u32 len;
	char *s;

	if (!load_module[0])
		return;
	strcpy(comp->module, load_module);
	if (!load_args || !*load_args)
		return;
	len = strlen(load_args);
	if (len > HAL_ARGS_LEN)
		len = HAL_ARGS_LEN;
	s = hal_alloc_block(hal_seg, len + 1, HAL_KIND_STRING, hal_off(comp));
	if (!s)
		return;		/* only "save comp" loses the arguments */
	memcpy(s, load_args, len);
	s[len] = 0;
	comp->args_off = hal_off(s);
}

static int comp_new_locked(const char *name)
{
	struct hal_comp_rec *comp;
	int err;

	err = hal_check_lock(HAL_LOCK_LOAD, "load a component");
	if (err)
		return err;
	comp = hal_object_new(HAL_KIND_COMP, sizeof(*comp), name, 0, &err);
	if (!comp)
		return err;
	comp->comp_id = hal_seg->next_comp_id++;
#ifdef RTAPI
	comp->is_realtime = 1;
	comp->pid = 0;
#else
	comp->is_realtime = 0;
	comp->pid = (rtapi_s32)rtapi_getpid();
#endif
	comp->mem_base = (rtapi_u64)(unsigned long)hal_shmem_base;
#ifdef RTAPI
	hal_seg->rt_mem_base = comp->mem_base;
#endif
	record_load_context(comp);
	hal_current_comp_off = hal_off(comp);
	return comp->comp_id;
}

int hal_init(const char *name)
{
	char auto_name[HAL_NAME_LEN + 1];
	int rc;

	rc = hal_segment_map();
	if (rc < 0)
		return rc;
	if (!name) {
		rtapi_snprintf(auto_name, sizeof(auto_name), "comp%d", ++comp_ids_issued);
		name = auto_name;
	}
	hal_lock();
	rc = comp_new_locked(name);
	hal_unlock();
	if (rc > 0)
		hal_local_users++;
	else if (hal_local_users == 0)
		hal_segment_unmap();
	return rc;
}

/* Remove a component and everything it owns. Caller holds the HAL lock. */
static void comp_delete_locked(struct hal_comp_rec *comp)
{
	rtapi_u32 comp_off = hal_off(comp);
	struct hal_obj_hdr *o, *next;
	struct hal_block_hdr *blk;

	hal_comp_functs_remove_from_threads(comp_off);
	hal_threads_quiesce();	/* no thread may still be inside this component's code */
	for (o = hal_first(HAL_KIND_FUNCT); o; o = next) {
		next = hal_next(o);
		if (o->owner_off == comp_off)
			hal_funct_delete_locked((struct hal_funct_rec *)o);
	}
	for (o = hal_first(HAL_KIND_PIN); o; o = next) {
		next = hal_next(o);
		if (o->owner_off == comp_off)
			hal_pin_delete_locked((struct hal_pin_rec *)o);
	}
	for (o = hal_first(HAL_KIND_PARAM); o; o = next) {
		next = hal_next(o);
		if (o->owner_off == comp_off)
			hal_param_delete_locked((struct hal_param_rec *)o);
	}
	if (hal_current_comp_off == comp_off)
		hal_current_comp_off = 0;
	hal_index_remove(hal_seg, &comp->hdr);
	blk = (struct hal_block_hdr *)comp - 1;
	blk->owner_off = comp_off;	/* so the sweep below frees the record too */
	hal_free_owned(hal_seg, comp_off);
}

/* Was 'comp' made by this address space? halcmd removes components that a dead
 * process left behind; those never counted among this process's users. */
static bool comp_is_local(const struct hal_comp_rec *comp)
{
#ifdef ULAPI
	return !comp->is_realtime && comp->pid == (rtapi_s32)rtapi_getpid();
#else
	return comp->is_realtime;
#endif
}

void hal_local_user_gone(void)
{
	if (--hal_local_users <= 0) {
		hal_local_users = 0;
		hal_segment_unmap();
	}
}

int hal_exit(int comp_id)
{
	struct hal_comp_rec *comp;
	bool local;

	if (!hal_seg) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hal_exit(%d): HAL is not initialised\n", comp_id);
		return -EINVAL;
	}
	hal_lock();
	comp = hal_comp_by_id(comp_id);
	if (!comp) {
		hal_unlock();
		rtapi_print_msg(RTAPI_MSG_ERR, "hal_exit: component id %d does not exist\n", comp_id);
		return -EINVAL;
	}
#ifdef ULAPI
	if (comp->is_realtime) {
		hal_unlock();
		rtapi_print_msg(RTAPI_MSG_ERR,
				"component '%s' is realtime: unload it with unloadrt\n", comp->hdr.name);
		return -EPERM;
	}
#endif
	local = comp_is_local(comp);
	comp_delete_locked(comp);
	hal_unlock();
	if (local)
		hal_local_user_gone();
	return 0;
}

#ifdef ULAPI
/* Caller holds the HAL lock. 0 removed, -ENOENT, -EPERM (realtime), -EBUSY (alive). */
static int comp_remove_dead_locked(struct hal_comp_rec *comp)
{
	if (comp->is_realtime)
		return -EPERM;
	if (comp->pid == (rtapi_s32)rtapi_getpid() || rtapi_process_exists(comp->pid))
		return -EBUSY;
	comp_delete_locked(comp);
	return 0;
}

int hal_comp_remove_dead(int comp_id)
{
	struct hal_comp_rec *comp;
	int rc;

	if (!hal_seg)
		return -EINVAL;
	hal_lock();
	comp = hal_comp_by_id(comp_id);
	rc = comp ? comp_remove_dead_locked(comp) : -ENOENT;
	hal_unlock();
	return rc;
}

int hal_comps_remove_dead(void)
{
	struct hal_obj_hdr *o, *next;
	int removed = 0;

	if (!hal_seg)
		return 0;
	hal_lock();
	for (o = hal_first(HAL_KIND_COMP); o; o = next) {
		next = hal_next(o);
		if (comp_remove_dead_locked((struct hal_comp_rec *)o) == 0)
			removed++;
	}
	hal_unlock();
	return removed;
}
#endif

int hal_exit_module_comps(const char *module)
{
	struct hal_obj_hdr *o, *next;
	int removed = 0, n;

	if (!hal_seg)
		return 0;
	hal_lock();
	for (o = hal_first(HAL_KIND_COMP); o; o = next) {
		struct hal_comp_rec *comp = (struct hal_comp_rec *)o;

		next = hal_next(o);
		if (comp->is_realtime && strcmp(comp->module, module) == 0) {
			comp_delete_locked(comp);
			removed++;
		}
	}
	hal_unlock();
	for (n = 0; n < removed; n++)
		hal_local_user_gone();
	return removed;
}

int hal_realtime_object_count(void)
{
	struct hal_obj_hdr *o;
	int n, err;

	err = hal_segment_map();
	if (err)
		return err;
	hal_lock();
	n = (int)hal_seg->count[HAL_KIND_THREAD];
	for (o = hal_first(HAL_KIND_COMP); o; o = hal_next(o))
		if (((struct hal_comp_rec *)o)->is_realtime)
			n++;
	hal_unlock();
	return n;
}

int hal_ready(int comp_id)
{
	struct hal_comp_rec *comp;
	int rc = 0;

	if (!hal_seg) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hal_ready(%d): HAL is not initialised\n", comp_id);
		return -EINVAL;
	}
	hal_lock();
	comp = hal_comp_by_id(comp_id);
	if (comp)
		comp->is_ready = 1;
	hal_unlock();
	if (!comp) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hal_ready: component id %d does not exist\n", comp_id);
		rc = -EINVAL;
	}
	return rc;
}

int hal_set_constructor(int comp_id, hal_constructor_t constructor)
{
	struct hal_comp_rec *comp;

	if (!hal_seg)
		return -EINVAL;
	hal_lock();
	comp = hal_comp_by_id(comp_id);
	if (comp)
		comp->constructor = (rtapi_u64)(unsigned long)constructor;
	hal_unlock();
	if (!comp) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hal_set_constructor: component id %d does not exist\n",
				comp_id);
		return -EINVAL;
	}
	return 0;
}

void *hal_malloc(long int size)
{
	void *p;

	if (!hal_seg) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hal_malloc: call hal_init first\n");
		return 0;
	}
	if (size <= 0 || (unsigned long)size >= hal_seg->size) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hal_malloc: bad size %ld\n", size);
		return 0;
	}
	hal_lock();
	p = hal_alloc_block(hal_seg, (rtapi_u32)size, HAL_KIND_MALLOC, hal_current_comp_off);
	hal_unlock();
	if (!p)
		rtapi_print_msg(RTAPI_MSG_ERR, "hal_malloc: HAL shared memory is full (%ld bytes wanted)\n",
				size);
	return p;
}
