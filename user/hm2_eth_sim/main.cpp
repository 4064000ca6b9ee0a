// SPDX-License-Identifier: GPL-2.0-or-later
// hm2-eth-sim - a Mesa Ethernet card on 127.0.0.1: a UDP server speaking LBP16
// (kernel/drivers/hostmot2/hm2_lbp16.h) in front of the simulated HostMot2 FPGA of
// hm2_sim (kernel/drivers/hostmot2/sim/hm2_sim_model.c), so that hm2_eth's whole
// code path runs without a card: `loadrt hm2_eth board_ip=127.0.0.1:PORT` then gives
// the same HAL names as `loadrt hm2_sim board=5i25`. Faults for tests: dropped
// request or write datagrams, late replies, replies of the wrong length.
// Prints "listening on 127.0.0.1:PORT" (and writes PORT to --port-file) when ready,
// "watchdog bit" when the card's watchdog bites; exits on SIGTERM/SIGINT or after
// --lifetime seconds.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>
#include <thread>
#include <chrono>

extern "C" {
#include "hm2_lbp16.h"
#include "hm2_sim_model.h"
}

namespace {

volatile std::sig_atomic_t stop_requested = 0, unplugged = 0, loss_on = 1;
void on_signal(int) { stop_requested = 1; }
void on_usr1(int) { unplugged = !unplugged; }	// the cable pulled / plugged in again
void on_usr2(int) { loss_on = !loss_on; }	// the --drop-* pattern paused / resumed

struct Options {
	std::string board = "5i25", name, port_file, fault;
	int port = 0, drop_reads = 0, drop_writes = 0, late_every = 0, late_us = 0, lifetime = 600;
	bool bad_reply = false, loss_paused = false;
};

int usage()
{
	std::fprintf(stderr,
		"usage: hm2-eth-sim [--board 5i25|5i20] [--name NAME] [--port N] [--port-file F]\n"
		"                   [--drop-reads N] [--drop-writes N] [--late-every N --late-us US]\n"
		"                   [--bad-reply] [--fault IDROM-FAULT] [--lifetime SECONDS]\n"
		"                   [--loss-paused]\n"
		"SIGUSR1 toggles 'cable pulled' (every datagram lost); SIGUSR2 pauses/resumes\n"
		"the --drop-* pattern (--loss-paused: it starts paused).\n");
	return 2;
}

bool parse_int(const char *s, int lo, int hi, int &out)
{
	char *end;
	errno = 0;
	long v = std::strtol(s, &end, 10);
	if (errno || *end || end == s || v < lo || v > hi)
		return false;
	out = (int)v;
	return true;
}

long long now_ns()
{
	timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return ts.tv_sec * 1000000000LL + ts.tv_nsec;
}

// The card: the FPGA model plus the LBP16 spaces hm2_eth and mesaflash touch.
class Card {
public:
	Card(const sim_layout *l, int fault, const std::string &name)
	{
		hm2_sim_model_init(&model_, l, fault, now_ns());
		std::memcpy(name_, name.data(), name.size() < sizeof(name_) ? name.size() : sizeof(name_));
		// EEPROM: MAC 00:60:1B:12:34:56 (stored reversed), IP 127.0.0.1
		const unsigned char mac[6] = {0x56, 0x34, 0x12, 0x1B, 0x60, 0x00};
		std::memcpy(eeprom_ + 2, mac, 6);
		eeprom_[0x20] = 1; eeprom_[0x21] = 0; eeprom_[0x22] = 0; eeprom_[0x23] = 127;
		std::memcpy(eeprom_ + 0x10, name_, 16);
	}

	// Runs every command of the datagram; the reply is the read data in order.
	// false: a malformed command (the card counts a parse error and stops there).
	bool run(const unsigned char *pkt, int len, std::string &reply)
	{
		hm2_sim_model_advance(&model_, now_ns());
		bump(status_, 0x08);	// RX packet count
		int pos = 0;
		while (pos < len) {
			lbp16_cmd c;
			pos = lbp16_decode(pkt, len, pos, &c);
			if (pos < 0) {
				bump(status_, 0x02);
				return false;
			}
			if (c.has_addr)
				ptr_[c.space] = c.addr;
			for (int i = 0; i < c.count; i++) {
				unsigned addr = ptr_[c.space];
				if (c.write) {
					if (!write(c, addr, pkt + pos))
						return bump(status_, 0x06), false;
					pos += c.size;
				} else {
					unsigned char buf[8];
					if (!read(c, addr, buf))
						return bump(status_, 0x04), false;
					reply.append((const char *)buf, c.size);
				}
				if (c.inc)
					ptr_[c.space] = (unsigned short)(addr + c.size);
			}
		}
		return true;
	}

	bool bitten() const { return model_.wd_status & 1; }

private:
	static void bump(unsigned char *space, int off)
	{
		lbp16_put16(space + off, (rtapi_u16)(lbp16_get16(space + off) + 1));
	}

	unsigned char *space16(int s)
	{
		switch (s) {
		case LBP16_SPACE_EEPROM: return eeprom_;
		case LBP16_SPACE_TIMER: return timer_;
		case LBP16_SPACE_STATUS: return status_;
		default: return nullptr;
		}
	}

	bool read(const lbp16_cmd &c, unsigned addr, unsigned char *out)
	{
		if (c.info) {	// info area: cookie, sizes, ranges, pointer, 8-char name
			if (c.size != 2 || addr > 14)
				return false;
			static const char *names[8] = {"HostMot2", "", "EEPROM", "", "Timers", "", "Status", "Info"};
			unsigned short v = 0;
			if (addr == 0)
				v = (unsigned short)(0x5A00 | c.space);
			else if (addr == 2)
				v = c.space == 0 ? 0x8104 : 0x0102;	// 32-bit registers / 16-bit
			else if (addr == 6)
				v = ptr_[c.space];
			else if (addr >= 8)
				v = (unsigned short)(names[c.space][addr - 8] | names[c.space][addr - 7] << 8);
			lbp16_put16(out, v);
			return true;
		}
		if (c.space == LBP16_SPACE_HM2) {
			if (c.size != 4 || (addr & 3))
				return false;
			lbp16_put32(out, hm2_sim_model_read(&model_, addr));
			return true;
		}
		if (c.space == LBP16_SPACE_INFO) {
			if (c.size != 2 || addr + 2 > 0x20)
				return false;
			unsigned char info[0x20] = {};
			std::memcpy(info, name_, 16);
			info[0x10] = 3;	// LBP16 version
			std::memcpy(out, info + addr, 2);
			return true;
		}
		unsigned char *m = space16(c.space);
		if (!m || c.size != 2 || addr + 2 > kSpaceBytes)
			return false;
		std::memcpy(out, m + addr, 2);
		return true;
	}

	bool write(const lbp16_cmd &c, unsigned addr, const unsigned char *in)
	{
		if (c.info)
			return false;
		if (c.space == LBP16_SPACE_HM2) {
			if (c.size != 4 || (addr & 3))
				return false;
			hm2_sim_model_write(&model_, addr, lbp16_get32(in));
			return true;
		}
		unsigned char *m = space16(c.space);
		if (!m || c.size != 2 || addr + 2 > kSpaceBytes)
			return false;
		if (c.space == LBP16_SPACE_EEPROM) {	// only right after the write-enable
			if (lbp16_get16(status_ + 0x1A) != 0x5A02)
				return false;
		}
		std::memcpy(m + addr, in, 2);
		return true;
	}

	static constexpr unsigned kSpaceBytes = 0x40;
	hm2_sim_model model_;
	char name_[16] = {};
	unsigned char eeprom_[kSpaceBytes] = {}, timer_[kSpaceBytes] = {}, status_[kSpaceBytes] = {};
	unsigned short ptr_[8] = {};
};

bool has_reads(const unsigned char *pkt, int len)
{
	int pos = 0;
	while (pos < len) {
		lbp16_cmd c;
		pos = lbp16_decode(pkt, len, pos, &c);
		if (pos < 0)
			return false;
		if (!c.write)
			return true;
		pos += c.count * c.size;
	}
	return false;
}

}  // namespace

int main(int argc, char **argv)
{
	Options o;
	for (int i = 1; i < argc; i++) {
		std::string a = argv[i];
		const char *v = i + 1 < argc ? argv[i + 1] : nullptr;
		auto num = [&](int lo, int hi, int &out) {
			if (!v || !parse_int(v, lo, hi, out)) {
				std::fprintf(stderr, "hm2-eth-sim: %s needs a number %d..%d\n", a.c_str(), lo, hi);
				std::exit(2);
			}
			i++;
		};
		if (a == "--board" && v) o.board = v, i++;
		else if (a == "--name" && v) o.name = v, i++;
		else if (a == "--port-file" && v) o.port_file = v, i++;
		else if (a == "--fault" && v) o.fault = v, i++;
		else if (a == "--port") num(0, 65535, o.port);
		else if (a == "--drop-reads") num(0, 1000000, o.drop_reads);
		else if (a == "--drop-writes") num(0, 1000000, o.drop_writes);
		else if (a == "--late-every") num(0, 1000000, o.late_every);
		else if (a == "--late-us") num(0, 10000000, o.late_us);
		else if (a == "--lifetime") num(1, 86400, o.lifetime);
		else if (a == "--bad-reply") o.bad_reply = true;
		else if (a == "--loss-paused") o.loss_paused = true;
		else return usage();
	}
	const sim_layout *layout = hm2_sim_layout_find(o.board.c_str());
	if (!layout) {
		std::fprintf(stderr, "hm2-eth-sim: --board %s: unknown; known: %s\n", o.board.c_str(),
			     hm2_sim_layout_names());
		return 2;
	}
	int fault = SIM_FAULT_NONE;
	if (!o.fault.empty() && (fault = hm2_sim_fault_find(o.fault.c_str())) < 0) {
		std::fprintf(stderr, "hm2-eth-sim: --fault %s: unknown; known: %s\n", o.fault.c_str(),
			     hm2_sim_fault_names());
		return 2;
	}
	if (o.name.empty()) {
		o.name = layout->board;
		for (char &ch : o.name)
			ch = (char)std::toupper((unsigned char)ch);
	}
	if (o.name.size() > 16) {
		std::fprintf(stderr, "hm2-eth-sim: --name %s: at most 16 characters\n", o.name.c_str());
		return 2;
	}
	int fd = socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
	sockaddr_in sa{};
	sa.sin_family = AF_INET;
	sa.sin_port = htons((unsigned short)o.port);
	sa.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
	socklen_t sl = sizeof(sa);
	if (fd < 0 || bind(fd, (sockaddr *)&sa, sizeof(sa)) < 0 || getsockname(fd, (sockaddr *)&sa, &sl) < 0) {
		std::fprintf(stderr, "hm2-eth-sim: cannot listen on 127.0.0.1:%d: %s\n", o.port,
			     std::strerror(errno));
		return 1;
	}
	std::signal(SIGTERM, on_signal);
	std::signal(SIGINT, on_signal);
	std::signal(SIGUSR1, on_usr1);
	std::signal(SIGUSR2, on_usr2);
	loss_on = !o.loss_paused;
	int port = ntohs(sa.sin_port);
	if (!o.port_file.empty()) {
		std::string tmp = o.port_file + ".tmp";
		FILE *f = std::fopen(tmp.c_str(), "w");
		if (!f || std::fprintf(f, "%d\n", port) < 0 || std::fclose(f) != 0 ||
		    std::rename(tmp.c_str(), o.port_file.c_str()) != 0) {
			std::fprintf(stderr, "hm2-eth-sim: cannot write %s\n", o.port_file.c_str());
			return 1;
		}
	}
	std::printf("listening on 127.0.0.1:%d as %s (%s)\n", port, o.name.c_str(), layout->firmware);
	std::fflush(stdout);

	Card card(layout, fault, o.name);
	unsigned long in_pkts = 0, in_bytes = 0, out_pkts = 0, out_bytes = 0, read_pkts = 0;
	long long end = now_ns() + o.lifetime * 1000000000LL;
	unsigned long reads = 0, writes = 0;
	bool was_bitten = false;
	while (!stop_requested && now_ns() < end) {
		pollfd p{fd, POLLIN, 0};
		if (poll(&p, 1, 200) <= 0)
			continue;
		unsigned char pkt[2048];
		sockaddr_in from{};
		socklen_t fl = sizeof(from);
		ssize_t n = recvfrom(fd, pkt, sizeof(pkt), 0, (sockaddr *)&from, &fl);
		if (n <= 0 || unplugged)
			continue;
		in_pkts++;
		in_bytes += (unsigned long)n;
		bool reading = has_reads(pkt, (int)n);
		read_pkts += reading;
		unsigned long k = 0;
		if (loss_on)
			k = reading ? ++reads : ++writes;
		if (loss_on && ((reading && o.drop_reads && k % o.drop_reads == 0) ||
				(!reading && o.drop_writes && k % o.drop_writes == 0)))
			continue;	// lost on the wire
		std::string reply;
		card.run(pkt, (int)n, reply);
		if (card.bitten() != was_bitten) {
			was_bitten = card.bitten();
			std::printf("%s\n", was_bitten ? "watchdog bit" : "watchdog reset");
			std::fflush(stdout);
		}
		if (reply.empty())
			continue;
		if (o.bad_reply)
			reply.push_back('\0');
		if (reading && loss_on && o.late_every && k % o.late_every == 0)
			std::this_thread::sleep_for(std::chrono::microseconds(o.late_us));
		sendto(fd, reply.data(), reply.size(), 0, (sockaddr *)&from, fl);
		out_pkts++;
		out_bytes += reply.size();
	}
	close(fd);
	std::printf("datagrams received %lu (%lu bytes, %lu with reads), sent %lu (%lu bytes)\n",
		    in_pkts, in_bytes, read_pkts, out_pkts, out_bytes);
	return 0;
}
