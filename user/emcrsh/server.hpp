// SPDX-License-Identifier: GPL-2.0-or-later
// server.hpp - emcrsh's TCP side: the listening socket, a thread per connection
// (each with its own bus connection and Session), the session limit, SHUTDOWN.
#pragma once

#include <string>

#include "hal/result.hpp"
#include "session.hpp"

namespace hal::emcrsh {

class Server {
public:
    Server(Shared& shared, std::string bus_path) : shared_(shared), bus_path_(std::move(bus_path)) {}
    ~Server();
    // Binds every address on the port (0: a free one); returns the port bound.
    Result<int> listen(int port);
    // Accepts connections until a session's SHUTDOWN; returns then.
    void run();

private:
    void serve(int fd, int id);

    Shared& shared_;
    std::string bus_path_;
    int listen_fd_ = -1;
    int wake_[2] = {-1, -1};   // a session's SHUTDOWN wakes the accept loop
};

}  // namespace hal::emcrsh
