/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hal_os_uspace.c - what the HAL core asks of the operating system in userspace
 * (rtapi_app and tools): who we are and whether a process still lives, for the
 * HAL mutex's holder record (hal_lock.c). The kernel flavor's are in hal_lib_kmod.c. */
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "hal_internal.h"

const char *hal_os_segment_size_text(void)
{
	const char *s = getenv("HAL_SIZE");

	return s ? s : "";
}

int hal_os_self(char *name, int len)
{
	static char comm[16];
	int fd;

	if (!comm[0]) {
		ssize_t n = -1;

		fd = open("/proc/self/comm", O_RDONLY | O_CLOEXEC);
		if (fd >= 0) {
			n = read(fd, comm, sizeof(comm) - 1);
			close(fd);
		}
		if (n <= 0)
			snprintf(comm, sizeof(comm), "?");
		else
			comm[strcspn(comm, "\n")] = 0;
	}
	snprintf(name, (size_t)len, "%s", comm);
	return (int)rtapi_getpid();	/* cached: this runs at every HAL lock */
}

/* A zombie (exited, not yet reaped) still answers kill(pid, 0); its parent may never
 * reap it (a userspace component that halcmd started is reparented to init, and some
 * init processes of containers never reap), so the state in /proc decides. The kernel
 * flavor's check treats an exiting task the same way (hal_lib_kmod.c). */
static bool pid_is_zombie(int pid)
{
	char path[32], buf[512], *close_paren;
	ssize_t n;
	int fd;

	snprintf(path, sizeof(path), "/proc/%d/stat", pid);
	fd = open(path, O_RDONLY | O_CLOEXEC);
	if (fd < 0)
		return false;	/* no /proc: kill() alone decides */
	n = read(fd, buf, sizeof(buf) - 1);
	close(fd);
	if (n <= 0)
		return false;
	buf[n] = 0;
	/* "PID (COMM) S ...": COMM may hold spaces and parentheses, the last ')' ends it */
	close_paren = strrchr(buf, ')');
	if (!close_paren || close_paren[1] != ' ')
		return false;
	return close_paren[2] == 'Z' || close_paren[2] == 'X';
}

bool hal_os_pid_alive(int pid)
{
	if (pid <= 0)
		return false;
	if (kill((pid_t)pid, 0) != 0 && errno != EPERM)
		return false;
	return !pid_is_zombie(pid);
}

/* rtapi_app unloads a module only after hal_exit_module_comps() took its functions
 * off every thread and quiesced them, and dlclose() happens in the same thread that
 * did that, so there is no reference to keep here (the kernel flavor's rmmod is the
 * one that needs them: hal_lib_kmod.c). */
int hal_os_code_get(rtapi_u64 module)
{
	(void)module;
	return 0;
}

void hal_os_code_put(rtapi_u64 module)
{
	(void)module;
}
