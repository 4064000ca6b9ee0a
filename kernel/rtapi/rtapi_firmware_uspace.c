/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_firmware_uspace.c - rtapi_request_firmware (rtapi_firmware.h) in the simulated
 * flavor: HAL_FIRMWARE_PATH's directories, then the kernel's search path (its
 * firmware_class.path parameter as sysfs shows it, then /lib/firmware/updates/<release>,
 * /lib/firmware/updates, /lib/firmware/<release>, /lib/firmware), first file wins. */
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/utsname.h>
#include <unistd.h>
#include "rtapi.h"
#include "rtapi_firmware.h"

#define FW_MAX_SIZE (64L << 20)	/* no FPGA image is larger; a bound on a bad file */

static int name_ok(const char *name)
{
	const char *p = name;

	if (!name || !*name || *name == '/')
		return 0;
	for (;;) {
		if (p[0] == '.' && p[1] == '.' && (p[2] == '/' || !p[2]))
			return 0;
		p = strchr(p, '/');
		if (!p)
			return 1;
		p++;
	}
}

/* Reads dir/name: 0 with the image, -ENOENT when absent, -errno after a message. */
static int read_image(const char *dir, const char *name, struct rtapi_firmware *fw)
{
	char path[1024];
	struct stat st;
	unsigned char *buf;
	long got = 0;
	int fd;

	if (!*dir || snprintf(path, sizeof(path), "%s/%s", dir, name) >= (int)sizeof(path))
		return -ENOENT;
	fd = open(path, O_RDONLY | O_CLOEXEC);
	if (fd < 0)
		return -ENOENT;
	if (fstat(fd, &st) < 0 || !S_ISREG(st.st_mode) || st.st_size > FW_MAX_SIZE) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: firmware %s is not a regular file of "
				"at most %ld bytes\n", path, FW_MAX_SIZE);
		close(fd);
		return -EINVAL;
	}
	buf = malloc(st.st_size ? st.st_size : 1);
	if (!buf) {
		close(fd);
		return -ENOMEM;
	}
	while (got < st.st_size) {
		ssize_t n = read(fd, buf + got, st.st_size - got);

		if (n <= 0) {
			rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: firmware %s: read error\n", path);
			free(buf);
			close(fd);
			return -EIO;
		}
		got += n;
	}
	close(fd);
	fw->size = got;
	fw->data = buf;
	fw->priv = buf;
	return 0;
}

/* firmware_class.path as the running kernel has it, "" when unset or unreadable. */
static void kernel_custom_path(char *buf, size_t len)
{
	FILE *f = fopen("/sys/module/firmware_class/parameters/path", "r");

	buf[0] = 0;
	if (!f)
		return;
	if (!fgets(buf, (int)len, f))
		buf[0] = 0;
	fclose(f);
	buf[strcspn(buf, "\n")] = 0;
}

int rtapi_request_firmware(const struct rtapi_firmware **fw, const char *name)
{
	struct rtapi_firmware *img;
	const char *env = getenv("HAL_FIRMWARE_PATH");
	char dirs[5][256];
	struct utsname u;
	int i, rc = -ENOENT;

	if (!name_ok(name)) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: firmware name '%s' must be relative to "
				"/lib/firmware, without '..'\n", name ? name : "");
		return -EINVAL;
	}
	img = malloc(sizeof(*img));
	if (!img)
		return -ENOMEM;
	if (env) {
		char *list = strdup(env), *save = 0, *d;

		for (d = list ? strtok_r(list, ":", &save) : 0; d && rc == -ENOENT;
		     d = strtok_r(0, ":", &save))
			rc = read_image(d, name, img);
		free(list);
	}
	if (uname(&u) < 0)
		u.release[0] = 0;
	kernel_custom_path(dirs[0], sizeof(dirs[0]));
	snprintf(dirs[1], sizeof(dirs[1]), "/lib/firmware/updates/%s", u.release);
	snprintf(dirs[2], sizeof(dirs[2]), "/lib/firmware/updates");
	snprintf(dirs[3], sizeof(dirs[3]), "/lib/firmware/%s", u.release);
	snprintf(dirs[4], sizeof(dirs[4]), "/lib/firmware");
	for (i = 0; i < 5 && rc == -ENOENT; i++)
		rc = read_image(dirs[i], name, img);
	if (rc) {
		free(img);
		return rc;
	}
	*fw = img;
	return 0;
}

void rtapi_release_firmware(const struct rtapi_firmware *fw)
{
	if (!fw)
		return;
	free(fw->priv);
	free((void *)fw);
}
