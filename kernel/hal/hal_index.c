/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hal_index.c - the name index (one hash table over all kinds, so lookups are
 * O(1) and loading a long .hal file stays linear) and the per-kind lists in
 * creation order. Caller holds the HAL lock. */
#include "hal_internal.h"
#include "rtapi_string.h"

static rtapi_u32 *buckets(struct hal_seg_hdr *seg)
{
	return (rtapi_u32 *)((char *)seg + seg->hash_off);
}

static struct hal_obj_hdr *obj_at(struct hal_seg_hdr *seg, rtapi_u32 off)
{
	return off ? (struct hal_obj_hdr *)((char *)seg + off) : 0;
}

static rtapi_u32 obj_off(struct hal_seg_hdr *seg, struct hal_obj_hdr *obj)
{
	return (rtapi_u32)((char *)obj - (char *)seg);
}

/* FNV-1a over the kind and the name. */
rtapi_u32 hal_name_hash(enum hal_kind kind, const char *name)
{
	rtapi_u32 h = 2166136261u ^ (rtapi_u32)kind;

	while (*name) {
		h ^= (unsigned char)*name++;
		h *= 16777619u;
	}
	return h;
}

void hal_index_hash_insert(struct hal_seg_hdr *seg, struct hal_obj_hdr *obj)
{
	rtapi_u32 *bucket = &buckets(seg)[obj->hash & (HAL_HASH_BUCKETS - 1)];

	obj->hash_next_off = *bucket;
	*bucket = obj_off(seg, obj);
}

void hal_index_hash_remove(struct hal_seg_hdr *seg, struct hal_obj_hdr *obj)
{
	rtapi_u32 off = obj_off(seg, obj);
	rtapi_u32 *link = &buckets(seg)[obj->hash & (HAL_HASH_BUCKETS - 1)];

	while (*link && *link != off)
		link = &obj_at(seg, *link)->hash_next_off;
	if (*link)
		*link = obj->hash_next_off;
}

void hal_index_insert(struct hal_seg_hdr *seg, struct hal_obj_hdr *obj)
{
	rtapi_u32 off = obj_off(seg, obj);
	rtapi_u32 *bucket = &buckets(seg)[obj->hash & (HAL_HASH_BUCKETS - 1)];

	obj->hash_next_off = *bucket;
	*bucket = off;
	obj->next_off = 0;
	obj->prev_off = seg->list_tail[obj->kind];
	if (obj->prev_off)
		obj_at(seg, obj->prev_off)->next_off = off;
	else
		seg->list_head[obj->kind] = off;
	seg->list_tail[obj->kind] = off;
	seg->count[obj->kind]++;
}

void hal_index_remove(struct hal_seg_hdr *seg, struct hal_obj_hdr *obj)
{
	rtapi_u32 off = obj_off(seg, obj);
	rtapi_u32 *link = &buckets(seg)[obj->hash & (HAL_HASH_BUCKETS - 1)];

	while (*link && *link != off)
		link = &obj_at(seg, *link)->hash_next_off;
	if (*link)
		*link = obj->hash_next_off;
	if (obj->prev_off)
		obj_at(seg, obj->prev_off)->next_off = obj->next_off;
	else
		seg->list_head[obj->kind] = obj->next_off;
	if (obj->next_off)
		obj_at(seg, obj->next_off)->prev_off = obj->prev_off;
	else
		seg->list_tail[obj->kind] = obj->prev_off;
	seg->count[obj->kind]--;
}

struct hal_obj_hdr *hal_index_find(struct hal_seg_hdr *seg, enum hal_kind kind, const char *name)
{
	rtapi_u32 h = hal_name_hash(kind, name);
	struct hal_obj_hdr *o = obj_at(seg, buckets(seg)[h & (HAL_HASH_BUCKETS - 1)]);

	for (; o; o = obj_at(seg, o->hash_next_off))
		if (o->hash == h && o->kind == kind && strcmp(o->name, name) == 0)
			return (o->flags & HAL_OBJ_ALIAS) ? hal_alias_target(seg, o) : o;
	return 0;
}

const char *hal_kind_name(enum hal_kind kind)
{
	switch (kind) {
	case HAL_KIND_COMP: return "component";
	case HAL_KIND_PIN: return "pin";
	case HAL_KIND_PARAM: return "parameter";
	case HAL_KIND_SIG: return "signal";
	case HAL_KIND_FUNCT: return "function";
	case HAL_KIND_THREAD: return "thread";
	default: return "object";
	}
}

static int check_name(enum hal_kind kind, const char *name)
{
	const char *p;

	if (!name || !*name) {
		rtapi_print_msg(RTAPI_MSG_ERR, "%s name is empty\n", hal_kind_name(kind));
		return -EINVAL;
	}
	if (strlen(name) > HAL_NAME_LEN) {
		rtapi_print_msg(RTAPI_MSG_ERR, "%s name '%s' is longer than %d characters\n",
				hal_kind_name(kind), name, HAL_NAME_LEN);
		return -EINVAL;
	}
	/* The name is not echoed: it may hold terminal escape sequences. */
	for (p = name; *p; p++) {
		unsigned char c = (unsigned char)*p;

		if (c == ' ' || c == '\t') {
			rtapi_print_msg(RTAPI_MSG_ERR, "%s name contains whitespace (at position %d)\n",
					hal_kind_name(kind), (int)(p - name) + 1);
			return -EINVAL;
		}
		if (c < ' ' || c == 0x7f) {
			rtapi_print_msg(RTAPI_MSG_ERR, "%s name contains control character 0x%02x "
					"(at position %d)\n", hal_kind_name(kind), c, (int)(p - name) + 1);
			return -EINVAL;
		}
		if (c > 0x7f) {
			rtapi_print_msg(RTAPI_MSG_ERR, "%s name contains a non-ASCII byte 0x%02x (at "
					"position %d): HAL names are ASCII\n", hal_kind_name(kind), c,
					(int)(p - name) + 1);
			return -EINVAL;
		}
	}
	return 0;
}

void *hal_object_new(enum hal_kind kind, rtapi_u32 size, const char *name, rtapi_u32 owner_off, int *err)
{
	struct hal_obj_hdr *obj;

	*err = check_name(kind, name);
	if (*err)
		return 0;
	if (hal_find(kind, name)) {
		rtapi_print_msg(RTAPI_MSG_ERR, "%s '%s' already exists\n", hal_kind_name(kind), name);
		*err = -EEXIST;
		return 0;
	}
	obj = hal_alloc_block(hal_seg, size, kind, owner_off);
	if (!obj) {
		rtapi_print_msg(RTAPI_MSG_ERR, "HAL shared memory is full: cannot create %s '%s'\n",
				hal_kind_name(kind), name);
		*err = -ENOMEM;
		return 0;
	}
	obj->kind = kind;
	obj->owner_off = owner_off;
	obj->hash = hal_name_hash(kind, name);
	strcpy(obj->name, name);
	hal_index_insert(hal_seg, obj);
	return obj;
}

void hal_object_delete(struct hal_obj_hdr *obj)
{
	hal_alias_remove_all(obj);	/* its other names go with it */
	hal_index_remove(hal_seg, obj);
	hal_free_block(hal_seg, obj);
}

int hal_format_name(char *buf, const char *what, const char *fmt, va_list ap)
{
	int n = rtapi_vsnprintf(buf, HAL_NAME_LEN + 1, fmt, ap);

	if (n < 0 || n > HAL_NAME_LEN) {
		rtapi_print_msg(RTAPI_MSG_ERR, "%s name '%s...' is longer than %d characters\n",
				what, buf, HAL_NAME_LEN);
		return -EINVAL;
	}
	return 0;
}
