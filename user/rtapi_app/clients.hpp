// SPDX-License-Identifier: GPL-2.0-or-later
// clients.hpp - the daemon's open connections. Each reads its one request line
// without blocking the others and within its own deadline, so a client that
// connects and sends nothing delays nobody (issue 19, item 6); the requests
// themselves are still answered one at a time, which keeps loads serialized.
#pragma once

#include <poll.h>

#include <chrono>
#include <string>
#include <vector>

#include "protocol.hpp"

namespace hal {

class Clients {
public:
    using Clock = std::chrono::steady_clock;

    // A connection whose request is complete (or that failed, or ran out of time).
    struct Done {
        rtapi_proto::Fd fd;
        rtapi_proto::ReadResult in;
    };

    explicit Clients(size_t max_clients, int request_timeout_ms)
        : max_(max_clients), timeout_(request_timeout_ms)
    {
    }

    bool full() const { return open_.size() >= max_; }
    size_t size() const { return open_.size(); }
    // A new connection (non-blocking): its deadline starts now.
    void add(rtapi_proto::Fd fd, Clock::time_point now);
    // Append one pollfd per connection, in order, starting at out.size().
    void poll_fds(std::vector<pollfd>& out) const;
    // Milliseconds until the earliest deadline (-1: no connection).
    int ms_to_deadline(Clock::time_point now) const;
    // After poll(): read what arrived on fds[first..], and hand back the finished ones.
    std::vector<Done> collect(const std::vector<pollfd>& fds, size_t first, Clock::time_point now);

private:
    struct Open {
        rtapi_proto::Fd fd;
        std::string data;
        Clock::time_point deadline;
    };
    // Read what is there now; true when the request is finished (end set in 'in').
    static bool read_some(Open& c, rtapi_proto::ReadResult& in);

    std::vector<Open> open_;
    size_t max_;
    int timeout_;
};

}  // namespace hal
