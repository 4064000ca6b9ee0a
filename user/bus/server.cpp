// SPDX-License-Identifier: GPL-2.0-or-later
// server.cpp - the machine bus server (see server.hpp and docs/bus.md).
#include "bus/server.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

namespace hal::bus {

static std::string errno_text(const std::string& what, int e)
{
    return what + ": " + std::strerror(e);
}

// The socket's directory: created 0750 if missing; an existing one must be ours (or
// root's, e.g. /tmp itself is never used directly) and not writable by others, so
// nobody else can replace the socket.
static Result<void> check_dir(const std::string& path)
{
    size_t slash = path.rfind('/');
    if (slash == std::string::npos || slash == 0)
        return ok();
    std::string dir = path.substr(0, slash);
    struct stat st;
    if (lstat(dir.c_str(), &st) != 0) {
        if (errno != ENOENT)
            return Error{-errno, errno_text("bus directory " + dir, errno)};
        if (mkdir(dir.c_str(), 0750) != 0 && errno != EEXIST)
            return Error{-errno, errno_text("cannot create bus directory " + dir, errno)};
        if (lstat(dir.c_str(), &st) != 0)
            return Error{-errno, errno_text("bus directory " + dir, errno)};
    }
    if (!S_ISDIR(st.st_mode))
        return Error{-ENOTDIR, "bus directory " + dir + " is not a directory"};
    if (st.st_uid != geteuid() && st.st_uid != 0)
        return Error{-EPERM, "bus directory " + dir + " belongs to another user (uid " +
                                 std::to_string(st.st_uid) + ")"};
    if ((st.st_mode & S_IWOTH) && !(st.st_mode & S_ISVTX))
        return Error{-EPERM, "bus directory " + dir + " is world-writable"};
    return ok();
}

Result<std::unique_ptr<Server>> Server::listen(const std::string& path)
{
    sockaddr_un addr{};
    if (path.empty() || path.size() >= sizeof addr.sun_path)
        return Error{-ENAMETOOLONG, "bus socket path empty or too long: '" + path + "'"};
    if (auto r = check_dir(path); !r)
        return r.error();
    addr.sun_family = AF_UNIX;
    std::memcpy(addr.sun_path, path.c_str(), path.size() + 1);

    struct stat st;
    if (lstat(path.c_str(), &st) == 0) {
        if (!S_ISSOCK(st.st_mode))
            return Error{-EEXIST, "bus socket " + path + " exists and is not a socket"};
        // a socket left by a task that died is removed; a live one is refused
        int probe = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
        bool alive = probe >= 0 && connect(probe, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0;
        if (probe >= 0)
            close(probe);
        if (alive)
            return Error{-EADDRINUSE, "another task already serves the bus " + path};
        unlink(path.c_str());
    }
    int fd = socket(AF_UNIX, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
    if (fd < 0)
        return Error{-errno, errno_text("bus socket", errno)};
    // umask 0117 while binding: the socket is created rw for owner and group only
    mode_t old = umask(0117);
    int rc = bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr);
    int e = errno;
    umask(old);
    if (rc != 0 || ::listen(fd, 16) != 0) {
        if (rc == 0)
            e = errno;
        close(fd);
        return Error{-e, errno_text("cannot listen on bus socket " + path, e)};
    }
    chmod(path.c_str(), 0660);
    std::unique_ptr<Server> s(new Server());
    s->listen_fd_ = fd;
    s->path_ = path;
    return s;
}

Server::~Server()
{
    for (auto& [id, c] : clients_)
        close(c.fd);
    if (listen_fd_ >= 0) {
        close(listen_fd_);
        unlink(path_.c_str());
    }
}

int Server::io_client() const
{
    for (const auto& [id, c] : clients_)
        if (c.hello && c.role == Role::Io && !c.closing)
            return id;
    return -1;
}

void Server::poll_once(int timeout_ms, Handler& h)
{
    std::vector<pollfd> fds;
    std::vector<int> ids;
    fds.push_back({listen_fd_, POLLIN, 0});
    ids.push_back(0);
    for (auto& [id, c] : clients_) {
        short ev = c.closing ? 0 : POLLIN;
        if (!c.out.empty())
            ev |= POLLOUT;
        fds.push_back({c.fd, ev, 0});
        ids.push_back(id);
    }
    int n = poll(fds.data(), fds.size(), timeout_ms);
    if (n <= 0)
        return;
    if (fds[0].revents & POLLIN)
        accept_one(h);
    for (size_t i = 1; i < fds.size(); ++i) {
        auto it = clients_.find(ids[i]);
        if (it == clients_.end() || fds[i].revents == 0)
            continue;
        Conn& c = it->second;
        if (fds[i].revents & POLLOUT)
            flush(c);
        if (fds[i].revents & (POLLIN | POLLHUP | POLLERR))
            read_from(ids[i], c, h);
    }
    // close what asked to be closed (after its last words went out) or broke
    std::vector<int> gone;
    for (auto& [id, c] : clients_)
        if (c.fd < 0 || (c.closing && c.out.empty()))
            gone.push_back(id);
    for (int id : gone)
        drop(id, h);
}

void Server::accept_one(Handler& h)
{
    (void)h;
    int fd = accept4(listen_fd_, nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC);
    if (fd < 0)
        return;
    // Who is calling: the socket's mode already keeps others out; this also refuses
    // a process of another user that got hold of the path some other way.
    ucred cred{};
    socklen_t len = sizeof cred;
    bool allowed = getsockopt(fd, SOL_SOCKET, SO_PEERCRED, &cred, &len) == 0 &&
                   (cred.uid == geteuid() || cred.uid == 0 || cred.gid == getegid());
    if (!allowed || clients_.size() >= static_cast<size_t>(MAX_CLIENTS)) {
        const char* msg = allowed ? "HELLO ERROR too many clients\n" : "HELLO ERROR permission denied\n";
        ssize_t r = write(fd, msg, std::strlen(msg));
        (void)r;
        close(fd);
        return;
    }
    Conn c;
    c.fd = fd;
    clients_.emplace(next_id_++, std::move(c));
}

void Server::read_from(int id, Conn& c, Handler& h)
{
    char buf[4096];
    for (;;) {
        ssize_t n = read(c.fd, buf, sizeof buf);
        if (n > 0) {
            c.in.append(buf, static_cast<size_t>(n));
            bool too_long = false;
            for (;;) {
                auto line = c.in.next(&too_long);
                if (too_long) {
                    bad_line(id, c, 0, "line too long (more than " + std::to_string(MAX_LINE) + " bytes)");
                    continue;   // the lines after it are still served
                }
                if (!line)
                    break;
                handle_line(id, c, *line, h);
                if (c.closing || c.fd < 0)
                    return;
            }
            if (c.closing || c.fd < 0)
                return;
            continue;
        }
        if (n < 0 && (errno == EAGAIN || errno == EINTR))
            return;
        // end of stream or error: a half-sent line is simply forgotten
        close(c.fd);
        c.fd = -1;
        return;
    }
}

void Server::bad_line(int id, Conn& c, long serial, const std::string& why)
{
    (void)id;
    send_line_to(c, std::to_string(serial) + " ERROR " + why);
    if (++c.bad_lines >= MAX_BAD_LINES) {
        send_line_to(c, "0 ERROR too many bad lines, closing the connection");
        c.closing = true;
    }
}

void Server::handle_line(int id, Conn& c, const std::string& line, Handler& h)
{
    if (!c.hello) {
        // HELLO <version> <role> [name]
        auto w = split_words(line);
        if (w.size() < 3 || w[0] != "HELLO") {
            send_line_to(c, "HELLO ERROR the first line must be 'HELLO " + std::to_string(PROTOCOL_VERSION) +
                                " client|io [NAME]'");
            c.closing = true;
            return;
        }
        if (w[1] != std::to_string(PROTOCOL_VERSION)) {
            send_line_to(c, "HELLO ERROR protocol version '" + sanitize(w[1], 20) + "' not supported (this is " +
                                std::to_string(PROTOCOL_VERSION) + ")");
            c.closing = true;
            return;
        }
        if (w[2] == "io") {
            if (io_client() >= 0) {
                send_line_to(c, "HELLO ERROR an io client is already connected");
                c.closing = true;
                return;
            }
            c.role = Role::Io;
        } else if (w[2] == "client") {
            c.role = Role::Client;
        } else {
            send_line_to(c, "HELLO ERROR unknown role '" + sanitize(w[2], 20) + "' (client or io)");
            c.closing = true;
            return;
        }
        c.hello = true;
        send_line_to(c, "HELLO OK " + std::to_string(PROTOCOL_VERSION) + " " + std::to_string(id));
        h.on_connect(id, c.role);
        return;
    }
    if (c.role == Role::Io) {
        if (!is_printable(line)) {
            bad_line(id, c, 0, "control characters in the line");
            return;
        }
        c.bad_lines = 0;
        h.on_io_line(id, line);
        return;
    }
    auto req = parse_request(line);
    if (!req) {
        // the serial, when the line starts with one, lets the client match the error
        long serial = 0;
        auto w = split_words(line, 2);
        if (!w.empty()) {
            char* end = nullptr;
            long s = std::strtol(w[0].c_str(), &end, 10);
            if (*end == '\0' && s > 0 && s <= MAX_SERIAL)
                serial = s;
        }
        bad_line(id, c, serial, req.error().message);
        return;
    }
    c.bad_lines = 0;
    h.on_command(id, *req);
}

void Server::send_line_to(Conn& c, const std::string& line)
{
    if (c.fd < 0)
        return;
    if (c.out.size() + line.size() + 1 > MAX_OUTPUT) {
        // a client that does not read its replies is dropped, not waited for
        close(c.fd);
        c.fd = -1;
        c.out.clear();
        return;
    }
    c.out += line;
    c.out += '\n';
    flush(c);
}

void Server::flush(Conn& c)
{
    while (c.fd >= 0 && !c.out.empty()) {
        ssize_t n = send(c.fd, c.out.data(), c.out.size(), MSG_NOSIGNAL);
        if (n > 0) {
            c.out.erase(0, static_cast<size_t>(n));
            continue;
        }
        if (n < 0 && (errno == EAGAIN || errno == EINTR))
            return;
        close(c.fd);
        c.fd = -1;
        c.out.clear();
    }
}

void Server::drop(int id, Handler& h)
{
    auto it = clients_.find(id);
    if (it == clients_.end())
        return;
    bool was_hello = it->second.hello;
    Role role = it->second.role;
    if (it->second.fd >= 0)
        close(it->second.fd);
    clients_.erase(it);
    if (was_hello)
        h.on_disconnect(id, role);
}

void Server::send_line(int client, const std::string& line)
{
    auto it = clients_.find(client);
    if (it != clients_.end())
        send_line_to(it->second, line);
}

void Server::reply(int client, long serial, const std::string& what)
{
    send_line(client, std::to_string(serial) + " " + what);
}

void Server::send_status(int client, long serial, const StatusLines& st)
{
    auto it = clients_.find(client);
    if (it == clients_.end())
        return;
    std::string block = std::to_string(serial) + " STATUS " + std::to_string(st.size());
    for (const auto& [k, v] : st)
        block += "\n" + k + " " + v;
    send_line_to(it->second, block);
}

void Server::broadcast(const std::string& kind, const std::string& text)
{
    std::string line = "MSG " + kind + " " + sanitize(text, MAX_LINE - 64);
    for (auto& [id, c] : clients_)
        if (c.hello && c.role == Role::Client)
            send_line_to(c, line);
}

}  // namespace hal::bus
