/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_modparam_uspace.c - module parameter registry and value parsing for rtapi_app
 * (rtapi_modparam_uspace.h), simulated-realtime flavor. Splitting the loadrt line into
 * name=value words is rtapi_app's job; this file parses one value. */
#include <limits.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include "rtapi.h"
#include "rtapi_modparam_uspace.h"

struct mp_list {
	void **items;
	int n, cap;
};

static pthread_mutex_t mp_lock = PTHREAD_MUTEX_INITIALIZER;
static struct mp_list collected;	/* const struct rtapi_mp_desc * */
static struct mp_list owned;		/* strings we strdup'ed into modules' variables */

/* caller holds mp_lock */
static int list_add(struct mp_list *l, void *item)
{
	if (l->n == l->cap) {
		int cap = l->cap ? 2 * l->cap : 16;
		void **items = realloc(l->items, (size_t)cap * sizeof(*items));

		if (!items)
			return -ENOMEM;
		l->items = items;
		l->cap = cap;
	}
	l->items[l->n++] = item;
	return 0;
}

void rtapi_mp_register(const struct rtapi_mp_desc *desc)
{
	int err;

	pthread_mutex_lock(&mp_lock);
	err = list_add(&collected, (void *)desc);
	pthread_mutex_unlock(&mp_lock);
	if (err)
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: module parameter '%s' lost: out of memory\n",
				desc->name);
}

void rtapi_mp_collect_begin(void)
{
	pthread_mutex_lock(&mp_lock);
	collected.n = 0;
	pthread_mutex_unlock(&mp_lock);
}

int rtapi_mp_collect_end(const struct rtapi_mp_desc ***out)
{
	int n;

	pthread_mutex_lock(&mp_lock);
	*out = (const struct rtapi_mp_desc **)collected.items;
	n = collected.n;
	pthread_mutex_unlock(&mp_lock);
	return n;
}

/* Parse one integer element; 0 or -EINVAL with err filled. */
static int parse_integer(const struct rtapi_mp_desc *d, const char *text, long *out,
			 char *err, unsigned long errlen)
{
	long lo = d->type == RTAPI_MP_TYPE_INT ? INT_MIN : LONG_MIN;
	long hi = d->type == RTAPI_MP_TYPE_INT ? INT_MAX : LONG_MAX;
	char *end;
	long v;

	errno = 0;
	v = strtol(text, &end, 0);
	if (end == text || *end || text[0] == ' ' || text[0] == '\t') {
		rtapi_snprintf(err, errlen, "%s: '%s' is not an integer", d->name, text);
		return -EINVAL;
	}
	if (errno == ERANGE || v < lo || v > hi) {
		rtapi_snprintf(err, errlen, "%s: %s is out of range for %s (%ld..%ld)", d->name, text,
			       d->type == RTAPI_MP_TYPE_INT ? "an int" : "a long", lo, hi);
		return -EINVAL;
	}
	*out = v;
	return 0;
}

/* Split 'value' in place at commas into at most 'max' elements. */
static int split_list(const struct rtapi_mp_desc *d, char *value, char **elem, int max,
		      char *err, unsigned long errlen)
{
	int n = 1, i;
	char *p;

	/* "names=" (nothing at all) is one empty string, as the kernel's module_param_array
	 * makes it: components read it as "names= not given" (LinuxCNC: the default count). */
	if (d->type == RTAPI_MP_TYPE_STRING && !value[0]) {
		elem[0] = value;
		return 1;
	}
	for (p = value; *p; p++)
		if (*p == ',')
			n++;
	if (n > max) {
		rtapi_snprintf(err, errlen, "%s: %d values given, at most %d allowed", d->name, n, max);
		return -EINVAL;
	}
	elem[0] = value;
	for (i = 1, p = value; *p; p++) {
		if (*p == ',') {
			*p = '\0';
			elem[i++] = p + 1;
		}
	}
	for (i = 0; i < n; i++) {
		if (!elem[i][0]) {
			rtapi_snprintf(err, errlen, "%s: value %d of %d is empty", d->name, i + 1, n);
			return -EINVAL;
		}
	}
	return n;
}

/* caller holds mp_lock: replace *slot by a copy of text, freeing our earlier copy */
static int assign_string(char **slot, const char *text)
{
	char *copy = strdup(text);
	int i;

	if (!copy || list_add(&owned, copy) != 0) {
		free(copy);
		return -ENOMEM;
	}
	for (i = 0; i < owned.n - 1; i++) {
		if (owned.items[i] == *slot) {
			free(owned.items[i]);
			owned.items[i] = copy;	/* the last entry moves into the hole */
			owned.n--;
			break;
		}
	}
	*slot = copy;
	return 0;
}

int rtapi_mp_set(const struct rtapi_mp_desc *d, const char *value, char *err, unsigned long errlen)
{
	int max = d->num > 0 ? d->num : 1, n, i, ret = 0;
	char *buf, **elem;
	long *nums;

	if (!value) {
		rtapi_snprintf(err, errlen, "%s: no value given", d->name);
		return -EINVAL;
	}
	buf = strdup(value);
	elem = calloc((size_t)max, sizeof(*elem));
	nums = calloc((size_t)max, sizeof(*nums));
	if (!buf || !elem || !nums) {
		rtapi_snprintf(err, errlen, "%s: out of memory", d->name);
		ret = -ENOMEM;
		goto free_bufs;
	}
	if (d->num > 0) {
		n = split_list(d, buf, elem, max, err, errlen);
		if (n < 0) {
			ret = n;
			goto free_bufs;
		}
	} else {
		elem[0] = buf;	/* a scalar may contain commas (strings) */
		n = 1;
	}
	if (d->type != RTAPI_MP_TYPE_STRING)
		for (i = 0; i < n && !ret; i++)
			ret = parse_integer(d, elem[i], &nums[i], err, errlen);
	if (ret)
		goto free_bufs;
	pthread_mutex_lock(&mp_lock);	/* all parsed: now assign */
	for (i = 0; i < n && !ret; i++) {
		if (d->type == RTAPI_MP_TYPE_INT)
			((int *)d->addr)[i] = (int)nums[i];
		else if (d->type == RTAPI_MP_TYPE_LONG)
			((long *)d->addr)[i] = nums[i];
		else
			ret = assign_string(&((char **)d->addr)[i], elem[i]);
	}
	pthread_mutex_unlock(&mp_lock);
	if (ret)
		rtapi_snprintf(err, errlen, "%s: out of memory", d->name);
free_bufs:
	free(nums);
	free(elem);
	free(buf);
	return ret;
}
