// SPDX-License-Identifier: GPL-2.0-or-later
// client.cpp - the machine bus client library (see client.hpp).
#include "bus/client.hpp"

#include <cerrno>
#include <cstring>
#include <poll.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

namespace hal::bus {

using Clock = std::chrono::steady_clock;

static int remaining_ms(Clock::time_point deadline)
{
    auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    return left < 0 ? 0 : static_cast<int>(left);
}

Result<std::unique_ptr<Client>> Client::connect(const std::string& path, const std::string& role,
                                                std::chrono::milliseconds timeout)
{
    sockaddr_un addr{};
    if (path.size() >= sizeof addr.sun_path)
        return Error{-ENAMETOOLONG, "bus socket path too long: " + path};
    addr.sun_family = AF_UNIX;
    std::memcpy(addr.sun_path, path.c_str(), path.size() + 1);
    int fd = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (fd < 0)
        return Error{-errno, std::string("socket: ") + std::strerror(errno)};
    if (::connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0) {
        int e = errno;
        close(fd);
        return Error{-e, "cannot connect to the bus " + path + ": " + std::strerror(e) +
                             (e == ENOENT || e == ECONNREFUSED ? " (is task running?)" : "")};
    }
    std::unique_ptr<Client> c(new Client());
    c->fd_ = fd;
    c->io_role_ = role == "io";
    if (auto r = c->send_raw("HELLO " + std::to_string(PROTOCOL_VERSION) + " " + role); !r)
        return r.error();
    auto deadline = Clock::now() + timeout;
    while (c->id_ == 0) {
        if (!c->broken_.empty())
            return Error{-EPROTO, "bus " + path + ": " + c->broken_};
        int left = remaining_ms(deadline);
        if (left == 0)
            return Error{-ETIMEDOUT, "bus " + path + ": no HELLO reply from task"};
        if (auto r = c->read_some(left); !r)
            return Error{r.error().code, "bus " + path + ": " + r.error().message};
    }
    return c;
}

Client::~Client()
{
    if (fd_ >= 0)
        close(fd_);
}

Result<void> Client::send_raw(const std::string& line)
{
    if (fd_ < 0 || !broken_.empty())
        return Error{-EPIPE, broken_.empty() ? "not connected" : broken_};
    std::string data = line + "\n";
    size_t off = 0;
    while (off < data.size()) {
        ssize_t n = ::send(fd_, data.data() + off, data.size() - off, MSG_NOSIGNAL);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0) {
            broken_ = std::string("connection to task lost: ") + std::strerror(errno);
            return Error{-EPIPE, broken_};
        }
        off += static_cast<size_t>(n);
    }
    return ok();
}

Result<long> Client::send(const std::string& line)
{
    long serial = next_serial_++;
    if (next_serial_ > MAX_SERIAL)
        next_serial_ = 1;
    if (auto r = send_raw(std::to_string(serial) + " " + line); !r)
        return r.error();
    return serial;
}

Result<void> Client::read_some(int timeout_ms)
{
    if (!broken_.empty())
        return Error{-EPIPE, broken_};
    pollfd p{fd_, POLLIN, 0};
    int n = poll(&p, 1, timeout_ms);
    if (n < 0 && errno != EINTR)
        return Error{-errno, std::string("poll: ") + std::strerror(errno)};
    if (n <= 0)
        return ok();
    char buf[8192];
    ssize_t got = read(fd_, buf, sizeof buf);
    if (got <= 0) {
        if (got < 0 && (errno == EINTR || errno == EAGAIN))
            return ok();
        broken_ = "connection closed by task";
        return Error{-EPIPE, broken_};
    }
    in_.append(buf, static_cast<size_t>(got));
    bool too_long = false;
    while (auto line = in_.next(&too_long))
        dispatch(*line);
    return ok();
}

void Client::dispatch(const std::string& line)
{
    if (status_left_ > 0) {
        auto w = split_words(line, 2);
        status_block_[w.empty() ? "" : w[0]] = w.size() > 1 ? w[1] : "";
        if (--status_left_ == 0)
            statuses_[status_serial_] = std::move(status_block_);
        return;
    }
    auto w = split_words(line, 3);
    if (w.empty())
        return;
    if (w[0] == "HELLO") {
        if (w.size() >= 2 && w[1] == "OK") {
            auto v = split_words(line);
            id_ = v.size() >= 4 ? std::atoi(v[3].c_str()) : 1;
            if (id_ <= 0)
                id_ = 1;
        } else {
            broken_ = line.size() > 6 ? line.substr(6) : line;
        }
        return;
    }
    if (w[0] == "MSG") {
        messages_.push_back({w.size() > 1 ? w[1] : "", w.size() > 2 ? w[2] : ""});
        return;
    }
    if (io_role_ && (w[0] == "IOCMD")) {
        raw_.push_back(line);
        return;
    }
    char* end = nullptr;
    long serial = std::strtol(w[0].c_str(), &end, 10);
    if (*end != '\0' || w.size() < 2) {
        raw_.push_back(line);
        return;
    }
    if (w[1] == "RECEIVED") {
        received_[serial] = true;
    } else if (w[1] == "DONE") {
        finished_[serial] = "";
    } else if (w[1] == "ERROR") {
        std::string text = w.size() > 2 ? w[2] : "error";
        if (serial == 0)
            messages_.push_back({"ERROR", text});   // a line task could not attribute
        else
            finished_[serial] = text.empty() ? "error" : text;
    } else if (w[1] == "STATUS") {
        status_serial_ = serial;
        status_left_ = w.size() > 2 ? std::strtoul(w[2].c_str(), nullptr, 10) : 0;
        status_block_.clear();
        if (status_left_ == 0)
            statuses_[serial] = {};
    }
}

bool Client::received(long serial) const
{
    return received_.count(serial) != 0 || finished_.count(serial) != 0;
}

Result<void> Client::wait_done(long serial, std::chrono::milliseconds timeout)
{
    auto deadline = Clock::now() + timeout;
    for (;;) {
        auto it = finished_.find(serial);
        if (it != finished_.end()) {
            std::string err = it->second;
            finished_.erase(it);
            received_.erase(serial);
            if (!err.empty())
                return Error{-1, err};
            return ok();
        }
        int left = remaining_ms(deadline);
        if (left == 0)
            return Error{-ETIMEDOUT, "no reply from task within " + std::to_string(timeout.count()) + " ms"};
        if (auto r = read_some(left); !r)
            return r;
    }
}

Result<void> Client::command(const std::string& line, std::chrono::milliseconds timeout)
{
    auto s = send(line);
    if (!s)
        return s.error();
    return wait_done(*s, timeout);
}

Result<Status> Client::status(std::chrono::milliseconds timeout)
{
    auto s = send("STATUS");
    if (!s)
        return s.error();
    auto deadline = Clock::now() + timeout;
    for (;;) {
        auto it = statuses_.find(*s);
        if (it != statuses_.end() && status_left_ == 0) {
            Status st = std::move(it->second);
            statuses_.erase(it);
            finished_.erase(*s);
            return st;
        }
        auto f = finished_.find(*s);
        if (f != finished_.end() && !f->second.empty()) {
            std::string err = f->second;
            finished_.erase(f);
            return Error{-1, err};
        }
        int left = remaining_ms(deadline);
        if (left == 0)
            return Error{-ETIMEDOUT, "no status from task within " + std::to_string(timeout.count()) + " ms"};
        if (auto r = read_some(left); !r)
            return r.error();
    }
}

std::vector<Message> Client::take_messages()
{
    std::vector<Message> out(messages_.begin(), messages_.end());
    messages_.clear();
    return out;
}

Result<void> Client::pump(std::chrono::milliseconds timeout)
{
    auto deadline = Clock::now() + timeout;
    do {
        if (auto r = read_some(remaining_ms(deadline)); !r)
            return r;
    } while (remaining_ms(deadline) > 0 && messages_.empty() && raw_.empty());
    return ok();
}

std::vector<std::string> Client::take_raw_lines()
{
    std::vector<std::string> out(raw_.begin(), raw_.end());
    raw_.clear();
    return out;
}

}  // namespace hal::bus
