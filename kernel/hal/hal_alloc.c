/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hal_alloc.c - the heap inside the HAL segment. Every block carries its owner,
 * so a component's records and its hal_malloc() memory are reclaimed when it
 * unloads (hal_malloc(3hal) promises no free; we do better). First fit over an
 * unordered free list, bump allocation above it; merging happens in
 * hal_heap_compact() after a component goes away. Caller holds the HAL lock. */
#include "hal_internal.h"

#define MIN_SPLIT 48u	/* smaller remainders stay inside the block */

static struct hal_block_hdr *block_at(struct hal_seg_hdr *seg, rtapi_u32 off)
{
	return (struct hal_block_hdr *)((char *)seg + off);
}

static void zero(void *p, rtapi_u32 n)
{
	rtapi_u64 *q = p;	/* blocks are 8-byte aligned and sized */
	rtapi_u32 i;

	for (i = 0; i < n / 8; i++)
		q[i] = 0;
}

static struct hal_block_hdr *take_free(struct hal_seg_hdr *seg, rtapi_u32 need)
{
	rtapi_u32 *link = &seg->free_head;

	while (*link) {
		struct hal_block_hdr *b = block_at(seg, *link);

		if (b->size >= need) {
			*link = b->next_free_off;
			if (b->size - need >= MIN_SPLIT) {
				struct hal_block_hdr *rest = (struct hal_block_hdr *)((char *)b + need);

				rest->size = b->size - need;
				rest->kind = HAL_KIND_FREE;
				rest->owner_off = 0;
				rest->next_free_off = seg->free_head;
				seg->free_head = (rtapi_u32)((char *)rest - (char *)seg);
				b->size = need;
			}
			return b;
		}
		link = &b->next_free_off;
	}
	return 0;
}

void *hal_alloc_block(struct hal_seg_hdr *seg, rtapi_u32 size, enum hal_kind kind, rtapi_u32 owner_off)
{
	rtapi_u32 need = (size + sizeof(struct hal_block_hdr) + HAL_ALIGN - 1) & ~(HAL_ALIGN - 1);
	struct hal_block_hdr *b;

	if (size == 0 || size > seg->size)
		return 0;
	b = take_free(seg, need);
	if (!b) {
		if (seg->size - seg->heap_top < need)
			return 0;
		b = block_at(seg, seg->heap_top);
		b->size = need;
		seg->heap_top += need;
	}
	b->kind = kind;
	b->owner_off = owner_off;
	b->next_free_off = 0;
	seg->bytes_used += b->size;
	zero(b + 1, b->size - sizeof(*b));
	return b + 1;
}

void hal_free_block(struct hal_seg_hdr *seg, void *data)
{
	struct hal_block_hdr *b = (struct hal_block_hdr *)data - 1;

	seg->bytes_used -= b->size;
	b->kind = HAL_KIND_FREE;
	b->owner_off = 0;
	b->next_free_off = seg->free_head;
	seg->free_head = (rtapi_u32)((char *)b - (char *)seg);
}

void hal_free_owned(struct hal_seg_hdr *seg, rtapi_u32 owner_off)
{
	rtapi_u32 off;

	for (off = seg->heap_start; off < seg->heap_top; off += block_at(seg, off)->size) {
		struct hal_block_hdr *b = block_at(seg, off);

		if (b->kind != HAL_KIND_FREE && b->owner_off == owner_off) {
			seg->bytes_used -= b->size;
			b->kind = HAL_KIND_FREE;
			b->owner_off = 0;
		}
	}
	hal_heap_compact(seg);
}

/* Rebuild the free list in address order, merging neighbours and giving the
 * free tail back to the bump area. */
void hal_heap_compact(struct hal_seg_hdr *seg)
{
	rtapi_u32 off = seg->heap_start, last_used_end = seg->heap_start;
	rtapi_u32 *link = &seg->free_head;

	seg->free_head = 0;
	while (off < seg->heap_top) {
		struct hal_block_hdr *b = block_at(seg, off);

		if (b->kind != HAL_KIND_FREE) {
			off += b->size;
			last_used_end = off;
			continue;
		}
		while (off + b->size < seg->heap_top &&
		       block_at(seg, off + b->size)->kind == HAL_KIND_FREE)
			b->size += block_at(seg, off + b->size)->size;
		*link = off;
		b->next_free_off = 0;
		link = &b->next_free_off;
		off += b->size;
	}
	/* Free blocks at the very end return to the bump area. */
	if (last_used_end < seg->heap_top) {
		rtapi_u32 *l = &seg->free_head;

		while (*l && *l != last_used_end)
			l = &block_at(seg, *l)->next_free_off;
		if (*l)
			*l = 0;
		seg->heap_top = last_used_end;
	}
}
