/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hal_internal.h - what the HAL library files share. Functions named *_locked
 * expect the caller to hold the HAL mutex; the public API wraps each one once. */
#ifndef HAL_INTERNAL_H
#define HAL_INTERNAL_H

#include "hal.h"
#include "hal_layout.h"

/* --- per-address-space state (hal_segment.c) --- */
extern char *hal_shmem_base;		/* this process's (or the kernel's) mapping */
extern struct hal_seg_hdr *hal_seg;	/* == hal_shmem_base, typed */

static inline void *hal_ptr(rtapi_u32 off)
{
	return off ? hal_shmem_base + off : 0;
}
static inline rtapi_u32 hal_off(const volatile void *ptr)
{
	return (rtapi_u32)((const char *)ptr - hal_shmem_base);
}
/* Is [p, p+len) inside the segment? (pin/param storage must be) */
static inline bool hal_in_segment(const volatile void *p, unsigned long len)
{
	const char *c = (const char *)p;

	return hal_shmem_base && c >= hal_shmem_base + sizeof(struct hal_seg_hdr) &&
	       c + len <= hal_shmem_base + hal_seg->size;
}

int hal_segment_map(void);		/* map (and first time initialise) the segment */
void hal_segment_unmap(void);		/* when the last local user is gone */
void hal_segment_init(struct hal_seg_hdr *seg, rtapi_u32 size);	/* lays out an empty segment */
extern int hal_local_users;		/* components + threads of this address space + attach: atomic */
void hal_local_user_new(void);
void hal_local_user_gone(void);		/* unmaps the segment after the last one */

/* --- locking (hal_lock.c) --- */
void hal_lock(void);		/* waits; recovers the mutex from a dead holder */
void hal_unlock(void);
void hal_lock_seg(struct hal_seg_hdr *seg);
void hal_lock_give(struct hal_seg_hdr *seg);
/* One attempt by 'self' (pid, process name): 0 taken (*dead_pid: the dead holder it was
 * recovered from, or 0), -EBUSY held by a live holder. */
int hal_lock_try(struct hal_seg_hdr *seg, int self, const char *name, int *dead_pid);
/* Tests inject liveness; NULL restores hal_os_pid_alive. */
void hal_lock_set_liveness_check(bool (*alive)(int pid));
int hal_set_lock_locked(unsigned lock_type);

/* --- the operating system, per flavor (kernel/rtapi/hal_os_uspace.c, hal_lib_kmod.c) --- */
int hal_os_self(char *name, int len);	/* this process's pid (tgid); its name into name */
bool hal_os_pid_alive(int pid);
/* The HAL_SIZE setting as text, "" when unset: the environment variable in userspace,
 * hal_lib.ko's hal_size parameter in the kernel flavor. */
const char *hal_os_segment_size_text(void);
/* The size a new segment gets: HAL_SIZE (bytes, or with a K, M or G suffix; rounded
 * down to whole pages) or HAL_SEGMENT_SIZE_DEFAULT. -EINVAL, with a message naming the
 * value, when HAL_SIZE is not a size from HAL_SEGMENT_SIZE_MIN to _MAX. */
int hal_segment_size_wanted(rtapi_u32 *size);
/* 0, or -EPERM with a message naming 'what' when 'level' is locked. */
int hal_check_lock(unsigned level, const char *what);

/* --- heap (hal_alloc.c): base is the segment start --- */
void *hal_alloc_block(struct hal_seg_hdr *seg, rtapi_u32 size, enum hal_kind kind, rtapi_u32 owner_off);
void hal_free_block(struct hal_seg_hdr *seg, void *data);
/* Free every block owned by 'owner_off', then merge free neighbours. */
void hal_free_owned(struct hal_seg_hdr *seg, rtapi_u32 owner_off);
void hal_heap_compact(struct hal_seg_hdr *seg);
/* Is [off, off+len) inside hal_malloc() memory of the userspace component at owner_off?
 * Checks offsets that come from users (kernel flavor requests) before the core
 * writes through them. */
bool hal_umalloc_owned(const struct hal_seg_hdr *seg, rtapi_u32 owner_off, rtapi_u32 off, rtapi_u32 len);

/* --- name index and kind lists (hal_index.c) --- */
rtapi_u32 hal_name_hash(enum hal_kind kind, const char *name);
void hal_index_insert(struct hal_seg_hdr *seg, struct hal_obj_hdr *obj);
void hal_index_remove(struct hal_seg_hdr *seg, struct hal_obj_hdr *obj);
/* Finds objects by name or alias (an alias answers its target). */
struct hal_obj_hdr *hal_index_find(struct hal_seg_hdr *seg, enum hal_kind kind, const char *name);
/* Name index only, no kind list: for alias records. */
void hal_index_hash_insert(struct hal_seg_hdr *seg, struct hal_obj_hdr *obj);
void hal_index_hash_remove(struct hal_seg_hdr *seg, struct hal_obj_hdr *obj);

/* --- aliases (hal_alias.c) --- */
struct hal_obj_hdr *hal_alias_target(struct hal_seg_hdr *seg, const struct hal_obj_hdr *alias);
/* Remove every alias of 'target' (no-op for kinds that have none). */
void hal_alias_remove_all(struct hal_obj_hdr *target);
/* Add (alias non-empty) or remove (NULL/"": all of them) aliases of a pin or param. */
int hal_alias_set_locked(enum hal_kind kind, const char *name, const char *alias);
/* halcmd unalias: 'name' is an alias (removed) or a pin/param (all its aliases removed). */
int hal_unalias_locked(enum hal_kind kind, const char *name);
/* halcmd setexact_for_test_suite_only (hal_thread.c): -EBUSY once a thread exists. */
int hal_set_exact_periods_locked(void);
/* Allocate a named record of 'size' bytes, check the name, index it. Logs and returns NULL
 * with *err set on failure (-EINVAL bad/long name, -EEXIST duplicate, -ENOMEM). */
void *hal_object_new(enum hal_kind kind, rtapi_u32 size, const char *name, rtapi_u32 owner_off, int *err);
void hal_object_delete(struct hal_obj_hdr *obj);
static inline void *hal_find(enum hal_kind kind, const char *name)
{
	return hal_index_find(hal_seg, kind, name);
}
/* First/next object of a kind in creation order. */
static inline struct hal_obj_hdr *hal_first(enum hal_kind kind)
{
	return hal_ptr(hal_seg->list_head[kind]);
}
static inline struct hal_obj_hdr *hal_next(const struct hal_obj_hdr *obj)
{
	return hal_ptr(obj->next_off);
}
const char *hal_kind_name(enum hal_kind kind);	/* "pin", "signal", ... for messages */
/* Format a name from fmt/args into buf (HAL_NAME_LEN + 1); -EINVAL + message if too long. */
int hal_format_name(char *buf, const char *what, const char *fmt, va_list ap);

/* --- components (hal_comp.c) --- */
struct hal_comp_rec *hal_comp_by_id(int comp_id);
/* A component record: realtime (owned by the realtime host, mem_base its mapping) or
 * a userspace process's (pid; mem_base where that process maps the segment). */
int hal_comp_new_locked(const char *name, bool is_realtime, int pid, rtapi_u64 mem_base);
void hal_comp_delete_locked(struct hal_comp_rec *comp);
const char *hal_type_name(int type);
const char *hal_dir_name(int dir);

/* --- pins, signals (hal_pin.c, hal_signal.c) --- */
/* comp NULL: owned by the realtime host itself (a thread's timing pin). */
int hal_pin_new_locked(const char *name, hal_type_t type, hal_pin_dir_t dir, void **data_ptr_addr,
		       struct hal_comp_rec *comp);
void hal_pin_aim(struct hal_pin_rec *pin, volatile void *target);	/* set the owner's pointer */
void hal_pin_unlink_locked(struct hal_pin_rec *pin);
void hal_pin_delete_locked(struct hal_pin_rec *pin);
int hal_param_new_locked(const char *name, hal_type_t type, hal_param_dir_t dir, volatile void *data_addr,
			 struct hal_comp_rec *comp);
void hal_param_delete_locked(struct hal_param_rec *param);
/* Value storage of a pin as this process sees it: the signal's value or the dummy. */
union hal_data *hal_pin_value(struct hal_pin_rec *pin);
static inline union hal_data *hal_pin_dummy(const struct hal_pin_rec *pin)
{
	return hal_ptr(pin->dummy_off);
}
static inline union hal_data *hal_sig_value(const struct hal_sig_rec *sig)
{
	return hal_ptr(sig->value_off);
}

int hal_signal_new_locked(const char *name, hal_type_t type);
int hal_signal_delete_locked(const char *name);
int hal_link_locked(const char *pin_name, const char *sig_name);
int hal_unlink_locked(const char *pin_name);

/* --- functions and threads (hal_funct.c, hal_thread.c) --- */
int hal_add_funct_locked(const char *funct_name, const char *thread_name, int position);
int hal_del_funct_locked(const char *funct_name, const char *thread_name);
int hal_set_running_locked(int running);
/* Hold / drop a reference on a function's module (hal_funct_rec.module) while the
 * function is on a thread (kernel flavor: try_module_get; hal_lib_kmod.c). 0 or -errno. */
int hal_os_code_get(rtapi_u64 module);
void hal_os_code_put(rtapi_u64 module);
/* The module being loaded now (hal_set_load_module), 0 outside a load context. */
rtapi_u64 hal_load_module(void);
/* The <name>.time pin and <name>.tmax param every function and thread has. */
int hal_timing_objects_new(const char *name, hal_s32_t **time_ptr, rtapi_s32 *tmax,
			   struct hal_comp_rec *comp);
void hal_timing_objects_delete(const char *name);
void hal_funct_delete_locked(struct hal_funct_rec *f);
void hal_thread_delete_locked(struct hal_thread_rec *t);
/* Remove every entry of 'f' from every thread. */
void hal_funct_remove_from_threads(struct hal_funct_rec *f);
/* Remove every entry of every function component 'comp_off' owns: one pass per thread. */
void hal_comp_functs_remove_from_threads(rtapi_u32 comp_off);
/* Make a thread's dispatch table match its entry list after a change (hal_thread.c):
 * rebuild publishes a new table and retires the old one (freed by hal_threads_quiesce,
 * which the caller runs before returning); append adds the last entry, in place when
 * there is room. 0 or -ENOMEM. */
int hal_dispatch_rebuild(struct hal_thread_rec *t);
int hal_dispatch_append(struct hal_thread_rec *t);
/* After entries were removed: rebuild, or, when the heap has no room for a new table,
 * rewrite the old one in place while the thread runs nothing. Cannot fail. */
void hal_dispatch_shrink(struct hal_thread_rec *t);
/* Every table rebuilt from its list: after recovering the mutex from a dead holder. */
void hal_dispatch_repair(void);
/* Wait until no thread can still use what was unpublished before the call (removed
 * functions, replaced dispatch tables), then free and release it. */
void hal_threads_quiesce(void);

/* --- configuration requests (hal_request.c, hal_request_ul.c) --- */
#include "hal_request.h"
struct hal_caller {
	bool is_user;		/* a userspace process: every offset and owner is checked */
	int pid;
};
/* Check and carry out one request; the caller holds the HAL mutex. Messages go where
 * rtapi_print_msg sends them (the kernel flavor captures them into r->msg). */
int hal_req_execute(struct hal_req *r, const struct hal_caller *c);
#ifdef ULAPI
/* Userspace: build a request, run it here or in the kernel (hal_request_ul.c). */
int hal_ul_submit(struct hal_req *r);
int hal_ul_names(enum hal_req_op op, const char *name, const char *name2, int arg);
int hal_ul_comp_new(const char *name);
int hal_ul_comp_exit(int comp_id);
int hal_ul_comp_id_req(enum hal_req_op op, int comp_id);
void *hal_ul_malloc(long size);
int hal_ul_obj_new(enum hal_req_op op, const char *name, int type, int dir, volatile void *addr,
		   int comp_id);
int hal_ul_set(enum hal_req_op op, const char *name, int type, rtapi_u64 raw);
int hal_ul_set_own_param(const char *name, hal_type_t type, void *value_addr);
/* Kernel flavor (kernel/rtapi/hal_ulapi_kmod.c): /dev/rtapi mapped here, or not. */
extern bool hal_seg_is_kmod;
int hal_kmod_map(char **base);
void hal_kmod_unmap(void);
int hal_kmod_request(struct hal_req *r);
void hal_kmod_lock(bool take);
int hal_kmod_recover(void);
#endif

#endif /* HAL_INTERNAL_H */
