/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hal_alloc.c - the heap inside the HAL segment. Every block carries its owner,
 * so a component's records and its hal_malloc() memory are reclaimed when it
 * unloads (hal_malloc(3hal) promises no free; we do better). First fit over an
 * unordered free list, bump allocation above it; merging happens in
 * hal_heap_compact() after a component goes away. Caller holds the HAL lock.
 * The value area above val_start (hal_layout.h) has no headers users could forge: its
 * 8-byte granules are handed out by a bitmap that lives in the record heap. */
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

/* --- the value area: a bitmap of 8-byte granules --- */

static rtapi_u64 *val_map(struct hal_seg_hdr *seg)
{
	return (rtapi_u64 *)((char *)seg + seg->val_map_off);
}

static rtapi_u32 val_granules(const struct hal_seg_hdr *seg)
{
	return (seg->size - seg->val_start) / 8;
}

static bool granule_used(struct hal_seg_hdr *seg, rtapi_u32 g)
{
	return (val_map(seg)[g / 64] >> (g % 64)) & 1;
}

static void granules_mark(struct hal_seg_hdr *seg, rtapi_u32 g, rtapi_u32 n, bool used)
{
	rtapi_u64 *map = val_map(seg);

	for (; n; g++, n--) {
		if (used)
			map[g / 64] |= 1ull << (g % 64);
		else
			map[g / 64] &= ~(1ull << (g % 64));
	}
}

/* First fit from the hint, then from the start: 'n' free granules in a row, or -1. */
static long granules_find(struct hal_seg_hdr *seg, rtapi_u32 n)
{
	rtapi_u32 total = val_granules(seg), hint = seg->val_hint < total ? seg->val_hint : 0;
	rtapi_u32 g, end, run;
	int pass;

	for (pass = 0; pass < 2; pass++) {
		g = pass ? 0 : hint;
		end = pass ? (hint + n < total ? hint + n : total) : total;
		for (run = 0; g < end; g++) {
			if (granule_used(seg, g)) {
				run = 0;
				continue;
			}
			if (++run == n)
				return (long)(g + 1 - n);
		}
	}
	return -1;
}

static void *record_alloc(struct hal_seg_hdr *seg, rtapi_u32 size, enum hal_kind kind,
			  rtapi_u32 owner_off);

static void *value_alloc(struct hal_seg_hdr *seg, rtapi_u32 size, enum hal_kind kind, rtapi_u32 owner_off)
{
	rtapi_u32 n = (size + 7) / 8, off;
	struct hal_umalloc_rec *rec = 0;
	rtapi_u64 *p;
	long g;
	rtapi_u32 i;

	if (size == 0 || n > val_granules(seg))
		return 0;
	g = granules_find(seg, n);
	if (g < 0)
		return 0;
	if (kind == HAL_KIND_UMALLOC) {	/* its record, in the record heap */
		rec = record_alloc(seg, sizeof(*rec), HAL_KIND_UMALLOC, owner_off);
		if (!rec)
			return 0;
	}
	granules_mark(seg, (rtapi_u32)g, n, true);
	seg->val_hint = (rtapi_u32)g + n;
	off = seg->val_start + (rtapi_u32)g * 8;
	if (off + n * 8 > seg->val_top)
		seg->val_top = off + n * 8;
	seg->val_bytes_used += n * 8;
	if (rec) {
		rec->off = off;
		rec->size = n * 8;
	}
	p = (rtapi_u64 *)((char *)seg + off);
	for (i = 0; i < n; i++)
		p[i] = 0;
	return p;
}

static void value_free(struct hal_seg_hdr *seg, rtapi_u32 off, rtapi_u32 size)
{
	rtapi_u32 g = (off - seg->val_start) / 8, n = size / 8;

	granules_mark(seg, g, n, false);
	seg->val_bytes_used -= n * 8;
	if (g < seg->val_hint)
		seg->val_hint = g;
}

void *hal_alloc_block(struct hal_seg_hdr *seg, rtapi_u32 size, enum hal_kind kind, rtapi_u32 owner_off)
{
	if (kind == HAL_KIND_VALUE || kind == HAL_KIND_UMALLOC)
		return value_alloc(seg, size, kind, owner_off);
	return record_alloc(seg, size, kind, owner_off);
}

static void *record_alloc(struct hal_seg_hdr *seg, rtapi_u32 size, enum hal_kind kind,
			  rtapi_u32 owner_off)
{
	rtapi_u32 need = (size + sizeof(struct hal_block_hdr) + HAL_ALIGN - 1) & ~(HAL_ALIGN - 1);
	struct hal_block_hdr *b;

	if (size == 0 || size > seg->size)
		return 0;
	b = take_free(seg, need);
	if (!b) {
		if (seg->val_start - seg->heap_top < need)
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
	rtapi_u32 off = (rtapi_u32)((char *)data - (char *)seg);

	if (off >= seg->val_start) {	/* a HAL_KIND_VALUE: 8 bytes */
		value_free(seg, off, 8);
		return;
	}
	if (b->kind == HAL_KIND_UMALLOC) {
		const struct hal_umalloc_rec *rec = data;

		value_free(seg, rec->off, rec->size);
	}
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
			if (b->kind == HAL_KIND_UMALLOC) {
				const struct hal_umalloc_rec *rec = (const void *)(b + 1);

				value_free(seg, rec->off, rec->size);
			}
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

bool hal_umalloc_owned(const struct hal_seg_hdr *seg, rtapi_u32 owner_off, rtapi_u32 off, rtapi_u32 len)
{
	rtapi_u32 b;

	for (b = seg->heap_start; b < seg->heap_top;) {
		const struct hal_block_hdr *h = (const struct hal_block_hdr *)((const char *)seg + b);
		const struct hal_umalloc_rec *rec = (const void *)(h + 1);

		if (h->kind == HAL_KIND_UMALLOC && h->owner_off == owner_off && off >= rec->off &&
		    off < rec->off + rec->size && len <= rec->off + rec->size - off)
			return true;
		b += h->size;
	}
	return false;
}
