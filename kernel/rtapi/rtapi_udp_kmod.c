/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_udp_kmod.c - rtapi_udp.h in the kernel flavor: every open is refused, with
 * the reason, because a kernel UDP socket cannot be used safely from a realtime
 * thread here:
 *  - realtime functions run inside the thread's FPU section (kernel_fpu_begin), where
 *    preemption is off, and kernel_sendmsg/kernel_recvmsg may sleep (socket lock,
 *    skb allocation): sleeping there is a bug ("scheduling while atomic");
 *  - the reply is delivered by the network stack's softirq (on PREEMPT_RT a kernel
 *    thread) on the same CPU, which cannot run while the realtime thread busy-waits
 *    for it: the wait would end only at its timeout, every cycle;
 *  - a socket's latency is bounded by nothing the driver controls (qdisc, NAPI
 *    budget, other traffic).
 * A safe kernel transport would need a dedicated NIC driven by the realtime thread
 * itself (RTnet-style), which is outside this project. Drivers (hm2_eth) document
 * this in their man page and fail their load with the -EOPNOTSUPP returned here. */
#include <linux/module.h>
#include "rtapi_kmod.h"
#include "rtapi_udp.h"

int rtapi_udp_open(const char *ip, int port)
{
	/* one line under the kernel message ring's 200 bytes */
	rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: UDP to %s: not available in the kernel flavor: "
			"kernel UDP sockets may sleep and need the network softirq, which a "
			"realtime thread cannot allow\n", ip);
	return -EOPNOTSUPP;
}
EXPORT_SYMBOL(rtapi_udp_open);

/* the rest is never reached: no handle is ever handed out in this flavor */
void rtapi_udp_close(int handle)
{
}
EXPORT_SYMBOL(rtapi_udp_close);

int rtapi_udp_send(int handle, const void *buf, int len)
{
	return -EOPNOTSUPP;
}
EXPORT_SYMBOL(rtapi_udp_send);

int rtapi_udp_recv(int handle, void *buf, int cap, long long deadline_ns)
{
	return -EOPNOTSUPP;
}
EXPORT_SYMBOL(rtapi_udp_recv);
