// SPDX-License-Identifier: GPL-2.0-or-later
// daemon.cpp - the rtapi_app socket server: single instance per RTAPI_INSTANCE
// (an flock()ed lock file), stale socket removal, signal-safe main loop, and the
// request dispatcher. Connections are read concurrently (clients.hpp), requests
// answered one at a time. Garbage gets an error reply; nothing a client sends can
// crash it or stall another client.
#include "daemon.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include "clients.hpp"
#include "hal_host.h"
#include "module_args.hpp"
#include "module_host.hpp"
#include "overrun_watch.hpp"
#include "protocol.hpp"

namespace hal {
namespace {

using rtapi_proto::Fd;

constexpr int request_timeout_ms = 3000;  // a client sends its line right after connecting
constexpr int reply_timeout_ms = 3000;
// Connections read at once; more wait in the listen backlog until one finishes
// (each within request_timeout_ms), so no number of idle clients stalls the daemon.
constexpr size_t max_clients = 64;

volatile sig_atomic_t stop_signal = 0;  // set by on_signal(), read by the main loop

extern "C" void on_signal(int sig) { stop_signal = sig; }

struct Reply {
    std::string text;
    bool should_exit = false;  // unlink the socket before sending, then end
};

Reply ok_reply(const std::string& lines = "") { return Reply{"ok\n" + lines, false}; }

Reply error_reply(int code, const std::string& message)
{
    return Reply{"error " + std::to_string(code) + "\n" + message + "\n", false};
}

bool is_text(std::string_view s)
{
    for (unsigned char c : s) {
        if ((c < 0x20 && c != '\t') || c == 0x7f)
            return false;
    }
    return true;
}

// Before this rtapi_app loads its first module: realtime objects already in the HAL
// belong to a host that died (we hold the instance lock), and no longer run.
Reply refuse_orphans()
{
    int n = hal_realtime_object_count();
    if (n <= 0)
        return Reply{};
    return error_reply(-EEXIST, "rtapi_app: the HAL still holds " + std::to_string(n) +
                                    " realtime object" + (n == 1 ? "" : "s") +
                                    " of a realtime host that died; clean up with 'halrun -U', "
                                    "then load again");
}

// Dispatch one request line (already checked to be text). 'is_fresh': nothing
// loaded by this process yet.
Reply handle_request(ModuleHost& host, std::string_view line, bool& is_fresh)
{
    auto sp = line.find(' ');
    std::string verb(line.substr(0, sp));
    std::string_view rest = sp == std::string_view::npos ? "" : line.substr(sp + 1);
    if (verb == "ping" && rest.empty())
        return ok_reply();
    if (verb == "list" && rest.empty()) {
        std::string names;
        for (const std::string& n : host.list())
            names += n + "\n";
        return ok_reply(names);
    }
    if (verb == "shutdown" && rest.empty()) {
        (void)host.unload("all");
        return Reply{"ok\n", true};
    }
    if (verb == "unload" && !rest.empty() && rest.find(' ') == std::string_view::npos) {
        auto r = host.unload(std::string(rest));
        Reply reply = r ? ok_reply() : error_reply(r.error().code, r.error().message);
        // The last module went and no thread outlived it (threads(9)): nothing left to host.
        reply.should_exit = host.empty() && hal_thread_count() == 0;
        return reply;
    }
    if (verb == "load" && !rest.empty()) {
        auto nsp = rest.find(' ');
        std::string name(rest.substr(0, nsp));
        std::string_view joined = nsp == std::string_view::npos ? "" : rest.substr(nsp + 1);
        auto args = parse_module_args(name, joined);
        if (!args)
            return error_reply(args.error().code, args.error().message);
        if (is_fresh) {
            if (Reply refused = refuse_orphans(); !refused.text.empty())
                return refused;
            is_fresh = false;
        }
        auto r = host.load(name, *args);
        return r ? ok_reply() : error_reply(r.error().code, r.error().message);
    }
    if (verb == "msglevel" && rest.size() == 1 && rest[0] >= '0' && rest[0] <= '5') {
        rtapi_set_msg_level(rest[0] - '0');
        return ok_reply();
    }
    std::string shown = verb.substr(0, 32);
    if (verb == "msglevel" || verb == "ping" || verb == "list" || verb == "shutdown" || verb == "unload" ||
        verb == "load")
        return error_reply(-EINVAL, "rtapi_app: wrong arguments for '" + shown + "'");
    return error_reply(-EINVAL, "rtapi_app: unknown request '" + shown + "'");
}

// Only the daemon's owner may talk to it (DESIGN.md: the socket checks SO_PEERCRED).
bool is_owner(int fd)
{
    ucred peer{};
    socklen_t len = sizeof(peer);
    return getsockopt(fd, SOL_SOCKET, SO_PEERCRED, &peer, &len) == 0 && peer.uid == getuid();
}

// Check and answer one request that Clients has read.
Reply answer(ModuleHost& host, const rtapi_proto::ReadResult& in, bool& is_fresh)
{
    switch (in.end) {
    case rtapi_proto::ReadEnd::line:
        break;
    case rtapi_proto::ReadEnd::eof:
        if (in.data.empty())
            return Reply{};  // a connect-only probe: nothing to answer
        return error_reply(-EPROTO, "rtapi_app: truncated request (no end of line)");
    case rtapi_proto::ReadEnd::too_long:
        return error_reply(-EMSGSIZE, "rtapi_app: request longer than " +
                                          std::to_string(rtapi_proto::max_request) + " bytes");
    case rtapi_proto::ReadEnd::timeout:
        return error_reply(-ETIMEDOUT, "rtapi_app: no complete request within " +
                                           std::to_string(request_timeout_ms) + " ms");
    case rtapi_proto::ReadEnd::failed:
        return Reply{};
    }
    if (!is_text(in.data))
        return error_reply(-EPROTO, "rtapi_app: request is not a line of text");
    try {
        return handle_request(host, in.data, is_fresh);
    } catch (const std::exception& e) {
        return error_reply(-EIO, std::string("rtapi_app: internal error: ") + e.what());
    }
}

// Accept every pending connection while there is room. Strangers get one error line.
void accept_all(int listener, Clients& clients)
{
    while (!clients.full()) {
        Fd conn{accept4(listener, nullptr, nullptr, SOCK_CLOEXEC | SOCK_NONBLOCK)};
        if (!conn)
            return;  // EAGAIN: none left (or a transient error: poll again)
        if (!is_owner(conn.get())) {
            Reply r = error_reply(-EPERM, "rtapi_app: only its owner may use this rtapi_app");
            (void)rtapi_proto::write_all(conn.get(), r.text, reply_timeout_ms);
            continue;
        }
        clients.add(std::move(conn), Clients::Clock::now());
    }
}

// The lock that makes this the only daemon of the instance. A lock file whose
// name was unlinked by an exiting daemon after we opened it is no lock: retry.
Fd take_instance_lock(const std::string& lock_path, bool& is_busy)
{
    is_busy = false;
    for (int attempt = 0; attempt < 10; ++attempt) {
        Fd fd{open(lock_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0600)};
        if (!fd)
            return Fd{};
        if (flock(fd.get(), LOCK_EX | LOCK_NB) != 0) {
            is_busy = errno == EWOULDBLOCK;
            return Fd{};
        }
        struct stat held{}, named{};
        if (fstat(fd.get(), &held) == 0 && stat(lock_path.c_str(), &named) == 0 &&
            held.st_ino == named.st_ino && held.st_dev == named.st_dev)
            return fd;
    }
    return Fd{};
}

Fd listen_on(const std::string& path)
{
    sockaddr_un addr{};
    addr.sun_family = AF_UNIX;
    if (path.size() >= sizeof(addr.sun_path)) {
        errno = ENAMETOOLONG;
        return Fd{};
    }
    std::memcpy(addr.sun_path, path.c_str(), path.size() + 1);
    Fd fd{socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0)};
    if (!fd)
        return Fd{};
    unlink(path.c_str());  // we hold the instance lock: any socket file is stale
    mode_t old_mask = umask(077);
    int rc = bind(fd.get(), reinterpret_cast<sockaddr*>(&addr), sizeof(addr));
    umask(old_mask);
    if (rc != 0 || chmod(path.c_str(), 0600) != 0 || listen(fd.get(), SOMAXCONN) != 0)
        return Fd{};
    return fd;
}

// Remove the socket, then the lock file, while we still hold the lock: only then
// can a new daemon take the instance, so we never remove names it created.
// Called once, on the way out.
void release_names(const std::string& path, const std::string& lock_path)
{
    unlink(path.c_str());
    unlink(lock_path.c_str());
}

}  // namespace

int run_daemon()
{
    auto path = rtapi_proto::socket_path();
    if (!path) {
        std::fprintf(stderr, "rtapi_app: %s\n", path.error().message.c_str());
        return 1;
    }
    std::string lock_path = path->substr(0, path->size() - 5) + ".lock";
    bool is_busy = false;
    Fd lock = take_instance_lock(lock_path, is_busy);
    if (!lock) {
        if (is_busy)
            return 0;  // another rtapi_app serves this instance; clients use that one
        std::fprintf(stderr, "rtapi_app: %s: %s\n", lock_path.c_str(), std::strerror(errno));
        return 1;
    }
    Fd listener = listen_on(*path);
    if (!listener) {
        std::fprintf(stderr, "rtapi_app: %s: %s\n", path->c_str(), std::strerror(errno));
        release_names(*path, lock_path);
        return 1;
    }

    // Signals stay blocked except inside ppoll(), so a stop request is never lost
    // between the check and the wait, and never interrupts a module's init.
    sigset_t stop_set, wait_mask;
    sigemptyset(&stop_set);
    sigaddset(&stop_set, SIGTERM);
    sigaddset(&stop_set, SIGINT);
    sigaddset(&stop_set, SIGHUP);
    sigprocmask(SIG_BLOCK, &stop_set, &wait_mask);
    sigdelset(&wait_mask, SIGTERM);
    sigdelset(&wait_mask, SIGINT);
    sigdelset(&wait_mask, SIGHUP);
    struct sigaction sa{};
    sa.sa_handler = on_signal;
    sigaction(SIGTERM, &sa, nullptr);
    sigaction(SIGINT, &sa, nullptr);
    sigaction(SIGHUP, &sa, nullptr);
    signal(SIGPIPE, SIG_IGN);  // replies to vanished clients must not kill us

    ModuleHost host(module_dir());
    Clients clients(max_clients, request_timeout_ms);
    OverrunWatch overruns;
    bool is_fresh = true;
    bool is_listening = true;
    std::vector<pollfd> fds;
    while (!stop_signal && is_listening) {
        fds.assign(1, pollfd{listener.get(), static_cast<short>(clients.full() ? 0 : POLLIN), 0});
        clients.poll_fds(fds);
        auto before = Clients::Clock::now();
        int wait_ms = clients.ms_to_deadline(before);
        if (int w = overruns.ms_to_check(before); w >= 0 && (wait_ms < 0 || w < wait_ms))
            wait_ms = w;
        timespec ts{wait_ms / 1000, (wait_ms % 1000) * 1000000L};
        if (ppoll(fds.data(), fds.size(), wait_ms < 0 ? nullptr : &ts, &wait_mask) < 0)
            continue;  // EINTR: look at stop_signal
        auto now = Clients::Clock::now();
        for (auto& done : clients.collect(fds, 1, now)) {
            Reply reply = answer(host, done.in, is_fresh);
            if (reply.should_exit) {
                release_names(*path, lock_path);  // before the client hears "ok"
                is_listening = false;
            }
            if (!reply.text.empty())
                (void)rtapi_proto::write_all(done.fd.get(), reply.text, reply_timeout_ms);
            if (!is_listening)
                break;
        }
        if (is_listening && (fds[0].revents & POLLIN))
            accept_all(listener.get(), clients);
        if (is_listening)
            overruns.check(Clients::Clock::now());
    }
    (void)host.unload("all");
    if (is_listening)
        release_names(*path, lock_path);
    return 0;
}

}  // namespace hal
