// SPDX-License-Identifier: GPL-2.0-or-later
// protocol.hpp - the rtapi_app socket, shared by the daemon and the client.
// One request per connection, one line of text ending in '\n':
//   "ping" | "list" | "shutdown" | "unload NAME" | "unload all" | "load NAME [ARGS]"
// (ARGS in the joined form of module_args.hpp). The daemon answers and closes:
//   "ok\n" [one loaded module per line, for "list"]
//   "error CODE\n" MESSAGE-LINE...     (CODE a negative errno)
// Both sides bound every read by size and time, so garbage never blocks either.
#pragma once

#include <string>
#include <string_view>

#include "hal/result.hpp"

namespace hal::rtapi_proto {

inline constexpr size_t max_request = 64 * 1024;  // bytes, including the '\n'
inline constexpr size_t max_reply = 64 * 1024;

// "/tmp/rtapi-<uid>-<instance>.sock" from RTAPI_INSTANCE (default "0"). An
// instance that is empty, too long, or holds anything but [A-Za-z0-9._-] is refused
// (it also names shared memory segments, where a '/' would be fatal).
Result<std::string> socket_path();
// Where a daemon started by halcmd writes its messages: the socket path + ".log".
Result<std::string> log_path();

// An owned file descriptor.
class Fd {
public:
    Fd() = default;
    explicit Fd(int fd) : fd_(fd) {}
    Fd(Fd&& o) noexcept : fd_(o.release()) {}
    Fd& operator=(Fd&& o) noexcept;
    Fd(const Fd&) = delete;
    Fd& operator=(const Fd&) = delete;
    ~Fd();
    int get() const { return fd_; }
    int release() { int fd = fd_; fd_ = -1; return fd; }
    explicit operator bool() const { return fd_ >= 0; }

private:
    int fd_ = -1;
};

enum class ReadEnd {
    line,     // stopped after the first '\n' (not included in data)
    eof,      // peer closed
    too_long, // 'max' bytes without the end asked for
    timeout,  // 'timeout_ms' passed
    failed,   // read error
};

struct ReadResult {
    std::string data;
    ReadEnd end;
};

// Read until '\n' (stop_at_newline) or EOF, at most 'max' bytes, within
// 'timeout_ms' in total.
ReadResult read_bounded(int fd, size_t max, int timeout_ms, bool stop_at_newline);

// Write everything within 'timeout_ms'; false on error, timeout or a closed peer
// (never raises SIGPIPE).
bool write_all(int fd, std::string_view data, int timeout_ms);

}  // namespace hal::rtapi_proto
