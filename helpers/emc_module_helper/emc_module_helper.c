/* SPDX-License-Identifier: GPL-2.0-or-later */
/* emc_module_helper - lets halcmd load and unload the kernel flavor's realtime
 * modules without being root. Installed setuid root, so it trusts nothing from its
 * caller: only whitelisted module names, only from the compiled-in directory
 * (<EMC_MODULE_DIR>/<kernel release><EMC_MODULE_SUBDIR>/NAME.ko), only "param[=value]" arguments of
 * printable characters, and no capability but CAP_SYS_MODULE. It calls
 * finit_module(2)/delete_module(2) itself rather than running insmod: nothing else
 * is executed, and some insmod (busybox) retries a failed finit_module with
 * init_module, which runs a failing rtapi_app_main twice.
 *   emc_module_helper insert NAME [PARAM[=VALUE]...]   (joined with blanks, as insmod)
 *   emc_module_helper remove NAME
 * Exit status: 0 done, 1 the kernel refused ("... : <strerror>" on stderr), 2 refused. */
#define _GNU_SOURCE
#include <errno.h>
#include <grp.h>
#include <linux/capability.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <sys/utsname.h>
#include <unistd.h>
#include "emc_module_whitelist.h"	/* EMC_MODULE_WHITELIST: "name", ... (generated) */

#ifndef EMC_MODULE_DIR
#error "EMC_MODULE_DIR (module base directory) must be compiled in"
#endif
#ifndef EMC_MODULE_SUBDIR	/* "/updates/dkms" for the modules DKMS installs */
#define EMC_MODULE_SUBDIR ""
#endif
/* EMC_FAKE_CALLS (the unit tests' build only): instead of the two system calls,
 * append them to this file; they fail with EINVAL while "<file>.fail" exists. */

#define MAX_NAME 31	/* RTAPI_NAME_LEN */
#define MAX_ARG 1024
#define MAX_ARGS 64

static const char *const whitelist[] = { EMC_MODULE_WHITELIST };

static int refuse(const char *what, const char *why)
{
	fprintf(stderr, "emc_module_helper: %s: %s\n", what, why);
	return 2;
}

static int name_ok(const char *name)
{
	size_t i, n = strlen(name);

	if (n == 0 || n > MAX_NAME)
		return 0;
	for (i = 0; i < n; i++)
		if (!((name[i] >= 'a' && name[i] <= 'z') || (name[i] >= '0' && name[i] <= '9') ||
		      name[i] == '_'))
			return 0;
	return 1;
}

static int whitelisted(const char *name)
{
	size_t i;

	for (i = 0; i < sizeof(whitelist) / sizeof(whitelist[0]); i++)
		if (strcmp(whitelist[i], name) == 0)
			return 1;
	return 0;
}

/* "param" or "param=value": a lowercase parameter name (never an insmod option such
 * as -f), then printable ASCII only, so nothing reaches the kernel log unescaped. */
static const char *arg_problem(const char *arg)
{
	size_t i, n = strlen(arg);

	if (n > MAX_ARG)
		return "longer than 1024 characters";
	for (i = 0; i < n && arg[i] != '='; i++)
		if (!((arg[i] >= 'a' && arg[i] <= 'z') || (arg[i] >= '0' && arg[i] <= '9') ||
		      arg[i] == '_'))
			return "not of the form param=value (param: a-z 0-9 _)";
	if (i == 0)
		return "not of the form param=value (param: a-z 0-9 _)";
	for (; i < n; i++)
		if ((unsigned char)arg[i] < 0x20 || (unsigned char)arg[i] > 0x7e)
			return "contains a non-printable character";
	return NULL;
}

/* Become root for real (a setuid binary has only the effective uid), keep no
 * supplementary groups, and drop every capability but CAP_SYS_MODULE from the
 * bounding set, so a bug here can do nothing else. Without privileges (a test build
 * run by a user) this is skipped and the kernel reports the permission error. */
static int drop_privileges(void)
{
	int cap;

	if (geteuid() != 0)
		return 0;
	if (setgroups(0, NULL) || setresgid(0, 0, 0) || setresuid(0, 0, 0)) {
		perror("emc_module_helper: cannot set ids");
		return -1;
	}
	for (cap = 0; prctl(PR_CAPBSET_READ, cap, 0, 0, 0) >= 0; cap++)
		if (cap != CAP_SYS_MODULE && prctl(PR_CAPBSET_DROP, cap, 0, 0, 0) && errno != EINVAL) {
			perror("emc_module_helper: cannot drop capabilities");
			return -1;
		}
	return 0;
}

#ifdef EMC_FAKE_CALLS
static int fake_call(const char *what, const char *arg1, const char *arg2)
{
	FILE *f = fopen(EMC_FAKE_CALLS, "a");

	if (f) {
		fprintf(f, "%s %s%s%s\n", what, arg1, arg2 ? " " : "", arg2 ? arg2 : "");
		fclose(f);
	}
	if (access(EMC_FAKE_CALLS ".fail", F_OK) == 0) {
		errno = EINVAL;
		return -1;
	}
	return 0;
}
#endif

static int insert(const char *name, const char *path, const char *params)
{
	int fd = open(path, O_RDONLY | O_CLOEXEC), rc;

	if (fd < 0) {
		fprintf(stderr, "emc_module_helper: cannot open %s: %s\n", path, strerror(errno));
		return 1;
	}
#ifdef EMC_FAKE_CALLS
	rc = fake_call("finit_module", path, params);
#else
	rc = (int)syscall(SYS_finit_module, fd, params, 0);
#endif
	if (rc != 0) {
		int err = errno;

		close(fd);
		fprintf(stderr, "emc_module_helper: cannot insert %s: %s\n", name, strerror(err));
		return 1;
	}
	close(fd);
	return 0;
}

static int remove_module(const char *name)
{
	int rc;

#ifdef EMC_FAKE_CALLS
	rc = fake_call("delete_module", name, NULL);
#else
	rc = (int)syscall(SYS_delete_module, name, O_NONBLOCK);	/* never wait for users */
#endif
	if (rc != 0) {
		fprintf(stderr, "emc_module_helper: cannot remove %s: %s\n", name, strerror(errno));
		return 1;
	}
	return 0;
}

static int usage(void)
{
	fprintf(stderr, "usage: emc_module_helper insert NAME [PARAM=VALUE...]\n"
			"       emc_module_helper remove NAME\n");
	return 2;
}

int main(int argc, char **argv)
{
	static char path[4096];
	static char params[MAX_ARGS * (MAX_ARG + 1) + 1];
	struct utsname u;
	const char *name;
	size_t len = 0;
	int i, insert_verb;

	if (argc < 3)
		return usage();
	if (strcmp(argv[1], "insert") == 0)
		insert_verb = 1;
	else if (strcmp(argv[1], "remove") == 0)
		insert_verb = 0;
	else
		return usage();
	name = argv[2];
	if (!name_ok(name))
		return refuse("module name", "must be 1 to 31 characters of a-z 0-9 _");
	if (!whitelisted(name))
		return refuse(name, "not a HAL realtime module");
	if (!insert_verb && argc > 3)
		return refuse(name, "remove takes no arguments");
	if (argc - 3 > MAX_ARGS)
		return refuse(name, "more than 64 arguments");
	for (i = 3; i < argc; i++) {
		const char *why = arg_problem(argv[i]);

		if (why)
			return refuse(name, why);
	}
	if (drop_privileges())
		return 2;
	if (!insert_verb)
		return remove_module(name);
	if (uname(&u))
		return refuse(name, "cannot read the kernel release");
	if (snprintf(path, sizeof(path), "%s/%s%s/%s.ko", EMC_MODULE_DIR, u.release,
		     EMC_MODULE_SUBDIR, name) >=
	    (int)sizeof(path))
		return refuse(name, "module path too long");
	if (access(path, R_OK))
		return refuse(path, "no such module for this kernel (is the kernel flavor installed?)");
	/* as insmod does: the arguments joined by blanks (bounded by the checks above) */
	for (i = 3; i < argc; i++) {
		size_t n = strlen(argv[i]);

		memcpy(params + len, argv[i], n);
		len += n;
		if (i + 1 < argc)
			params[len++] = ' ';
	}
	params[len] = '\0';
	return insert(name, path, params);
}
