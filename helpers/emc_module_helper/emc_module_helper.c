/* SPDX-License-Identifier: GPL-2.0-or-later */
/* emc_module_helper - lets halcmd load and unload the kernel flavor's realtime
 * modules for the members of group hal. Installed 4750 root:hal (setuid root, run
 * only by root and hal), so it trusts nothing from its caller:
 *   - first of all, before it reads an argument, it keeps only CAP_SYS_MODULE and
 *     becomes its caller (real uid/gid, no supplementary groups, no new privileges,
 *     the default personality);
 *   - only whitelisted module names, only from the compiled-in directory
 *     <EMC_MODULE_DIR>/<kernel release><EMC_MODULE_SUBDIR>/NAME.ko, opened without following links
 *     relative to directory descriptors and used only if root owns it and nobody
 *     else may write it; the release is uname's, checked to be one path component;
 *   - one token per argument: "param" or "param=value", param a parameter the module
 *     declares (its .modinfo parmtype), value printable ASCII without '"'. The helper
 *     quotes a value holding blanks itself ("0x378 out" becomes param="0x378 out"),
 *     so one argument is always one parameter: the kernel splits the string at
 *     unquoted blanks. A value already in double quotes (halcmd's form) is taken as
 *     the same value without them.
 * It calls finit_module(2)/delete_module(2) itself rather than running insmod:
 * nothing else is executed, and some insmod (busybox) retries a failed finit_module
 * with init_module, which runs a failing rtapi_app_main twice.
 *   emc_module_helper insert NAME [PARAM[=VALUE]...]
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
#include <sys/personality.h>
#include <sys/prctl.h>
#include <sys/stat.h>
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
#define MAX_KO (64L << 20)	/* larger .ko files are not ours */

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

/* One argument, "param" or "param=value": a parameter name of a-z 0-9 _ (never an
 * insmod option such as -f), then printable ASCII without '"' (the kernel's quoting
 * has no escapes), so nothing reaches the kernel log unescaped. A value wholly in
 * double quotes is unwrapped first. Writes the argument as the kernel must get it
 * to 'out' (quoted when it holds a blank), or returns why it is refused. */
static const char *arg_problem(const char *arg, char *out, size_t out_size)
{
	size_t i, n = strlen(arg), vlen;
	const char *value;

	if (n > MAX_ARG)
		return "longer than 1024 characters";
	for (i = 0; i < n && arg[i] != '='; i++)
		if (!((arg[i] >= 'a' && arg[i] <= 'z') || (arg[i] >= '0' && arg[i] <= '9') ||
		      arg[i] == '_'))
			return "not of the form param=value (param: a-z 0-9 _)";
	if (i == 0)
		return "not of the form param=value (param: a-z 0-9 _)";
	if (i == n) {		/* a flag without a value */
		snprintf(out, out_size, "%s", arg);
		return NULL;
	}
	value = arg + i + 1;
	vlen = n - i - 1;
	if (vlen >= 2 && value[0] == '"' && value[vlen - 1] == '"') {
		value++;
		vlen -= 2;
	}
	for (n = 0; n < vlen; n++) {
		if ((unsigned char)value[n] < 0x20 || (unsigned char)value[n] > 0x7e)
			return "contains a non-printable character";
		if (value[n] == '"')
			return "contains '\"' (a value may not hold double quotes)";
	}
	if (memchr(value, ' ', vlen) || vlen == 0)
		snprintf(out, out_size, "%.*s\"%.*s\"", (int)(i + 1), arg, (int)vlen, value);
	else
		snprintf(out, out_size, "%.*s%.*s", (int)(i + 1), arg, (int)vlen, value);
	return NULL;
}

/* Is 'v' (vlen bytes) a value of the kernel parameter type 'type' ("int", "charp",
 * "array of int", ...)? Strings take any value arg_problem passed; numbers are
 * decimal or 0x hex with an optional sign, comma-separated in arrays; bool is a word. */
static int value_fits(const char *type, const char *v, size_t vlen)
{
	int array = strncmp(type, "array of ", 9) == 0;
	const char *t = array ? type + 9 : type;
	size_t i = 0, start;

	if (strcmp(t, "charp") == 0 || strcmp(t, "string") == 0)
		return 1;
	if (strcmp(t, "bool") == 0 || strcmp(t, "invbool") == 0) {
		for (; i < vlen; i++)
			if (!((v[i] >= 'a' && v[i] <= 'z') || (v[i] >= 'A' && v[i] <= 'Z') ||
			      (v[i] >= '0' && v[i] <= '9') || (array && v[i] == ',')))
				return 0;
		return 1;
	}
	for (;;) {		/* one number, then ',' in an array */
		if (i < vlen && (v[i] == '-' || v[i] == '+'))
			i++;
		if (i + 1 < vlen && v[i] == '0' && (v[i + 1] == 'x' || v[i + 1] == 'X'))
			i += 2;
		start = i;
		while (i < vlen && ((v[i] >= '0' && v[i] <= '9') || (v[i] >= 'a' && v[i] <= 'f') ||
				    (v[i] >= 'A' && v[i] <= 'F')))
			i++;
		if (i == start)
			return 0;
		if (i == vlen)
			return 1;
		if (!array || v[i] != ',')
			return 0;
		i++;
	}
}

/* The type the module declares for parameter 'param' (arg up to '='), or NULL. Its
 * .modinfo holds "parmtype=NAME:TYPE" for each; the kernel itself also takes a few
 * names for every module (dyndbg, async_probe), which no caller may reach here. */
static const char *declared(const char *ko, size_t ko_len, const char *arg)
{
	char key[64 + 12];
	size_t plen = strcspn(arg, "="), klen;
	const char *p = ko, *end = ko + ko_len;

	if (plen > 64)
		return 0;
	klen = (size_t)snprintf(key, sizeof(key), "parmtype=%.*s:", (int)plen, arg);
	while (p + klen <= end && (p = memmem(p, (size_t)(end - p), key, klen)) != NULL) {
		if ((p == ko || p[-1] == '\0') && memchr(p + klen, '\0', (size_t)(end - p - klen)))
			return p + klen;
		p++;
	}
	return NULL;
}

/* Only CAP_SYS_MODULE, as the caller: called first, before any argument is read.
 * The bounding set goes first (that needs CAP_SETPCAP), then the ids (kept
 * capabilities survive through PR_SET_KEEPCAPS), then the capability sets. No new
 * privileges from here on, and the default personality (UNAME26 would change what
 * uname reports, and so the module path). Without privileges (a test build run by a
 * user) only the personality and no-new-privileges parts apply. */
static int drop_privileges(void)
{
	struct __user_cap_header_struct hdr = { .version = _LINUX_CAPABILITY_VERSION_3 };
	struct __user_cap_data_struct data[2];
	uid_t uid = getuid();
	gid_t gid = getgid();
	int cap;

	if (personality(PER_LINUX) < 0) {
		perror("emc_module_helper: cannot reset the personality");
		return -1;
	}
	if (geteuid() == 0) {
		for (cap = 0; prctl(PR_CAPBSET_READ, cap, 0, 0, 0) >= 0; cap++)
			if (cap != CAP_SYS_MODULE && prctl(PR_CAPBSET_DROP, cap, 0, 0, 0)) {
				perror("emc_module_helper: cannot drop capabilities");
				return -1;
			}
		if (prctl(PR_SET_KEEPCAPS, 1, 0, 0, 0) || setgroups(0, NULL) ||
		    setresgid(gid, gid, gid) || setresuid(uid, uid, uid)) {
			perror("emc_module_helper: cannot set ids");
			return -1;
		}
		memset(data, 0, sizeof(data));
		data[0].effective = data[0].permitted = 1u << CAP_SYS_MODULE;
		if (syscall(SYS_capset, &hdr, data) || prctl(PR_SET_KEEPCAPS, 0, 0, 0, 0)) {
			perror("emc_module_helper: cannot keep CAP_SYS_MODULE alone");
			return -1;
		}
	}
	if (prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0)) {
		perror("emc_module_helper: cannot set no_new_privs");
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

/* The owner every file on the module path must have: root (the test build: its user). */
static uid_t trusted_owner(void)
{
#ifdef EMC_FAKE_CALLS
	return getuid();
#else
	return 0;
#endif
}

/* openat without following a link, used only if it is of 'type', owned by the
 * trusted owner and writable by nobody else; -1 (after a message) otherwise. */
static int open_trusted(int dirfd, const char *name, int flags, mode_t type, const char *shown)
{
	struct stat st;
	int fd = openat(dirfd, name, flags | O_NOFOLLOW | O_CLOEXEC);

	if (fd < 0) {
		fprintf(stderr, "emc_module_helper: %s: %s%s\n", shown, strerror(errno),
			errno == ENOENT ? " (is the kernel flavor installed for this kernel?)" :
			errno == ELOOP ? " (a symbolic link)" : "");
		return -1;
	}
	if (fstat(fd, &st) || (st.st_mode & S_IFMT) != type || st.st_uid != trusted_owner() ||
	    (st.st_mode & 022)) {
		fprintf(stderr, "emc_module_helper: %s: not a %s owned by %s and writable only by it\n",
			shown, type == S_IFDIR ? "directory" : "file",
			trusted_owner() == 0 ? "root" : "the test user");
		close(fd);
		return -1;
	}
	return fd;
}

static int insert(const char *name, int fd, const char *path, const char *params)
{
	int rc;

#ifdef EMC_FAKE_CALLS
	rc = fake_call("finit_module", path, params);
#else
	rc = (int)syscall(SYS_finit_module, fd, params, 0);
#endif
#ifdef EMC_FAKE_CALLS
	(void)fd;
#else
	(void)path;
#endif
	if (rc != 0) {
		fprintf(stderr, "emc_module_helper: cannot insert %s: %s\n", name, strerror(errno));
		return 1;
	}
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
	fprintf(stderr, "usage: emc_module_helper insert NAME [PARAM[=VALUE]...]\n"
			"       emc_module_helper remove NAME\n");
	return 2;
}

/* Reads the whole module (at most MAX_KO bytes) for its parameter names. */
static char *read_ko(int fd, size_t *len)
{
	struct stat st;
	char *buf;
	size_t got = 0;
	ssize_t n;

	if (fstat(fd, &st) || st.st_size <= 0 || st.st_size > MAX_KO)
		return NULL;
	buf = malloc((size_t)st.st_size);
	if (!buf)
		return NULL;
	while (got < (size_t)st.st_size && (n = pread(fd, buf + got, (size_t)st.st_size - got,
						     (off_t)got)) > 0)
		got += (size_t)n;
	*len = got;
	return buf;
}

/* The kernel release as one path component ("6.1.0-56-amd64"). */
static int release_ok(const char *r)
{
	size_t i;

	if (!r[0] || strcmp(r, ".") == 0 || strcmp(r, "..") == 0)
		return 0;
	for (i = 0; r[i]; i++)
		if (!((r[i] >= 'a' && r[i] <= 'z') || (r[i] >= 'A' && r[i] <= 'Z') ||
		      (r[i] >= '0' && r[i] <= '9') || strchr("._+-~", r[i])))
			return 0;
	return 1;
}

/* Walks the compiled-in EMC_MODULE_SUBDIR ("/updates/dkms") below the release
 * directory DIRFD, each component opened as open_trusted() opens the others. Takes
 * DIRFD over; returns the innermost directory or -1 (refused, message printed). */
static int open_subdir(int dirfd, const char *shown)
{
	char sub[] = EMC_MODULE_SUBDIR, *part, *save = NULL;
	int next;

	for (part = strtok_r(sub, "/", &save); part && dirfd >= 0;
	     part = strtok_r(NULL, "/", &save)) {
		next = open_trusted(dirfd, part, O_RDONLY | O_DIRECTORY, S_IFDIR, shown);
		close(dirfd);
		dirfd = next;
	}
	return dirfd;
}

int main(int argc, char **argv)
{
	static char params[MAX_ARGS * (MAX_ARG + 4) + 1];
	char path[512], file[MAX_NAME + 4], one[MAX_ARG + 4];
	struct utsname u;
	const char *name;
	char *ko;
	size_t len = 0, ko_len = 0;
	int i, insert_verb, basefd, relfd, fd, rc;

	if (drop_privileges())
		return 2;
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
		const char *why = arg_problem(argv[i], one, sizeof(one));

		if (why)
			return refuse(name, why);
	}
	if (!insert_verb)
		return remove_module(name);
	if (uname(&u) || !release_ok(u.release))
		return refuse(name, "cannot read the kernel release");
	snprintf(path, sizeof(path), "%s/%s%s/%s.ko", EMC_MODULE_DIR, u.release, EMC_MODULE_SUBDIR,
		 name);
	snprintf(file, sizeof(file), "%s.ko", name);
	basefd = open(EMC_MODULE_DIR, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
	if (basefd < 0)
		return refuse(EMC_MODULE_DIR, strerror(errno));
	relfd = open_trusted(basefd, u.release, O_RDONLY | O_DIRECTORY, S_IFDIR, path);
	close(basefd);
	relfd = open_subdir(relfd, path);
	if (relfd < 0)
		return 2;
	fd = open_trusted(relfd, file, O_RDONLY, S_IFREG, path);
	close(relfd);
	if (fd < 0)
		return 2;
	ko = read_ko(fd, &ko_len);
	if (!ko) {
		close(fd);
		return refuse(path, "cannot read it (empty, or larger than 64 MiB)");
	}
	/* one token per argument, each a parameter of this module, joined by blanks */
	for (i = 3; i < argc; i++) {
		size_t n;

		const char *type = declared(ko, ko_len, argv[i]), *v;
		int plen = (int)strcspn(argv[i], "=");

		arg_problem(argv[i], one, sizeof(one));
		if (!type) {
			free(ko);
			close(fd);
			fprintf(stderr, "emc_module_helper: %s: '%.*s' is not a parameter of this module\n",
				name, plen, argv[i]);
			return 2;
		}
		/* the value as the kernel will see it: after '=', without our quotes */
		v = strchr(one, '=');
		n = v ? strlen(v + 1) : 0;
		if (v && n >= 2 && v[1] == '"') {
			v++;
			n -= 2;
		}
		if (v && !value_fits(type, v + 1, n)) {
			/* type points into ko: print before freeing it */
			fprintf(stderr, "emc_module_helper: %s: %.*s: '%.*s' is not a value of type %s\n",
				name, plen, argv[i], (int)n, v + 1, type);
			free(ko);
			close(fd);
			return 2;
		}
		n = strlen(one);
		memcpy(params + len, one, n);
		len += n;
		if (i + 1 < argc)
			params[len++] = ' ';
	}
	params[len] = '\0';
	free(ko);
	rc = insert(name, fd, path, params);
	close(fd);
	return rc;
}
