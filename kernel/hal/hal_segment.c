/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hal_segment.c - mapping the one HAL segment into this address space and laying
 * it out the first time anybody maps it. */
#include "hal_internal.h"

char *hal_shmem_base;
struct hal_seg_hdr *hal_seg;
int hal_local_users;
#ifdef ULAPI
bool hal_seg_is_kmod;		/* mapped through /dev/rtapi (kernel/rtapi/hal_ulapi_kmod.c) */
int rtapi_shmem_kmod_active(void);
#endif

static int rtapi_module_id;
static int shmem_id;

static rtapi_u32 align_up(rtapi_u32 v)
{
	return (v + HAL_ALIGN - 1) & ~(HAL_ALIGN - 1);
}

void hal_segment_init(struct hal_seg_hdr *seg, rtapi_u32 size)
{
	rtapi_u32 *buckets;
	rtapi_u64 *map;
	rtapi_u32 i;

	seg->magic = HAL_SEG_MAGIC;
	seg->version = HAL_LAYOUT_VERSION;
	seg->size = size;
	seg->mutex = 0;
	seg->mutex_pid = 0;
	seg->mutex_holder[0] = 0;
	seg->lock_level = HAL_LOCK_NONE;
	seg->threads_running = 0;
	seg->next_comp_id = 1;
	seg->base_period_ns = 0;
	seg->hash_off = align_up(sizeof(*seg));
	buckets = (rtapi_u32 *)((char *)seg + seg->hash_off);
	for (i = 0; i < HAL_HASH_BUCKETS; i++)
		buckets[i] = 0;
	seg->val_start = HAL_VAL_START(size);
	seg->val_map_off = align_up(seg->hash_off + HAL_HASH_BUCKETS * sizeof(rtapi_u32));
	map = (rtapi_u64 *)((char *)seg + seg->val_map_off);
	for (i = 0; i < (size - seg->val_start) / 8 / 64; i++)
		map[i] = 0;
	seg->heap_start = align_up(seg->val_map_off + (size - seg->val_start) / 64);
	seg->heap_top = seg->heap_start;
	seg->free_head = 0;
	seg->bytes_used = 0;
	seg->val_top = seg->val_start;
	seg->val_bytes_used = 0;
	seg->val_hint = 0;
	for (i = 0; i < HAL_KIND_COUNT; i++) {
		seg->list_head[i] = 0;
		seg->list_tail[i] = 0;
		seg->count[i] = 0;
	}
}

int hal_segment_size_wanted(rtapi_u32 *size)
{
	const char *text = hal_os_segment_size_text(), *p = text;
	rtapi_u64 v = 0;

	if (!text || !*text) {
		*size = HAL_SEGMENT_SIZE_DEFAULT;
		return 0;
	}
	while (*p >= '0' && *p <= '9' && v <= HAL_SEGMENT_SIZE_MAX)
		v = v * 10 + (rtapi_u64)(*p++ - '0');
	if (p != text) {
		switch (*p) {
		case 'k': case 'K': v <<= 10; p++; break;
		case 'm': case 'M': v <<= 20; p++; break;
		case 'g': case 'G': v <<= 30; p++; break;
		}
	}
	if (p == text || *p || v < HAL_SEGMENT_SIZE_MIN || v > HAL_SEGMENT_SIZE_MAX) {
		rtapi_print_msg(RTAPI_MSG_ERR, "HAL: HAL_SIZE='%s' is not a segment size: bytes, or "
				"with a K, M or G suffix, from 64M to 1G (default 64M)\n", text);
		return -EINVAL;
	}
	*size = (rtapi_u32)v & ~4095u;
	return 0;
}

/* The first mapper initialises, with the size it asked for (a later process that asked
 * for less attached all the same: then the HAL uses that much); others wait until it
 * has finished. */
static int segment_ready(struct hal_seg_hdr *seg, rtapi_u32 size)
{
	rtapi_u32 expected = 0;
	int spins;

	if (__atomic_compare_exchange_n(&seg->init_state, &expected, 1, false,
					__ATOMIC_ACQ_REL, __ATOMIC_ACQUIRE)) {
		hal_segment_init(seg, size);
		__atomic_store_n(&seg->init_state, 2, __ATOMIC_RELEASE);
		return 0;
	}
	for (spins = 0; __atomic_load_n(&seg->init_state, __ATOMIC_ACQUIRE) != 2; spins++) {
		if (spins > 2000) {
			rtapi_print_msg(RTAPI_MSG_ERR, "HAL segment never finished initialising (the "
					"process creating it was killed?); remove it with 'halrun -U'\n");
			return -EAGAIN;
		}
		rtapi_sleep_ns(1000000);
	}
	if (seg->magic != HAL_SEG_MAGIC || seg->version != HAL_LAYOUT_VERSION) {
		rtapi_print_msg(RTAPI_MSG_ERR,
				"HAL segment has layout version %u, this program expects %u: "
				"stop the running HAL (halrun -U) first\n",
				(unsigned)seg->version, (unsigned)HAL_LAYOUT_VERSION);
		return -EINVAL;
	}
	return 0;
}

int hal_segment_map(void)
{
	void *ptr;
	rtapi_u32 size;
	int err;

	if (hal_shmem_base)
		return 0;
#ifdef ULAPI
	if (rtapi_shmem_kmod_active()) {
		char *base;

		err = hal_kmod_map(&base);
		if (err)
			return err;
		hal_seg_is_kmod = true;
		hal_shmem_base = base;
		hal_seg = (struct hal_seg_hdr *)base;
		return 0;
	}
#endif
	rtapi_module_id = rtapi_init("hal_lib");
	if (rtapi_module_id < 0) {
		rtapi_print_msg(RTAPI_MSG_ERR, "HAL: rtapi_init failed (%d)\n", rtapi_module_id);
		return rtapi_module_id;
	}
	err = hal_segment_size_wanted(&size);
	if (err)
		goto undo_init;
	shmem_id = rtapi_shmem_new(HAL_KEY, rtapi_module_id, size);
	if (shmem_id < 0) {
		err = shmem_id;
		rtapi_print_msg(RTAPI_MSG_ERR, "HAL: cannot get the HAL shared memory (%d)%s\n", err,
				hal_os_segment_size_text()[0] ? "; HAL_SIZE applies when the session "
				"starts: a running one keeps its size" : "");
		goto undo_init;
	}
	err = rtapi_shmem_getptr(shmem_id, &ptr);
	if (err < 0)
		goto undo_shmem;
	err = segment_ready(ptr, size);
	if (err < 0)
		goto undo_shmem;
	hal_shmem_base = ptr;
	hal_seg = ptr;
	return 0;

undo_shmem:
	rtapi_shmem_delete(shmem_id, rtapi_module_id);
undo_init:
	rtapi_exit(rtapi_module_id);
	return err;
}

void hal_segment_unmap(void)
{
	if (!hal_shmem_base)
		return;
	hal_shmem_base = 0;
	hal_seg = 0;
#ifdef ULAPI
	if (hal_seg_is_kmod) {
		hal_kmod_unmap();
		hal_seg_is_kmod = false;
		return;
	}
#endif
	rtapi_shmem_delete(shmem_id, rtapi_module_id);
	rtapi_exit(rtapi_module_id);
}
