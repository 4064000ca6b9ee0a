/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hal_alias.c - second names of pins and parameters (LinuxCNC's hal_pin_alias,
 * halcmd "alias"/"unalias"). An alias is an extra entry in the name index that
 * answers the same record, so both names work everywhere (getp, net, setp): motion
 * exports today's names and the EMC2 names as aliases (RULINGS.md "motion names").
 * Aliases are chained from hal_seg_hdr.alias_head; they are few, so walking the
 * chain when a pin or param goes away is cheap. */
#include "hal_internal.h"
#include "hal_query.h"
#include "rtapi_string.h"

static struct hal_alias_rec *alias_at(rtapi_u32 off)
{
	return hal_ptr(off);
}

struct hal_obj_hdr *hal_alias_target(struct hal_seg_hdr *seg, const struct hal_obj_hdr *alias)
{
	const struct hal_alias_rec *a = (const struct hal_alias_rec *)alias;

	return a->target_off ? (struct hal_obj_hdr *)((char *)seg + a->target_off) : 0;
}

static void alias_unlink(struct hal_alias_rec *a)
{
	rtapi_u32 off = hal_off(a);

	if (a->hdr.prev_off)
		alias_at(a->hdr.prev_off)->hdr.next_off = a->hdr.next_off;
	else if (hal_seg->alias_head == off)
		hal_seg->alias_head = a->hdr.next_off;
	if (a->hdr.next_off)
		alias_at(a->hdr.next_off)->hdr.prev_off = a->hdr.prev_off;
	hal_index_hash_remove(hal_seg, &a->hdr);
	hal_seg->alias_count--;
	hal_free_block(hal_seg, a);
}

/* caller holds the HAL lock */
void hal_alias_remove_all(struct hal_obj_hdr *target)
{
	rtapi_u32 off, next, target_off = hal_off(target);

	if (!hal_seg->alias_count || (target->kind != HAL_KIND_PIN && target->kind != HAL_KIND_PARAM))
		return;
	for (off = hal_seg->alias_head; off; off = next) {
		struct hal_alias_rec *a = alias_at(off);

		next = a->hdr.next_off;
		if (a->target_off == target_off)
			alias_unlink(a);
	}
}

static int alias_add_locked(enum hal_kind kind, struct hal_obj_hdr *target, const char *alias)
{
	struct hal_alias_rec *a;
	const char *p;

	if (strlen(alias) > HAL_NAME_LEN) {
		rtapi_print_msg(RTAPI_MSG_ERR, "alias '%s' of %s '%s' is longer than %d characters\n",
				alias, hal_kind_name(kind), target->name, HAL_NAME_LEN);
		return -EINVAL;
	}
	for (p = alias; *p; p++) {
		if (*p <= ' ' || *p == 0x7f) {
			rtapi_print_msg(RTAPI_MSG_ERR, "alias '%s' contains whitespace or a control character\n",
					alias);
			return -EINVAL;
		}
	}
	a = hal_alloc_block(hal_seg, sizeof(*a), HAL_KIND_ALIAS, 0);
	if (!a) {
		rtapi_print_msg(RTAPI_MSG_ERR, "HAL shared memory is full: cannot create alias '%s'\n", alias);
		return -ENOMEM;
	}
	/* Filed under the target's kind in the name index only (no kind list). */
	a->hdr.kind = kind;
	a->hdr.flags = HAL_OBJ_ALIAS;
	a->hdr.owner_off = 0;
	a->hdr.hash = hal_name_hash(kind, alias);
	strcpy(a->hdr.name, alias);
	a->target_off = hal_off(target);
	hal_index_hash_insert(hal_seg, &a->hdr);
	a->hdr.prev_off = 0;
	a->hdr.next_off = hal_seg->alias_head;
	if (a->hdr.next_off)
		alias_at(a->hdr.next_off)->hdr.prev_off = hal_off(a);
	hal_seg->alias_head = hal_off(a);
	hal_seg->alias_count++;
	return 0;
}

/* caller holds the HAL lock */
int hal_alias_set_locked(enum hal_kind kind, const char *name, const char *alias)
{
	struct hal_obj_hdr *target;
	int err = hal_check_lock(HAL_LOCK_CONFIG, "change aliases");

	if (err)
		return err;
	target = hal_find(kind, name);
	if (!target) {
		rtapi_print_msg(RTAPI_MSG_ERR, "alias: %s '%s' does not exist\n", hal_kind_name(kind), name);
		return -ENOENT;
	}
	if (alias && alias[0]) {
		if (hal_find(kind, alias)) {
			rtapi_print_msg(RTAPI_MSG_ERR, "alias: a %s or alias named '%s' already exists\n",
					hal_kind_name(kind), alias);
			return -EEXIST;
		}
		return alias_add_locked(kind, target, alias);
	}
	hal_alias_remove_all(target);
	return 0;
}

static int alias_set(enum hal_kind kind, const char *name, const char *alias)
{
	int rc;

	if (!hal_seg || !name) {
		rtapi_print_msg(RTAPI_MSG_ERR, "alias: HAL is not initialised or no name given\n");
		return -EINVAL;
	}
#ifdef ULAPI
	/* a userspace program changes the records only through a checked request */
	return hal_ul_names(HAL_REQ_ALIAS, name, alias ? alias : "", kind == HAL_KIND_PARAM);
#endif
	hal_lock();
	rc = hal_alias_set_locked(kind, name, alias);
	hal_unlock();
	return rc;
}

int hal_pin_alias(const char *pin_name, const char *alias)
{
	return alias_set(HAL_KIND_PIN, pin_name, alias);
}

int hal_param_alias(const char *param_name, const char *alias)
{
	return alias_set(HAL_KIND_PARAM, param_name, alias);
}

/* The alias record named 'name' of this kind, or NULL (a real object's name is no alias).
 * Only unalias (hal_unalias_locked) looks aliases up by their own name. */
static struct hal_alias_rec *alias_named(enum hal_kind kind, const char *name)
{
	rtapi_u32 off;

	for (off = hal_seg->alias_head; off; off = alias_at(off)->hdr.next_off) {
		struct hal_alias_rec *a = alias_at(off);

		if (a->hdr.kind == kind && strcmp(a->hdr.name, name) == 0)
			return a;
	}
	return 0;
}

/* caller holds the HAL lock (hal_request.c: halcmd unalias) */
int hal_unalias_locked(enum hal_kind kind, const char *name)
{
	struct hal_alias_rec *a;
	struct hal_obj_hdr *target;
	int rc = hal_check_lock(HAL_LOCK_CONFIG, "change aliases");

	if (rc)
		return rc;
	a = alias_named(kind, name);
	if (a) {
		alias_unlink(a);
		return 0;
	}
	target = hal_find(kind, name);
	if (!target) {
		rtapi_print_msg(RTAPI_MSG_ERR, "unalias: no %s or alias named '%s'\n", hal_kind_name(kind), name);
		return -ENOENT;
	}
	hal_alias_remove_all(target);
	return 0;
}

#ifdef ULAPI

/* --- tools (hal_query.h) --- */

static int unalias(enum hal_kind kind, const char *name)
{
	if (!hal_seg) {
		rtapi_print_msg(RTAPI_MSG_ERR, "unalias: HAL is not attached\n");
		return -EINVAL;
	}
	return hal_ul_names(HAL_REQ_UNALIAS, name, 0, kind == HAL_KIND_PARAM);
}

int hal_unalias_pin(const char *name)
{
	return unalias(HAL_KIND_PIN, name);
}

int hal_unalias_param(const char *name)
{
	return unalias(HAL_KIND_PARAM, name);
}

int hal_query_aliases(int (*cb)(const struct hal_alias_info *, void *), void *ctx)
{
	struct hal_alias_info info;
	rtapi_u32 off;
	int n = 0;

	if (!hal_seg)
		return -EINVAL;
	hal_lock();
	for (off = hal_seg->alias_head; off; off = alias_at(off)->hdr.next_off) {
		struct hal_alias_rec *a = alias_at(off);
		struct hal_obj_hdr *t = hal_alias_target(hal_seg, &a->hdr);

		info.is_param = a->hdr.kind == HAL_KIND_PARAM;
		rtapi_snprintf(info.alias, sizeof(info.alias), "%s", a->hdr.name);
		rtapi_snprintf(info.target, sizeof(info.target), "%s", t ? t->name : "");
		n++;
		if (cb(&info, ctx))
			break;
	}
	hal_unlock();
	return n;
}
#endif
