// SPDX-License-Identifier: GPL-2.0-or-later
// protocol.cpp - socket path and bounded reads/writes for the rtapi_app socket.
#include "protocol.hpp"

#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>

namespace hal::rtapi_proto {
namespace {

using Clock = std::chrono::steady_clock;

int ms_left(Clock::time_point deadline)
{
    auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
    return left.count() > 0 ? static_cast<int>(left.count()) : 0;
}

// Wait for 'events' on fd until the deadline: 1 ready, 0 timeout, -1 error.
int wait_fd(int fd, short events, Clock::time_point deadline)
{
    for (;;) {
        pollfd p{fd, events, 0};
        int n = poll(&p, 1, ms_left(deadline));
        if (n >= 0)
            return n > 0 ? 1 : 0;
        if (errno != EINTR)
            return -1;
    }
}

}  // namespace

Result<std::string> socket_path()
{
    const char* env = std::getenv("RTAPI_INSTANCE");
    std::string inst = env ? env : "0";
    bool is_safe = !inst.empty() && inst.size() <= 32;
    for (char c : inst) {
        if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
              c == '.' || c == '_' || c == '-'))
            is_safe = false;
    }
    if (!is_safe)
        return Error{-EINVAL, "RTAPI_INSTANCE '" + inst +
                                  "': use 1 to 32 letters, digits, '.', '_' or '-'"};
    return "/tmp/rtapi-" + std::to_string(getuid()) + "-" + inst + ".sock";
}

Result<std::string> log_path()
{
    auto sock = socket_path();
    if (!sock)
        return sock.error();
    return sock->substr(0, sock->size() - 5) + ".log";
}

Fd& Fd::operator=(Fd&& o) noexcept
{
    if (this != &o) {
        if (fd_ >= 0)
            close(fd_);
        fd_ = o.release();
    }
    return *this;
}

Fd::~Fd()
{
    if (fd_ >= 0)
        close(fd_);
}

ReadResult read_bounded(int fd, size_t max, int timeout_ms, bool stop_at_newline)
{
    auto deadline = Clock::now() + std::chrono::milliseconds(timeout_ms);
    ReadResult r{{}, ReadEnd::failed};
    char buf[4096];
    for (;;) {
        if (r.data.size() >= max) {
            r.end = ReadEnd::too_long;
            return r;
        }
        int ready = wait_fd(fd, POLLIN, deadline);
        if (ready <= 0) {
            r.end = ready == 0 ? ReadEnd::timeout : ReadEnd::failed;
            return r;
        }
        size_t want = std::min(sizeof(buf), max - r.data.size());
        // One request per connection: bytes after the '\n' are dropped.
        ssize_t n = read(fd, buf, want);
        if (n < 0) {
            if (errno == EINTR || errno == EAGAIN)
                continue;
            r.end = ReadEnd::failed;
            return r;
        }
        if (n == 0) {
            r.end = ReadEnd::eof;
            return r;
        }
        r.data.append(buf, static_cast<size_t>(n));
        if (stop_at_newline) {
            auto nl = r.data.find('\n');
            if (nl != std::string::npos) {
                r.data.resize(nl);
                r.end = ReadEnd::line;
                return r;
            }
        }
    }
}

bool write_all(int fd, std::string_view data, int timeout_ms)
{
    auto deadline = Clock::now() + std::chrono::milliseconds(timeout_ms);
    while (!data.empty()) {
        if (wait_fd(fd, POLLOUT, deadline) <= 0)
            return false;
        ssize_t n = send(fd, data.data(), data.size(), MSG_NOSIGNAL | MSG_DONTWAIT);
        if (n < 0) {
            if (errno == EINTR || errno == EAGAIN)
                continue;
            return false;
        }
        data.remove_prefix(static_cast<size_t>(n));
    }
    return true;
}

}  // namespace hal::rtapi_proto
