/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_eth_net.h - hm2_eth's UDP socket, one per board (hm2_eth_net.c). */
#ifndef HM2_ETH_NET_H
#define HM2_ETH_NET_H

/* A socket connected to ip:port: handle >= 0, or -errno after a message. In the
 * kernel flavor it always refuses (-EOPNOTSUPP) with the reason hm2_eth(9) gives. */
int hm2_eth_net_open(const char *ip, int port);
void hm2_eth_net_close(int handle);
int hm2_eth_net_send(int handle, const void *buf, int len);
/* one datagram, waiting until deadline_ns (rtapi_get_time) at the latest: its
 * length, -ETIMEDOUT or -errno */
int hm2_eth_net_recv(int handle, void *buf, int cap, long long deadline_ns);

#endif /* HM2_ETH_NET_H */
