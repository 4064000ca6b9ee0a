// SPDX-License-Identifier: GPL-2.0-or-later
// rtapi_client.cpp - halcmd's side of the rtapi_app socket: connect, start the
// daemon on demand (double fork, setsid, exec), one request per connection.
#include "rtapi_client.hpp"

#include <fcntl.h>
#include <linux/close_range.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <thread>

#include "module_args.hpp"
#include "protocol.hpp"

namespace hal {
namespace {

using rtapi_proto::Fd;

constexpr int start_timeout_ms = 5000;     // rtapi_app creates its socket well within this
constexpr int short_reply_timeout_ms = 10000;
constexpr int load_reply_timeout_ms = 60000;  // module init, maybe queued behind another load

// Connect to the daemon; code -ENOENT/-ECONNREFUSED when none answers.
Result<Fd> connect_daemon()
{
    auto path = rtapi_proto::socket_path();
    if (!path)
        return path.error();
    sockaddr_un addr{};
    addr.sun_family = AF_UNIX;
    if (path->size() >= sizeof(addr.sun_path))
        return Error{-ENAMETOOLONG, *path + ": socket path too long"};
    std::memcpy(addr.sun_path, path->c_str(), path->size() + 1);
    Fd fd{socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0)};
    if (!fd)
        return Error{-errno, std::string("rtapi_app: socket: ") + std::strerror(errno)};
    if (connect(fd.get(), reinterpret_cast<sockaddr*>(&addr), sizeof(addr)) != 0)
        return Error{-errno, *path + ": " + std::strerror(errno)};
    return fd;
}

bool is_not_running(const Error& e) { return e.code == -ENOENT || e.code == -ECONNREFUSED; }

std::string rtapi_app_path()
{
    if (const char* env = std::getenv("RTAPI_APP"); env && *env)
        return env;
    std::error_code ec;
    auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    return (exe.parent_path() / "rtapi_app").string();
}

// Start rtapi_app detached from us (own session, reparented to init, stdin and
// stdout on /dev/null, stderr kept so its messages reach the user). A pipe closed
// on exec tells whether the exec itself worked. Fork, then only async-signal-safe
// calls: halcmd may have threads.
Result<void> spawn_daemon()
{
    std::string app = rtapi_app_path();
    if (access(app.c_str(), X_OK) != 0)
        return Error{-ENOENT, "rtapi_app: cannot run " + app + ": " + std::strerror(errno) +
                                  " (set RTAPI_APP)"};
    int status_pipe[2];
    if (pipe2(status_pipe, O_CLOEXEC) != 0)
        return Error{-errno, std::string("rtapi_app: pipe: ") + std::strerror(errno)};
    Fd status_in{status_pipe[0]}, status_out{status_pipe[1]};
    const char* argv[] = {"rtapi_app", nullptr};
    // A daemon started by halcmd outlives it: holding halcmd's stderr open would make
    // "halcmd loadrt m 2>&1 | cat" (or a Python subprocess) wait until the HAL is torn
    // down. Its messages go to a log file beside the socket instead. halrun, which
    // ends the session itself, asks for its stderr to be kept (RTAPI_APP_STDERR=keep),
    // so realtime messages reach the terminal or the test result.
    int log_fd = -1;
    const char* keep = std::getenv("RTAPI_APP_STDERR");
    if (!keep || std::strcmp(keep, "keep") != 0) {
        auto log = rtapi_proto::log_path();
        if (!log)
            return log.error();
        log_fd = open(log->c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC | O_NOFOLLOW, 0600);
        if (log_fd < 0)
            return Error{-errno, "rtapi_app: cannot open its log " + *log + ": " + std::strerror(errno)};
    }
    Fd log_guard{log_fd};
    pid_t child = fork();
    if (child < 0)
        return Error{-errno, std::string("rtapi_app: fork: ") + std::strerror(errno)};
    if (child == 0) {
        setsid();
        if (fork() != 0)
            _exit(0);
        if (chdir("/") != 0)
            _exit(127);
        int null_fd = open("/dev/null", O_RDWR);
        if (null_fd >= 0) {
            dup2(null_fd, STDIN_FILENO);
            dup2(null_fd, STDOUT_FILENO);
            if (null_fd > STDERR_FILENO)
                close(null_fd);
        }
        if (log_fd >= 0) {              // not halrun's own session: leave the caller's stderr
            dup2(log_fd, STDERR_FILENO);
            close(log_fd);
        }
        close_range(3, ~0U, CLOSE_RANGE_CLOEXEC);  // none of our descriptors outlive exec
        execv(app.c_str(), const_cast<char* const*>(argv));
        int err = errno;
        (void)!write(status_out.get(), &err, sizeof(err));
        _exit(127);
    }
    status_out = Fd{};
    int wstatus = 0;
    while (waitpid(child, &wstatus, 0) < 0 && errno == EINTR) {
    }
    int exec_errno = 0;
    ssize_t n;
    while ((n = read(status_in.get(), &exec_errno, sizeof(exec_errno))) < 0 && errno == EINTR) {
    }
    if (n == static_cast<ssize_t>(sizeof(exec_errno)))
        return Error{-exec_errno, "rtapi_app: cannot run " + app + ": " +
                                      std::strerror(exec_errno)};
    return {};
}

// Connect, starting the daemon when none answers.
Result<Fd> connect_or_start()
{
    auto fd = connect_daemon();
    if (fd || !is_not_running(fd.error()))
        return fd;
    if (auto r = spawn_daemon(); !r)
        return r.error();
    auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(start_timeout_ms);
    while (std::chrono::steady_clock::now() < deadline) {
        fd = connect_daemon();
        if (fd || !is_not_running(fd.error()))
            return fd;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return Error{-ETIMEDOUT, "rtapi_app: did not answer within " +
                                 std::to_string(start_timeout_ms / 1000) + " s of starting"};
}

// Send one request and read the reply: the lines after "ok", or the error lines
// joined into one.
Result<std::vector<std::string>> transact(Fd fd, const std::string& request, int timeout_ms)
{
    if (!rtapi_proto::write_all(fd.get(), request + "\n", timeout_ms))
        return Error{-EPIPE, "rtapi_app: cannot send the request: connection lost"};
    auto in = rtapi_proto::read_bounded(fd.get(), rtapi_proto::max_reply, timeout_ms, false);
    if (in.end != rtapi_proto::ReadEnd::eof)
        return Error{-EPROTO, in.end == rtapi_proto::ReadEnd::timeout
                                  ? "rtapi_app: no answer within " +
                                        std::to_string(timeout_ms / 1000) + " s"
                                  : std::string("rtapi_app: bad or oversized answer")};
    std::vector<std::string> lines;
    size_t pos = 0;
    while (pos < in.data.size()) {
        size_t nl = in.data.find('\n', pos);
        if (nl == std::string::npos)
            nl = in.data.size();
        lines.push_back(in.data.substr(pos, nl - pos));
        pos = nl + 1;
    }
    if (lines.empty())
        return Error{-EPROTO, "rtapi_app: closed the connection without answering"};
    if (lines[0] == "ok")
        return std::vector<std::string>(lines.begin() + 1, lines.end());
    if (lines[0].rfind("error ", 0) != 0)
        return Error{-EPROTO, "rtapi_app: unexpected answer '" + lines[0].substr(0, 40) + "'"};
    Error e{std::atoi(lines[0].c_str() + 6), ""};
    if (e.code >= 0)
        e.code = -EIO;
    for (size_t i = 1; i < lines.size(); ++i)
        e.message += (e.message.empty() ? "" : "; ") + lines[i];
    if (e.message.empty())
        e.message = "rtapi_app: request failed";
    return e;
}

Result<void> as_void(const Result<std::vector<std::string>>& r)
{
    if (!r)
        return r.error();
    return {};
}

}  // namespace

Result<void> rtapi_load(const std::string& module, const std::vector<std::string>& args)
{
    if (!is_module_name(module))
        return Error{-EINVAL, module + ": invalid module name (use 1 to 31 of a-z, 0-9 and _)"};
    auto parsed = parse_module_args(module, args);
    if (!parsed)
        return parsed.error();
    auto joined = join_module_args(module, *parsed);
    if (!joined)
        return joined.error();
    auto fd = connect_or_start();
    if (!fd)
        return fd.error();
    std::string request = "load " + module + (joined->empty() ? "" : " " + *joined);
    if (request.size() >= rtapi_proto::max_request)
        return Error{-E2BIG, module + ": arguments too long"};
    return as_void(transact(std::move(*fd), request, load_reply_timeout_ms));
}

Result<void> rtapi_unload(const std::string& module)
{
    if (module != "all" && !is_module_name(module))
        return Error{-ENOENT, module + ": not loaded"};
    auto fd = connect_daemon();
    if (!fd) {
        if (!is_not_running(fd.error()))
            return fd.error();
        if (module == "all")
            return {};
        return Error{-ENOENT, module + ": not loaded"};
    }
    return as_void(transact(std::move(*fd), "unload " + module, load_reply_timeout_ms));
}

Result<void> rtapi_start()
{
    auto fd = connect_or_start();
    if (!fd)
        return fd.error();
    return as_void(transact(std::move(*fd), "ping", short_reply_timeout_ms));
}

Result<void> rtapi_set_msg_level(int level)
{
    auto fd = connect_daemon();
    if (!fd) {
        if (is_not_running(fd.error()))
            return {};                   // nothing realtime runs: only the caller's level counts
        return fd.error();
    }
    return as_void(transact(std::move(*fd), "msglevel " + std::to_string(level), short_reply_timeout_ms));
}

Result<std::vector<std::string>> rtapi_list()
{
    auto fd = connect_daemon();
    if (!fd) {
        if (is_not_running(fd.error()))
            return std::vector<std::string>{};
        return fd.error();
    }
    return transact(std::move(*fd), "list", short_reply_timeout_ms);
}

Result<void> rtapi_shutdown()
{
    auto fd = connect_daemon();
    if (!fd) {
        if (is_not_running(fd.error()))
            return {};
        return fd.error();
    }
    return as_void(transact(std::move(*fd), "shutdown", load_reply_timeout_ms));
}

bool rtapi_running()
{
    return connect_daemon().has_value();
}

}  // namespace hal
