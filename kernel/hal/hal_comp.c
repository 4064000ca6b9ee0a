/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hal_comp.c - components: hal_init, hal_ready, hal_exit, hal_malloc,
 * hal_set_constructor, and the module host's hooks (hal_host.h). */
#include "hal_internal.h"
#include "hal_host.h"
#include "hal_query.h"
#include "rtapi_string.h"

/* The module being loaded or unloaded (hal_host.h), set by the module host around
 * rtapi_app_main() and rtapi_app_exit(). Module inits and exits are serialised by
 * load_mutex (two insmods at once in the kernel flavor), so there is one context and
 * every hal_init() and hal_malloc() in it belongs to that module. Guarded by load_mutex. */
static unsigned long load_mutex;
static struct {
	char module[HAL_NAME_LEN + 1];
	const char *args;
	rtapi_u32 comp_off;	/* what hal_malloc() charges: the module's last hal_init() */
	rtapi_u64 owner;	/* kernel flavor: its struct module */
} load;

/* Outside any load context (unit tests, userspace components): the last component
 * hal_init()ed in this address space. Guarded by the HAL mutex. */
static rtapi_u32 last_comp_off;

static int comp_ids_issued;	/* for names of anonymous components: atomic */

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
	if (module) {
		rtapi_mutex_get(&load_mutex);	/* held until the module's init/exit is over */
		rtapi_snprintf(load.module, sizeof(load.module), "%s", module);
		load.args = args;
		load.comp_off = 0;
		load.owner = 0;
		return;
	}
	load.module[0] = 0;
	load.args = 0;
	load.comp_off = 0;
	load.owner = 0;
	rtapi_mutex_give(&load_mutex);
}

void hal_set_load_module(void *owner)
{
	load.owner = (rtapi_u64)(unsigned long)owner;
}

rtapi_u64 hal_load_module(void)
{
	return load.module[0] ? load.owner : 0;
}

static void record_load_context(struct hal_comp_rec *comp)
{
	rtapi_u32 len;
	char *s;

	if (!load.module[0])
		return;
	strcpy(comp->module, load.module);
	load.comp_off = hal_off(comp);
	if (!load.args || !*load.args)
		return;
	len = strlen(load.args);
	if (len > HAL_ARGS_LEN)
		len = HAL_ARGS_LEN;
	s = hal_alloc_block(hal_seg, len + 1, HAL_KIND_STRING, hal_off(comp));
	if (!s)
		return;		/* only "save comp" loses the arguments */
	memcpy(s, load.args, len);
	s[len] = 0;
	comp->args_off = hal_off(s);
}

int hal_comp_new_locked(const char *name, bool is_realtime, int pid, rtapi_u64 mem_base)
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
	comp->is_realtime = is_realtime;
	comp->pid = is_realtime ? 0 : pid;
	comp->mem_base = mem_base;
	if (is_realtime) {
		hal_seg->rt_mem_base = comp->mem_base;
		record_load_context(comp);
		last_comp_off = hal_off(comp);
	}
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
		rtapi_snprintf(auto_name, sizeof(auto_name), "comp%d",
			       __atomic_add_fetch(&comp_ids_issued, 1, __ATOMIC_RELAXED));
		name = auto_name;
	}
#ifdef ULAPI
	rc = hal_ul_comp_new(name);
#else
	hal_lock();
	rc = hal_comp_new_locked(name, true, 0, (rtapi_u64)(unsigned long)hal_shmem_base);
	hal_unlock();
#endif
	if (rc > 0)
		hal_local_user_new();
	else if (__atomic_load_n(&hal_local_users, __ATOMIC_ACQUIRE) == 0)
		hal_segment_unmap();
	return rc;
}

/* Remove a component and everything it owns. Caller holds the HAL lock. */
void hal_comp_delete_locked(struct hal_comp_rec *comp)
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
	if (last_comp_off == comp_off)
		last_comp_off = 0;
	if (load.comp_off == comp_off)
		load.comp_off = 0;
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

void hal_local_user_new(void)
{
	__atomic_add_fetch(&hal_local_users, 1, __ATOMIC_ACQ_REL);
}

void hal_local_user_gone(void)
{
	if (__atomic_sub_fetch(&hal_local_users, 1, __ATOMIC_ACQ_REL) <= 0) {
		__atomic_store_n(&hal_local_users, 0, __ATOMIC_RELEASE);
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
#ifdef ULAPI
	return hal_ul_comp_exit(comp_id);
#endif
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
	hal_comp_delete_locked(comp);
	hal_unlock();
	if (local)
		hal_local_user_gone();
	return 0;
}

#ifdef ULAPI
/* Crash clean-up (hal_query.h): checked and carried out by hal_request.c, in the
 * kernel flavor inside hal_lib.ko. */
int hal_comp_remove_dead(int comp_id)
{
	if (!hal_seg)
		return -EINVAL;
	if (comp_id <= 0)
		return -ENOENT;
	return hal_ul_comp_id_req(HAL_REQ_COMP_REMOVE_DEAD, comp_id);
}

int hal_comps_remove_dead(void)
{
	int rc;

	if (!hal_seg)
		return 0;
	rc = hal_ul_comp_id_req(HAL_REQ_COMP_REMOVE_DEAD, 0);
	return rc < 0 ? 0 : rc;
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
			hal_comp_delete_locked(comp);
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

static int set_ready(int comp_id, int ready, const char *what)
{
	struct hal_comp_rec *comp;
	int rc = 0;

	if (!hal_seg) {
		rtapi_print_msg(RTAPI_MSG_ERR, "%s(%d): HAL is not initialised\n", what, comp_id);
		return -EINVAL;
	}
#ifdef ULAPI
	return hal_ul_comp_id_req(ready ? HAL_REQ_COMP_READY : HAL_REQ_COMP_UNREADY, comp_id);
#endif
	hal_lock();
	comp = hal_comp_by_id(comp_id);
	if (comp)
		comp->is_ready = ready;
	hal_unlock();
	if (!comp) {
		rtapi_print_msg(RTAPI_MSG_ERR, "%s: component id %d does not exist\n", what, comp_id);
		rc = -EINVAL;
	}
	return rc;
}

int hal_ready(int comp_id)
{
	return set_ready(comp_id, 1, "hal_ready");
}

/* LinuxCNC 2.9's hal_unready: a ready component becomes not ready again, e.g. a Python
 * component that adds pins after ready() (loadusr -W then waits for the next ready). */
int hal_unready(int comp_id)
{
	return set_ready(comp_id, 0, "hal_unready");
}

int hal_set_constructor(int comp_id, hal_constructor_t constructor)
{
	struct hal_comp_rec *comp;

	if (!hal_seg)
		return -EINVAL;
	hal_lock();
	comp = hal_comp_by_id(comp_id);
#ifdef ULAPI
	(void)constructor;	/* only the realtime host calls constructors: nothing to keep */
#else
	if (comp)
		comp->constructor = (rtapi_u64)(unsigned long)constructor;
#endif
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
#ifdef ULAPI
	p = hal_ul_malloc(size);
#else
	hal_lock();
	p = hal_alloc_block(hal_seg, (rtapi_u32)size, HAL_KIND_MALLOC,
			    load.module[0] ? load.comp_off : last_comp_off);
	hal_unlock();
#endif
	if (!p)
		rtapi_print_msg(RTAPI_MSG_ERR, "hal_malloc: HAL shared memory is full (%ld bytes wanted)\n",
				size);
	return p;
}
