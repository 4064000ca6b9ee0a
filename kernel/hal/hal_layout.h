/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hal_layout.h - the records of the HAL shared-memory segment (DESIGN.md "The HAL
 * shared-memory object model"). Every process and the kernel map the segment at a
 * different address, so records refer to each other by offsets from the segment
 * start; the only pointers are the per-owner pin pointers and function addresses,
 * which are meaningful in their owner's address space only. Only kernel/hal/
 * includes this file. */
#ifndef HAL_LAYOUT_H
#define HAL_LAYOUT_H

#include "hal.h"

#define HAL_KEY 0x48414c32		/* "HAL2": RTAPI shmem key of the segment */
/* The segment's size is fixed when it is created: HAL_SIZE (environment in userspace,
 * hal_lib.ko's hal_size parameter in the kernel; hal_segment_size_wanted()) or the
 * default, which holds about 59,000 two-input components with their nets. */
#define HAL_SEGMENT_SIZE_DEFAULT (64u << 20)
/* Never below the default: every process asks for at least its own HAL_SIZE or the
 * default when it maps the segment, and a segment smaller than that request would
 * refuse every tool started without the creator's HAL_SIZE. */
#define HAL_SEGMENT_SIZE_MIN HAL_SEGMENT_SIZE_DEFAULT
#define HAL_SEGMENT_SIZE_MAX (1u << 30)
#define HAL_LAYOUT_VERSION 7
#define HAL_SEG_MAGIC 0x48414c21
#define HAL_HASH_BUCKETS 262144u	/* power of two; 1 MiB: chains stay short at 256k objects */
#define HAL_ALIGN 8u
#define HAL_CACHE_LINE 64u		/* what a realtime thread writes sits alone in lines of this size */
#ifdef __cplusplus
#define HAL_LINE_ALIGNED alignas(HAL_CACHE_LINE)
#else
#define HAL_LINE_ALIGNED _Alignas(HAL_CACHE_LINE)
#endif
/* Where the value area starts in a segment of 'size' bytes: its last quarter, page
 * aligned, so that the kernel flavor maps it apart from the records (hal_layout.h). */
#define HAL_VAL_START(size) (((size) - (size) / 4) & ~4095u)

/* What a heap block holds. Kinds below HAL_KIND_COUNT are named, indexed objects. */
enum hal_kind {
	HAL_KIND_FREE = 0,
	HAL_KIND_COMP,
	HAL_KIND_PIN,
	HAL_KIND_PARAM,
	HAL_KIND_SIG,
	HAL_KIND_FUNCT,
	HAL_KIND_THREAD,
	HAL_KIND_COUNT,
	HAL_KIND_MALLOC = HAL_KIND_COUNT,	/* hal_malloc() memory */
	HAL_KIND_ENTRY,				/* a function's place in a thread */
	HAL_KIND_STRING,			/* module arguments */
	HAL_KIND_ALIAS,				/* struct hal_alias_rec (hal_alias.c) */
	/* The value area (below): the only memory a kernel-flavor user may write. */
	HAL_KIND_VALUE,				/* a signal's value or a pin's dummy (8 bytes) */
	HAL_KIND_UMALLOC,			/* hal_malloc() of a userspace component: its
						 * record (struct hal_umalloc_rec) is in the
						 * record heap, the memory in the value area */
	HAL_KIND_DISPATCH,			/* struct hal_dispatch: a thread's functions */
	HAL_KIND_THREAD_RT,			/* struct hal_thread_rt, with alignment room */
};

/* hal_obj_hdr.flags: set on alias records, which sit in the name index under the
 * kind of their target (pin or param) but in no kind list. */
#define HAL_OBJ_ALIAS 1u

/* Where a userspace component's hal_malloc() memory is (HAL_KIND_UMALLOC record). */
struct hal_umalloc_rec {
	rtapi_u32 off;		/* in the value area */
	rtapi_u32 size;		/* bytes, a multiple of 8 */
};

/* The segment has two heaps (DESIGN.md "Who may touch what"; docs/kernel-security.md):
 *  - the record heap [heap_start, val_start): the header, the name index, every object
 *    record, thread entries, module arguments and realtime components' hal_malloc()
 *    memory (their pin pointer slots and parameters). Only the HAL core writes it; in
 *    the kernel flavor users map it read-only.
 *  - the value area [val_start, size): signal values, pins' dummies and userspace
 *    components' hal_malloc() memory (HAL_KIND_VALUE, HAL_KIND_UMALLOC). Nothing in it
 *    is an address, offset or size that kernel code follows, not even allocator
 *    metadata: its 8-byte granules are handed out by a bitmap in the record heap
 *    (val_map_off); users may map it writable.
 * Precedes every block of the record heap; blocks tile it from its start to its top. */
struct hal_block_hdr {
	rtapi_u32 size;		/* bytes including this header, multiple of HAL_ALIGN */
	rtapi_u32 owner_off;	/* component record freed with, 0 = none */
	rtapi_u32 next_free_off;/* free list link while HAL_KIND_FREE */
	rtapi_u16 kind;		/* enum hal_kind */
	rtapi_u16 pad;
};
_Static_assert(sizeof(struct hal_block_hdr) == 16, "segment layout changed: bump HAL_LAYOUT_VERSION");

/* Common head of every named object; must be first in the record. */
struct hal_obj_hdr {
	rtapi_u32 next_off;	/* kind list, in creation order */
	rtapi_u32 prev_off;
	rtapi_u32 hash_next_off;/* name index bucket chain */
	rtapi_u32 owner_off;	/* owning component record (0: signals, threads: the RT host) */
	rtapi_u32 hash;
	rtapi_u8 kind;		/* enum hal_kind */
	rtapi_u8 flags;		/* HAL_OBJ_ALIAS */
	rtapi_u8 pad[2];
	char name[HAL_NAME_LEN + 1];
};
_Static_assert(sizeof(struct hal_obj_hdr) == 88, "segment layout changed: bump HAL_LAYOUT_VERSION");

/* Storage of one value; a signal's value and a pin's dummy are this. */
union hal_data {
	hal_bit_t b;
	hal_s32_t s;
	hal_u32_t u;
	hal_float_t f;
	hal_s64_t ls;
	hal_u64_t lu;
	rtapi_u64 raw;
};

struct hal_comp_rec {
	struct hal_obj_hdr hdr;
	rtapi_s32 comp_id;
	rtapi_s32 pid;		/* userspace components: the process; RT: 0 */
	rtapi_u8 is_realtime;
	rtapi_u8 is_ready;
	rtapi_u8 pad[2];
	rtapi_u32 args_off;	/* HAL_KIND_STRING block with the module arguments, or 0 */
	rtapi_u64 mem_base;	/* where the owner maps the segment: pins point at mem_base + off */
	rtapi_u64 constructor;	/* hal_constructor_t in the owner's address space */
	char module[HAL_NAME_LEN + 1];
};
_Static_assert(sizeof(struct hal_comp_rec) == 184, "segment layout changed: bump HAL_LAYOUT_VERSION");

struct hal_pin_rec {
	struct hal_obj_hdr hdr;
	rtapi_u32 data_ptr_off;	/* the owner's pointer variable (in hal_malloc memory) */
	rtapi_u32 signal_off;	/* linked signal, 0 = unlinked (pointer aims at dummy) */
	rtapi_u8 type;		/* hal_type_t */
	rtapi_u8 dir;		/* hal_pin_dir_t */
	rtapi_u8 pad[6];
	rtapi_u32 dummy_off;	/* HAL_KIND_VALUE block: the value while unlinked */
	rtapi_u32 pad2;
};
_Static_assert(sizeof(struct hal_pin_rec) == 112, "segment layout changed: bump HAL_LAYOUT_VERSION");

struct hal_param_rec {
	struct hal_obj_hdr hdr;
	rtapi_u32 data_off;	/* the owner's variable (in hal_malloc memory) */
	rtapi_u8 type;
	rtapi_u8 dir;		/* hal_param_dir_t */
	rtapi_u8 pad[2];
};
_Static_assert(sizeof(struct hal_param_rec) == 96, "segment layout changed: bump HAL_LAYOUT_VERSION");

struct hal_sig_rec {
	struct hal_obj_hdr hdr;
	rtapi_u16 readers;	/* HAL_IN pins linked */
	rtapi_u16 writers;	/* HAL_OUT pins linked: 0 or 1, hal_link() refuses a second */
	rtapi_u16 bidirs;	/* HAL_IO pins linked */
	rtapi_u8 type;
	rtapi_u8 pad;
	rtapi_u32 value_off;	/* HAL_KIND_VALUE block: linked pins point here */
	rtapi_u32 pad2;
};
_Static_assert(sizeof(struct hal_sig_rec) == 104, "segment layout changed: bump HAL_LAYOUT_VERSION");

struct hal_funct_rec {
	struct hal_obj_hdr hdr;
	rtapi_u64 funct;	/* hal_funct_t in the owner's address space */
	rtapi_u64 arg;
	hal_s32_t *time_ptr;	/* pin <name>.time: written by the thread after each call */
	rtapi_s32 tmax;		/* param <name>.tmax */
	rtapi_s32 users;	/* threads it is on */
	rtapi_u8 uses_fp;
	rtapi_u8 reentrant;
	rtapi_u8 pad[2];
	rtapi_u32 puts_pending;	/* entries removed whose module references hal_threads_quiesce() drops */
	rtapi_u64 module;	/* kernel flavor: the struct module the code is in (hal_os_code_get) */
};
_Static_assert(sizeof(struct hal_funct_rec) == 136, "segment layout changed: bump HAL_LAYOUT_VERSION");

/* A second name of a pin or parameter (halcmd "alias", hal_pin_alias()). hdr.kind is
 * the target's kind, so hal_find() under the alias name answers the target itself;
 * hdr.next_off/prev_off chain all aliases from hal_seg_hdr.alias_head. Removed with
 * its target (hal_object_delete), never by its owner. */
struct hal_alias_rec {
	struct hal_obj_hdr hdr;
	rtapi_u32 target_off;	/* the pin or param record */
	rtapi_u32 pad;
};
_Static_assert(sizeof(struct hal_alias_rec) == 96, "segment layout changed: bump HAL_LAYOUT_VERSION");

/* A function's place in a thread's list (HAL_KIND_ENTRY block, no name). */
struct hal_entry_rec {
	rtapi_u32 next_off;	/* written last when inserting: the thread walks without locking */
	rtapi_u32 funct_off;
};

/* One function of a thread's dispatch table: the code and argument (copied from the
 * function record, they never change) and the record, whose time_ptr and tmax take
 * the timing. */
struct hal_dispatch_slot {
	rtapi_u64 funct;
	rtapi_u64 arg;
	rtapi_u32 funct_off;
	rtapi_u32 pad;
};
_Static_assert(sizeof(struct hal_dispatch_slot) == 24, "segment layout changed: bump HAL_LAYOUT_VERSION");

/* What the thread runs each cycle (HAL_KIND_DISPATCH block): its entry list as one
 * array, so a cycle reads contiguous memory instead of following links (issue 20).
 * Rebuilt by the HAL core from the list on every change (hal_thread.c): appending
 * fills the next free slot and then publishes 'count' (release); anything else builds
 * a new table, publishes its offset, and frees the old one once the thread has passed
 * a period boundary (hal_threads_quiesce). */
struct hal_dispatch {
	rtapi_u32 count;	/* slots the thread runs: stored (release) after the slot */
	rtapi_u32 capacity;
	struct hal_dispatch_slot slot[];
};

/* What the thread writes every period, alone in its cache line (a HAL_KIND_THREAD_RT
 * block holds it at the first line boundary), so configuring processes writing records
 * nearby never take the line away from it. Written by the thread only. */
struct hal_thread_rt {
	rtapi_u32 periods;	/* periods completed, with or without running functions */
	rtapi_u32 idle_period;	/* 'periods' after the last period that ran no functions */
	rtapi_s32 tmax;		/* param <name>.tmax (written by users too) */
	rtapi_u32 block_off;	/* the HAL_KIND_THREAD_RT block this sits in */
	rtapi_u64 cycles;	/* completed cycles that ran the functions */
	rtapi_u64 run_ns;	/* time spent in functions */
	rtapi_u64 overruns;	/* periods missed since creation */
	rtapi_s32 host_pid;	/* simulated flavor: rtapi_app, whose death ends the thread; kernel: 0 */
	rtapi_u32 pad3;
	rtapi_u64 pad2[2];
};
_Static_assert(sizeof(struct hal_thread_rt) == HAL_CACHE_LINE, "segment layout changed: bump HAL_LAYOUT_VERSION");

struct hal_thread_rec {
	struct hal_obj_hdr hdr;
	rtapi_s64 period_ns;
	rtapi_s32 priority;
	rtapi_s32 task_id;	/* RTAPI task running hal_thread_task() */
	rtapi_u32 first_entry_off;/* functions in execution order (show, save, positions) */
	rtapi_u32 dispatch_off;	/* struct hal_dispatch built from them: what the thread runs */
	hal_s32_t *time_ptr;	/* pin <name>.time */
	rtapi_u32 rt_off;	/* struct hal_thread_rt */
	rtapi_u8 uses_fp;
	rtapi_u8 pad[3];
	rtapi_u32 entry_count;	/* functions on it; with last_entry_off, appending is O(1) */
	rtapi_u32 last_entry_off;
	hal_s32_t *overruns_ptr;/* pin <name>.overruns (saturates), for a watchdog */
	rtapi_u32 retired_off;	/* a replaced dispatch table, freed by hal_threads_quiesce() */
	rtapi_u32 pad2;
};
_Static_assert(sizeof(struct hal_thread_rec) == 152, "segment layout changed: bump HAL_LAYOUT_VERSION");

/* The segment starts with this header. */
struct hal_seg_hdr {
	rtapi_u32 init_state;	/* 0 new (zeroed by RTAPI), 1 being initialised, 2 ready */
	rtapi_u32 magic;
	rtapi_u32 version;
	rtapi_u32 size;
	unsigned long mutex;	/* guards every configuration change; never taken by threads */
	rtapi_s32 mutex_pid;	/* holder of 'mutex' (hal_lock.c), 0 = none or not yet known */
	char mutex_holder[16];	/* its process name, for messages */
	rtapi_u32 lock_level;	/* HAL_LOCK_* bits */
	rtapi_u32 pad_r;
	rtapi_s32 next_comp_id;
	rtapi_u32 hash_off;	/* HAL_HASH_BUCKETS u32 offsets */
	rtapi_s64 base_period_ns;/* set by the first thread */
	rtapi_u32 heap_start;
	rtapi_u32 heap_top;	/* first byte never allocated */
	rtapi_u32 free_head;	/* free blocks, unordered */
	rtapi_u32 bytes_used;
	rtapi_u32 val_start;	/* the value area: page aligned, up to 'size' */
	rtapi_u32 val_top;	/* first byte above every granule ever used */
	rtapi_u32 val_map_off;	/* bitmap of used 8-byte granules (u64 words), in the records */
	rtapi_u32 val_bytes_used;
	rtapi_u32 val_hint;	/* granule where the next search starts */
	rtapi_u32 pad_v;
	rtapi_u32 list_head[HAL_KIND_COUNT];
	rtapi_u32 list_tail[HAL_KIND_COUNT];
	rtapi_u32 count[HAL_KIND_COUNT];
	rtapi_u32 pad;
	rtapi_u64 rt_mem_base;	/* the realtime host's mapping: owner of threads and their pins */
	rtapi_u32 alias_head;	/* hal_alias_rec list (hal_alias.c) */
	rtapi_u32 alias_count;
	rtapi_u32 exact_periods;/* halcmd setexact_for_test_suite_only: take periods as asked */
	rtapi_u32 pad2;
	/* Read by every thread every period: in a line no request writes (the mutex and
	 * the allocator's fields above change with each one). */
	HAL_LINE_ALIGNED rtapi_u32 threads_running;
	rtapi_u32 pad_running[HAL_CACHE_LINE / 4 - 1];
};

#endif /* HAL_LAYOUT_H */
