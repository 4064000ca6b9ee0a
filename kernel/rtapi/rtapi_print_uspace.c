/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_print_uspace.c - rtapi_print, rtapi_print_msg, message level and handler
 * (rtapi_print(3rtapi), rtapi_set_msg_level(3rtapi)) for the simulated-realtime flavor.
 * Messages are formatted into a stack buffer (no allocation, usable from tasks) and
 * handed to the handler; the default handler writes them to stderr in one write(). */
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>
#include "rtapi.h"

#define RTAPI_PRINT_BUF 1024	/* longer messages are cut and end in "...\n" */

/* Default RTAPI_MSG_WARN: warnings (no SCHED_FIFO, missed periods, a lock taken over
 * from a dead process) are what users must see; INFO would flood every halcmd run. Env RTAPI_MSG_LEVEL
 * (a number 0..5 or NONE/ERR/WARN/INFO/DBG/ALL) overrides it at program start. */
static int msg_level = RTAPI_MSG_WARN;
static void default_handler(msg_level_t level, const char *msg);
static rtapi_msg_handler_t msg_handler = default_handler;

static int parse_level(const char *s)
{
	static const char *const names[] = { "NONE", "ERR", "WARN", "INFO", "DBG", "ALL" };
	int i;

	if (s[0] >= '0' && s[0] <= '5' && s[1] == '\0')
		return s[0] - '0';
	for (i = 0; i <= RTAPI_MSG_ALL; i++)
		if (strcasecmp(s, names[i]) == 0)
			return i;
	return -1;
}

__attribute__((constructor)) static void msg_level_from_env(void)
{
	const char *env = getenv("RTAPI_MSG_LEVEL");
	int level;

	if (!env || !env[0])
		return;
	level = parse_level(env);
	if (level < 0)
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: RTAPI_MSG_LEVEL='%s' ignored: use 0..5 or "
				"NONE, ERR, WARN, INFO, DBG, ALL\n", env);
	else
		msg_level = level;
}

static void default_handler(msg_level_t level, const char *msg)
{
	size_t len = strlen(msg);

	while (len > 0) {
		ssize_t n = write(STDERR_FILENO, msg, len);

		if (n <= 0)
			return;	/* nowhere to report it */
		msg += n;
		len -= (size_t)n;
	}
}

static void deliver(msg_level_t level, const char *fmt, va_list ap)
{
	char buf[RTAPI_PRINT_BUF];
	rtapi_msg_handler_t h = __atomic_load_n(&msg_handler, __ATOMIC_ACQUIRE);

	if (rtapi_vsnprintf(buf, sizeof(buf), fmt, ap) >= (int)sizeof(buf))
		memcpy(buf + sizeof(buf) - 5, "...\n", 5);
	h(level, buf);
}

void rtapi_print(const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	deliver(RTAPI_MSG_ALL, fmt, ap);
	va_end(ap);
}

void rtapi_print_msg(int level, const char *fmt, ...)
{
	va_list ap;

	if (level > __atomic_load_n(&msg_level, __ATOMIC_RELAXED))
		return;
	va_start(ap, fmt);
	deliver((msg_level_t)level, fmt, ap);
	va_end(ap);
}

int rtapi_set_msg_level(int level)
{
	if (level < RTAPI_MSG_NONE || level > RTAPI_MSG_ALL)
		return -EINVAL;
	__atomic_store_n(&msg_level, level, __ATOMIC_RELAXED);
	return 0;
}

int rtapi_get_msg_level(void)
{
	return __atomic_load_n(&msg_level, __ATOMIC_RELAXED);
}

void rtapi_set_msg_handler(rtapi_msg_handler_t handler)
{
	__atomic_store_n(&msg_handler, handler ? handler : default_handler, __ATOMIC_RELEASE);
}

rtapi_msg_handler_t rtapi_get_msg_handler(void)
{
	return __atomic_load_n(&msg_handler, __ATOMIC_ACQUIRE);
}
