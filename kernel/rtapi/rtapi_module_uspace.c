/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_module_uspace.c - rtapi_init/rtapi_exit (rtapi_init(3rtapi), rtapi_exit(3rtapi))
 * for the simulated-realtime flavor: a per-process table of module names. Ids are
 * only meaningful inside the process that got them. */
#include <errno.h>
#include <pthread.h>
#include <signal.h>
#include <string.h>
#include <unistd.h>
#include "rtapi.h"
#include "rtapi_uspace.h"

struct rtapi_module_rec {
	int in_use;
	char name[RTAPI_NAME_LEN + 1];	/* truncated to RTAPI_NAME_LEN */
};

static pthread_mutex_t module_lock = PTHREAD_MUTEX_INITIALIZER;
static struct rtapi_module_rec modules[RTAPI_MAX_MODULES + 1];	/* [0] unused */

int rtapi_init(const char *modname)
{
	int id;

	pthread_mutex_lock(&module_lock);
	for (id = 1; id <= RTAPI_MAX_MODULES; id++)
		if (!modules[id].in_use)
			break;
	if (id > RTAPI_MAX_MODULES) {
		pthread_mutex_unlock(&module_lock);
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: rtapi_init('%s') failed: all %d module slots in use\n",
				modname ? modname : "", RTAPI_MAX_MODULES);
		return -ENOMEM;
	}
	modules[id].in_use = 1;
	if (modname && modname[0])
		rtapi_snprintf(modules[id].name, sizeof(modules[id].name), "%s", modname);
	else	/* unnamed modules get a name that says where they came from */
		rtapi_snprintf(modules[id].name, sizeof(modules[id].name), "module%d", id);
	pthread_mutex_unlock(&module_lock);
	rtapi_print_msg(RTAPI_MSG_DBG, "rtapi: module '%s' is id %d\n", modules[id].name, id);
	return id;
}

int rtapi_module_is_valid(int module_id)
{
	int ok;

	if (module_id < 1 || module_id > RTAPI_MAX_MODULES)
		return 0;
	pthread_mutex_lock(&module_lock);
	ok = modules[module_id].in_use;
	pthread_mutex_unlock(&module_lock);
	return ok;
}

int rtapi_exit(int module_id)
{
	if (!rtapi_module_is_valid(module_id)) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: rtapi_exit(%d): no such module\n", module_id);
		return -EINVAL;
	}
	rtapi_shmem_module_exit(module_id);	/* what the module forgot to delete */
	pthread_mutex_lock(&module_lock);
	modules[module_id].in_use = 0;
	modules[module_id].name[0] = '\0';
	pthread_mutex_unlock(&module_lock);
	return 0;
}

/* getpid() is a system call (glibc stopped caching it) and the HAL lock asks for the
 * caller's pid at every acquisition: a third of loading a large .hal file went there.
 * The pid is cached, and forgotten in the child of a fork (posix_spawn's child execs
 * without calling back into this library). */
static int cached_pid;
static pthread_once_t pid_once = PTHREAD_ONCE_INIT;

static void forget_pid(void)
{
	__atomic_store_n(&cached_pid, 0, __ATOMIC_RELAXED);
}

static void watch_forks(void)
{
	pthread_atfork(0, 0, forget_pid);
}

long rtapi_getpid(void)
{
	int pid = __atomic_load_n(&cached_pid, __ATOMIC_RELAXED);

	if (!pid) {
		pthread_once(&pid_once, watch_forks);
		pid = (int)getpid();
		__atomic_store_n(&cached_pid, pid, __ATOMIC_RELAXED);
	}
	return pid;
}

bool rtapi_process_exists(long pid)
{
	/* EPERM: it exists but belongs to another user; only ESRCH means gone */
	return pid > 0 && (kill((pid_t)pid, 0) == 0 || errno != ESRCH);
}
