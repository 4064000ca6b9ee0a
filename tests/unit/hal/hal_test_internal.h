/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hal_test_internal.h - the HAL library internals the unit tests drive, declared so
 * C++ can include them (hal_internal.h itself is C only). hal_test_decls_check.c
 * includes both headers, so a prototype that drifts from hal_internal.h fails the
 * build instead of miscalling. Tests only. */
#ifndef HAL_TEST_INTERNAL_H
#define HAL_TEST_INTERNAL_H

#ifdef __cplusplus
#define _Static_assert static_assert	/* hal_layout.h pins its records with C11 asserts */
#endif
#include "hal_layout.h"

#ifdef __cplusplus
extern "C" {
#endif

extern char *hal_shmem_base;
extern struct hal_seg_hdr *hal_seg;
extern int hal_local_users;

void hal_segment_init(struct hal_seg_hdr *seg, rtapi_u32 size);
int hal_segment_size_wanted(rtapi_u32 *size);
void *hal_alloc_block(struct hal_seg_hdr *seg, rtapi_u32 size, enum hal_kind kind, rtapi_u32 owner_off);
void hal_free_block(struct hal_seg_hdr *seg, void *data);
void hal_free_owned(struct hal_seg_hdr *seg, rtapi_u32 owner_off);
void hal_heap_compact(struct hal_seg_hdr *seg);
rtapi_u32 hal_name_hash(enum hal_kind kind, const char *name);
void hal_index_insert(struct hal_seg_hdr *seg, struct hal_obj_hdr *obj);
void hal_index_remove(struct hal_seg_hdr *seg, struct hal_obj_hdr *obj);
struct hal_obj_hdr *hal_index_find(struct hal_seg_hdr *seg, enum hal_kind kind, const char *name);
void *hal_object_new(enum hal_kind kind, rtapi_u32 size, const char *name, rtapi_u32 owner_off, int *err);
void hal_object_delete(struct hal_obj_hdr *obj);
void hal_lock(void);
void hal_unlock(void);
bool hal_umalloc_owned(const struct hal_seg_hdr *seg, rtapi_u32 owner_off, rtapi_u32 off, rtapi_u32 len);

/* the HAL mutex and its holder record (hal_lock.c) */
int hal_lock_try(struct hal_seg_hdr *seg, int self, const char *name, int *dead_pid);
void hal_lock_give(struct hal_seg_hdr *seg);
void hal_lock_seg(struct hal_seg_hdr *seg);
void hal_lock_set_liveness_check(bool (*alive)(int pid));

/* configuration requests (hal_request.c) */
#include "hal_request.h"
#ifndef HAL_INTERNAL_H
struct hal_caller {
	bool is_user;
	int pid;
};
#endif
int hal_req_execute(struct hal_req *r, const struct hal_caller *c);

#ifdef __cplusplus
}
/* Value storage, as hal_internal.h's inline helpers find it. */
inline union hal_data* hal_pin_dummy(const struct hal_pin_rec* pin)
{
    return reinterpret_cast<union hal_data*>(hal_shmem_base + pin->dummy_off);
}
inline union hal_data* hal_sig_value(const struct hal_sig_rec* sig)
{
    return reinterpret_cast<union hal_data*>(hal_shmem_base + sig->value_off);
}
extern "C" {
#endif

#ifdef __cplusplus
}
#undef _Static_assert
#endif
#endif /* HAL_TEST_INTERNAL_H */
