/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_extras_uspace.c - the simulated flavor's RTAPI extras that LinuxCNC's uspace
 * RTAPI offers and out-of-tree modules (hm2_eth and the like) link against:
 * rtapi_spawn_as_root / rtapi_spawnp_as_root, rtapi_open_as_root, rtapi_is_realtime,
 * rtapi_is_kernelspace. rtapi_app is not setuid here, so "as root" means with the
 * host's own privileges (root when it was started as root). RTAPI build only: init
 * and non-realtime code may call them, never a realtime function. */
#include <fcntl.h>
#include <sched.h>
#include <spawn.h>
#include <stdio.h>
#include <sys/resource.h>
#include <unistd.h>
#include "rtapi.h"

int rtapi_spawn_as_root(pid_t *pid, const char *path, const posix_spawn_file_actions_t *file_actions,
			const posix_spawnattr_t *attrp, char *const argv[], char *const envp[])
{
	return posix_spawn(pid, path, file_actions, attrp, argv, envp);
}

int rtapi_spawnp_as_root(pid_t *pid, const char *path, const posix_spawn_file_actions_t *file_actions,
			 const posix_spawnattr_t *attrp, char *const argv[], char *const envp[])
{
	return posix_spawnp(pid, path, file_actions, attrp, argv, envp);
}

int rtapi_open_as_root(const char *filename, int mode)
{
	int fd = open(filename, mode | O_CLOEXEC);

	return fd < 0 ? -errno : fd;
}

int rtapi_is_kernelspace(void)
{
	return 0;
}

/* Realtime means here what LinuxCNC's uspace RTAPI means: a PREEMPT_RT kernel, and a
 * process that may use SCHED_FIFO (root, or an rtprio limit). */
int rtapi_is_realtime(void)
{
	struct rlimit rl;
	int rt = 0;
	FILE *f = fopen("/sys/kernel/realtime", "re");

	if (f) {
		rt = fgetc(f) == '1';
		fclose(f);
	}
	if (!rt)
		return 0;
	return geteuid() == 0 || (getrlimit(RLIMIT_RTPRIO, &rl) == 0 && rl.rlim_cur > 0);
}
