/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hal_os_uspace.c - what the HAL core asks of the operating system in userspace
 * (rtapi_app and tools): who we are and whether a process still lives, for the
 * HAL mutex's holder record (hal_lock.c). The kernel flavor's are in hal_lib_kmod.c. */
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>
#include "hal_internal.h"

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
	return (int)getpid();
}

bool hal_os_pid_alive(int pid)
{
	return kill((pid_t)pid, 0) == 0 || errno == EPERM;
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
