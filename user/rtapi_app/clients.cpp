// SPDX-License-Identifier: GPL-2.0-or-later
// clients.cpp - see clients.hpp.
#include "clients.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>

namespace hal {

void Clients::add(rtapi_proto::Fd fd, Clock::time_point now)
{
    open_.push_back(Open{std::move(fd), {}, now + std::chrono::milliseconds(timeout_)});
}

void Clients::poll_fds(std::vector<pollfd>& out) const
{
    for (const Open& c : open_)
        out.push_back(pollfd{c.fd.get(), POLLIN, 0});
}

int Clients::ms_to_deadline(Clock::time_point now) const
{
    if (open_.empty())
        return -1;
    auto first = std::min_element(open_.begin(), open_.end(), [](const Open& a, const Open& b) {
                     return a.deadline < b.deadline;
                 })->deadline;
    auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(first - now).count() + 1;
    return ms > 0 ? static_cast<int>(std::min<long long>(ms, 60000)) : 0;
}

bool Clients::read_some(Open& c, rtapi_proto::ReadResult& in)
{
    char buf[4096];
    for (;;) {
        if (c.data.size() >= rtapi_proto::max_request) {
            in.end = rtapi_proto::ReadEnd::too_long;
            return true;
        }
        size_t want = std::min(sizeof(buf), rtapi_proto::max_request - c.data.size());
        ssize_t n = read(c.fd.get(), buf, want);
        if (n < 0) {
            if (errno == EINTR)
                continue;
            if (errno == EAGAIN || errno == EWOULDBLOCK)
                return false;
            in.end = rtapi_proto::ReadEnd::failed;
            return true;
        }
        if (n == 0) {
            in.end = rtapi_proto::ReadEnd::eof;
            return true;
        }
        // One request per connection: bytes after the '\n' are dropped.
        size_t old = c.data.size();
        c.data.append(buf, static_cast<size_t>(n));
        auto nl = c.data.find('\n', old);
        if (nl != std::string::npos) {
            c.data.resize(nl);
            in.end = rtapi_proto::ReadEnd::line;
            return true;
        }
    }
}

std::vector<Clients::Done> Clients::collect(const std::vector<pollfd>& fds, size_t first,
                                            Clock::time_point now)
{
    std::vector<Done> done;
    std::vector<Open> still;
    for (size_t i = 0; i < open_.size(); ++i) {
        Open& c = open_[i];
        rtapi_proto::ReadResult in{{}, rtapi_proto::ReadEnd::timeout};
        bool finished = false;
        short rev = first + i < fds.size() ? fds[first + i].revents : 0;
        if (rev & (POLLIN | POLLHUP | POLLERR))
            finished = read_some(c, in);
        if (!finished && now >= c.deadline) {
            in.end = rtapi_proto::ReadEnd::timeout;
            finished = true;
        }
        if (finished) {
            in.data = std::move(c.data);
            done.push_back(Done{std::move(c.fd), std::move(in)});
        } else {
            still.push_back(std::move(c));
        }
    }
    open_ = std::move(still);
    return done;
}

}  // namespace hal
