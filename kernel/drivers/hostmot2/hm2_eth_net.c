/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_eth_net.c - hm2_eth's UDP socket, on rtapi_udp.h: POSIX sockets in rtapi_app
 * (simulated flavor); in the kernel flavor rtapi refuses every socket with its
 * reason (kernel/rtapi/rtapi_udp_kmod.c), and hm2_eth with it (hm2_eth(9)). */
#include "rtapi.h"
#include "rtapi_udp.h"
#include "hm2_eth_net.h"

int hm2_eth_net_open(const char *ip, int port)
{
	int rc = rtapi_udp_open(ip, port);

	if (rc == -EINVAL)
		rtapi_print_msg(RTAPI_MSG_ERR, "hm2_eth: board_ip=%s: not an IPv4 address "
				"(a.b.c.d or a.b.c.d:port)\n", ip);
	else if (rc == -EOPNOTSUPP)
		rtapi_print_msg(RTAPI_MSG_ERR, "hm2_eth: refused: no realtime UDP in this flavor "
				"(hm2_eth(9)); use the simulated flavor\n");
	return rc;
}

void hm2_eth_net_close(int handle)
{
	rtapi_udp_close(handle);
}

int hm2_eth_net_send(int handle, const void *buf, int len)
{
	return rtapi_udp_send(handle, buf, len);
}

int hm2_eth_net_recv(int handle, void *buf, int cap, long long deadline_ns)
{
	return rtapi_udp_recv(handle, buf, cap, deadline_ns);
}
