/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_udp.h - connected UDP sockets for realtime drivers of network I/O boards
 * (hm2_eth). Simulated flavor: POSIX sockets (rtapi_udp_uspace.c). The kernel flavor
 * has no realtime-safe UDP: rtapi_udp_open refuses with -EOPNOTSUPP after a message
 * giving the reason (rtapi_udp_kmod.c), and its drivers fail to load. open/close are init code;
 * send/recv never block longer than asked and may run in a realtime thread. */
#ifndef RTAPI_UDP_H
#define RTAPI_UDP_H

#include "rtapi.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A socket connected to ip (dotted quad) : port. The handle (>= 0), or -errno:
 * -EINVAL for an address that is not a dotted quad (no message), another -errno
 * after a message naming the address (-EOPNOTSUPP: the kernel flavor's refusal). */
int rtapi_udp_open(const char *ip, int port);
void rtapi_udp_close(int handle);
/* Sends one datagram: 0, or -errno (-EAGAIN when the socket buffer is full). */
int rtapi_udp_send(int handle, const void *buf, int len);
/* Receives one datagram into buf (at most cap bytes), waiting until the absolute
 * time deadline_ns (rtapi_get_time's clock) at the latest: its length, -ETIMEDOUT,
 * or another -errno (-ECONNREFUSED: nothing listens at the port). */
int rtapi_udp_recv(int handle, void *buf, int cap, long long deadline_ns);

#ifdef __cplusplus
}
#endif
#endif /* RTAPI_UDP_H */
