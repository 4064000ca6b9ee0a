/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_eth_net.c - hm2_eth's UDP socket. Simulated flavor: rtapi_udp (POSIX sockets
 * in rtapi_app). Kernel flavor: none, and hm2_eth refuses to load, because a kernel
 * UDP socket cannot be used safely from a realtime thread here:
 *  - hm2 read/write run inside the thread's FPU section (kernel_fpu_begin), where
 *    preemption is off, and kernel_sendmsg/kernel_recvmsg may sleep (socket lock,
 *    skb allocation): sleeping there is a bug ("scheduling while atomic");
 *  - the reply is delivered by the network stack's softirq (on PREEMPT_RT a kernel
 *    thread) on the same CPU, which cannot run while the realtime thread busy-waits
 *    for it: the wait would end only at its timeout, every cycle;
 *  - a socket's latency is bounded by nothing the driver controls (qdisc, NAPI
 *    budget, other traffic).
 * A safe kernel transport would need a dedicated NIC driven by the realtime thread
 * itself (RTnet-style), which is outside this project. */
#include "rtapi.h"
#include "hm2_eth_net.h"

#ifdef __KERNEL__

int hm2_eth_net_open(const char *ip, int port)
{
	/* one line under the kernel message ring's 200 bytes */
	rtapi_print_msg(RTAPI_MSG_ERR, "hm2_eth: not available in the kernel flavor: kernel UDP "
			"sockets may sleep and need the network softirq, which a realtime thread "
			"cannot allow (hm2_eth(9)); use the simulated flavor\n");
	return -EOPNOTSUPP;
}

/* never reached: open always fails in this flavor */
void hm2_eth_net_close(int handle)
{
}

int hm2_eth_net_send(int handle, const void *buf, int len)
{
	return -EOPNOTSUPP;
}

int hm2_eth_net_recv(int handle, void *buf, int cap, long long deadline_ns)
{
	return -EOPNOTSUPP;
}

#else /* simulated flavor */

#include "rtapi_udp.h"

int hm2_eth_net_open(const char *ip, int port)
{
	int rc = rtapi_udp_open(ip, port);

	if (rc == -EINVAL)
		rtapi_print_msg(RTAPI_MSG_ERR, "hm2_eth: board_ip=%s: not an IPv4 address "
				"(a.b.c.d or a.b.c.d:port)\n", ip);
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

#endif
