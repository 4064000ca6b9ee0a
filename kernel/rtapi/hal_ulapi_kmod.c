/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hal_ulapi_kmod.c - a userspace program's side of the kernel flavor's HAL segment
 * (docs/kernel-security.md): /dev/rtapi maps the record heap read-only and the value
 * area writable, at the same offsets as in the kernel, and carries configuration
 * requests and the HAL mutex to hal_lib.ko as ioctls. ULAPI only. */
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>
#include "hal_internal.h"
#include "rtapi_shmem_kmod.h"

static int dev_fd = -1;
static void *map_base;
static size_t map_len;

int hal_kmod_map(char **base)
{
	struct rtapi_shmem_query q = { .key = HAL_KEY };
	struct hal_dev_info info;
	long page = sysconf(_SC_PAGESIZE);
	void *ro, *rw;
	int err;

	int tries;

	/* Just after loadrt loaded rtapi.ko, udev may not have given the node its group
	 * yet (firmware/udev/): wait for it a little. */
	for (tries = 0; (dev_fd = open("/dev/" RTAPI_DEVICE_NAME, O_RDWR | O_CLOEXEC)) < 0 &&
			(errno == EACCES || errno == ENOENT) && tries < 40; tries++)
		usleep(50000);
	if (dev_fd < 0) {
		err = errno;
		rtapi_print_msg(RTAPI_MSG_ERR, "HAL: cannot open /dev/%s: %s%s\n", RTAPI_DEVICE_NAME,
				strerror(err), err == EACCES ? " (HAL users must be in group 'hal')" : "");
		return -err;
	}
	if (ioctl(dev_fd, HAL_IOC_INFO, &info) < 0 || ioctl(dev_fd, RTAPI_IOC_SHMEM_LOOKUP, &q) < 0) {
		err = errno;
		rtapi_print_msg(RTAPI_MSG_ERR, "HAL: no HAL segment in the kernel (%s): is hal_lib.ko "
				"loaded?\n", strerror(err));
		goto undo_open;
	}
	if (info.layout_version != HAL_LAYOUT_VERSION) {
		rtapi_print_msg(RTAPI_MSG_ERR,
				"HAL segment has layout version %u, this program expects %u: "
				"stop the running HAL (halrun -U) first\n",
				(unsigned)info.layout_version, (unsigned)HAL_LAYOUT_VERSION);
		err = EINVAL;
		goto undo_open;
	}
	/* One reservation, then the two parts at their offsets inside it. */
	map_len = info.size;
	map_base = mmap(NULL, map_len, PROT_NONE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
	if (map_base == MAP_FAILED) {
		err = errno;
		goto undo_open;
	}
	ro = mmap(map_base, info.val_start, PROT_READ, MAP_SHARED | MAP_FIXED, dev_fd,
		  (off_t)RTAPI_SHMEM_PGOFF(q.id, 0) * page);
	rw = ro == MAP_FAILED ? MAP_FAILED :
	     mmap((char *)map_base + info.val_start, info.size - info.val_start,
		  PROT_READ | PROT_WRITE, MAP_SHARED | MAP_FIXED, dev_fd,
		  (off_t)RTAPI_SHMEM_PGOFF(q.id, info.val_start / page) * page);
	if (rw == MAP_FAILED) {
		err = errno;
		rtapi_print_msg(RTAPI_MSG_ERR, "HAL: cannot map /dev/%s: %s\n", RTAPI_DEVICE_NAME,
				strerror(err));
		munmap(map_base, map_len);
		goto undo_open;
	}
	*base = map_base;
	return 0;

undo_open:
	close(dev_fd);
	dev_fd = -1;
	return -err;
}

void hal_kmod_unmap(void)
{
	if (map_base)
		munmap(map_base, map_len);
	map_base = 0;
	if (dev_fd >= 0)
		close(dev_fd);	/* gives the HAL mutex back if we still held it */
	dev_fd = -1;
}

int hal_kmod_request(struct hal_req *r)
{
	int rc = ioctl(dev_fd, HAL_IOC_REQUEST, r);

	if (rc < 0) {
		rc = -errno;
		rtapi_print_msg(RTAPI_MSG_ERR, "HAL: request %u refused by the kernel: %s\n",
				(unsigned)r->op, strerror(errno));
		return rc;
	}
	r->msg[sizeof(r->msg) - 1] = 0;
	if (r->msg[0])
		rtapi_print_msg(RTAPI_MSG_ERR, "%s", r->msg);
	return r->result;
}

void hal_kmod_lock(bool take)
{
	/* EINTR: a signal while waiting for another holder; keep waiting, as hal_lock does. */
	while (ioctl(dev_fd, take ? HAL_IOC_LOCK : HAL_IOC_UNLOCK) < 0 && errno == EINTR)
		;
}

int hal_kmod_recover(void)
{
	return ioctl(dev_fd, HAL_IOC_RECOVER) < 0 ? -errno : 0;
}
