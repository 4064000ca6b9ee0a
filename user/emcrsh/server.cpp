// SPDX-License-Identifier: GPL-2.0-or-later
// server.cpp - the TCP server (server.hpp).
#include "server.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <thread>

namespace hal::emcrsh {

Server::~Server()
{
    if (listen_fd_ >= 0)
        close(listen_fd_);
    for (int fd : wake_)
        if (fd >= 0)
            close(fd);
}

Result<int> Server::listen(int port)
{
    if (pipe2(wake_, O_CLOEXEC) != 0)
        return Error{-errno, std::string("pipe: ") + std::strerror(errno)};
    listen_fd_ = socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (listen_fd_ < 0)
        return Error{-errno, std::string("socket: ") + std::strerror(errno)};
    int one = 1;
    setsockopt(listen_fd_, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_ANY);
    a.sin_port = htons(static_cast<uint16_t>(port));
    if (bind(listen_fd_, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0)
        return Error{-errno, "port " + std::to_string(port) + ": " + std::strerror(errno)};
    if (::listen(listen_fd_, 16) != 0)
        return Error{-errno, "port " + std::to_string(port) + ": listen: " + std::strerror(errno)};
    socklen_t len = sizeof a;
    getsockname(listen_fd_, reinterpret_cast<sockaddr*>(&a), &len);
    return static_cast<int>(ntohs(a.sin_port));
}

static bool write_all(int fd, const std::string& s)
{
    size_t off = 0;
    while (off < s.size()) {
        ssize_t n = ::send(fd, s.data() + off, s.size() - off, MSG_NOSIGNAL);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return false;
        off += static_cast<size_t>(n);
    }
    return true;
}

void Server::serve(int fd, int id)
{
    {
        BusMachine machine(bus_path_);
        Session session(id, shared_, machine);
        LineReader reader;
        char buf[4096];
        bool open = true;
        while (open && !shared_.shutdown) {
            pollfd p[2] = {{fd, POLLIN, 0}, {machine.fd(), POLLIN, 0}};
            int np = machine.fd() >= 0 ? 2 : 1;
            if (poll(p, static_cast<nfds_t>(np), 500) < 0 && errno != EINTR)
                break;
            if (np == 2 && p[1].revents) {
                machine.pump();   // operator messages: kept for GET ERROR, never piling up
                session.take_messages();
            }
            if (!(p[0].revents & (POLLIN | POLLHUP | POLLERR)))
                continue;
            ssize_t n = read(fd, buf, sizeof buf);
            if (n < 0 && errno == EINTR)
                continue;
            if (n <= 0)
                break;
            reader.append(buf, static_cast<size_t>(n));
            for (;;) {
                bool too_long = false;
                auto line = reader.next(&too_long);
                if (too_long) {
                    open = write_all(fd, LINE_TOO_LONG);
                    if (!open)
                        break;
                    continue;
                }
                if (!line)
                    break;
                open = write_all(fd, session.handle(*line)) && !session.closing();
                if (!open || shared_.shutdown)
                    break;
            }
        }
    }   // the session gives its enable up, the bus connection closes
    --shared_.sessions;   // before our FIN: a client that saw the close may reconnect
    // Send our FIN first and read what the client still sends until its own, so the
    // close does not reset the connection under the last reply (unread input makes
    // the kernel answer with RST). Half a second at most.
    shutdown(fd, SHUT_WR);
    for (int waited = 0; waited < 500; waited += 50) {
        pollfd p{fd, POLLIN, 0};
        char drain[512];
        if (poll(&p, 1, 50) > 0 && read(fd, drain, sizeof drain) <= 0)
            break;
    }
    close(fd);
    if (shared_.shutdown) {
        char c = 'x';
        (void)!write(wake_[1], &c, 1);
    }
}

void Server::run()
{
    int next_id = 1;
    while (!shared_.shutdown) {
        pollfd p[2] = {{listen_fd_, POLLIN, 0}, {wake_[0], POLLIN, 0}};
        if (poll(p, 2, -1) < 0) {
            if (errno == EINTR)
                continue;
            return;
        }
        if (p[1].revents || shared_.shutdown)
            return;
        int fd = accept4(listen_fd_, nullptr, nullptr, SOCK_CLOEXEC);
        if (fd < 0)
            continue;
        int max = shared_.opt.max_sessions;
        if (max >= 0 && shared_.sessions.load() >= max) {
            close(fd);   // over the session limit: refused at once (the reference does the same)
            continue;
        }
        ++shared_.sessions;
        std::thread(&Server::serve, this, fd, next_id++).detach();
    }
}

}  // namespace hal::emcrsh
