/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_udp_uspace.c - rtapi_udp.h on POSIX sockets (simulated flavor). */
#include <arpa/inet.h>
#include <errno.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <string.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>
#include "rtapi.h"
#include "rtapi_udp.h"

int rtapi_udp_open(const char *ip, int port)
{
	struct sockaddr_in sa;
	int fd, e;

	memset(&sa, 0, sizeof(sa));
	sa.sin_family = AF_INET;
	sa.sin_port = htons((unsigned short)port);
	if (port <= 0 || port > 65535 || inet_pton(AF_INET, ip, &sa.sin_addr) != 1)
		return -EINVAL;
	fd = socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
	if (fd < 0) {
		e = errno;
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: UDP socket for %s:%d: %s\n", ip, port, strerror(e));
		return -e;
	}
	if (connect(fd, (struct sockaddr *)&sa, sizeof(sa)) < 0) {
		e = errno;
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: UDP connect to %s:%d: %s\n", ip, port, strerror(e));
		close(fd);
		return -e;
	}
	return fd;
}

void rtapi_udp_close(int handle)
{
	if (handle >= 0)
		close(handle);
}

int rtapi_udp_send(int handle, const void *buf, int len)
{
	ssize_t n = send(handle, buf, (size_t)len, MSG_DONTWAIT);

	if (n < 0)
		return -errno;
	return n == len ? 0 : -EMSGSIZE;
}

int rtapi_udp_recv(int handle, void *buf, int cap, long long deadline_ns)
{
	for (;;) {
		struct pollfd p = { .fd = handle, .events = POLLIN };
		long long left = deadline_ns - rtapi_get_time();
		struct timespec ts;
		ssize_t n = recv(handle, buf, (size_t)cap, MSG_DONTWAIT);

		if (n >= 0)
			return (int)n;
		if (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)
			return -errno;
		if (left <= 0)
			return -ETIMEDOUT;
		ts.tv_sec = left / 1000000000LL;
		ts.tv_nsec = left % 1000000000LL;
		if (ppoll(&p, 1, &ts, NULL) < 0 && errno != EINTR)
			return -errno;
	}
}
