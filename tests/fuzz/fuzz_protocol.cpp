// SPDX-License-Identifier: GPL-2.0-or-later
// fuzz_protocol - the rtapi_app socket as the daemon reads it: the bytes arrive on a
// real socket, in pieces, through the same connection reader (clients.hpp) the
// daemon uses; a complete "load" request's arguments go through the daemon's
// argument parser. (Module loading itself is not fuzzed.)
#include <sys/socket.h>
#include <unistd.h>

#include <cstdint>
#include <string_view>

#include "clients.hpp"
#include "module_args.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    int sv[2];
    if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_NONBLOCK, 0, sv) != 0)
        return 0;
    hal::Clients clients(4, 1000);
    auto now = hal::Clients::Clock::now();
    clients.add(hal::rtapi_proto::Fd{sv[0]}, now);
    // The first byte sets the piece size, so requests arrive split at any point.
    size_t piece = size ? 1 + data[0] % 64 : 1;
    size_t off = size ? 1 : 0;
    std::vector<hal::Clients::Done> done;
    while (done.empty()) {
        if (off < size) {
            size_t n = std::min(piece, size - off);
            if (send(sv[1], data + off, n, MSG_NOSIGNAL) < 0)
                break;
            off += n;
        } else {
            shutdown(sv[1], SHUT_WR);
        }
        std::vector<pollfd> fds;
        clients.poll_fds(fds);
        for (auto& p : fds)
            p.revents = POLLIN;
        done = clients.collect(fds, 0, now);
        if (off >= size && done.empty())
            done = clients.collect(fds, 0, now + std::chrono::seconds(2));  // timed out
    }
    close(sv[1]);
    for (auto& d : done) {
        if (d.in.end != hal::rtapi_proto::ReadEnd::line)
            continue;
        std::string_view line = d.in.data;
        if (line.substr(0, 5) == "load ") {
            line.remove_prefix(5);
            size_t sp = line.find(' ');
            if (hal::is_module_name(line.substr(0, sp)) && sp != std::string_view::npos)
                (void)hal::parse_module_args(line.substr(0, sp), line.substr(sp + 1));
        }
    }
    return 0;
}
