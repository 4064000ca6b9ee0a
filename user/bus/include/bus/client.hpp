// SPDX-License-Identifier: GPL-2.0-or-later
// client.hpp - hal::bus::Client: the C++ client of the machine bus (docs/bus.md).
//
//   auto c = hal::bus::Client::connect(path);          // HELLO 1 client
//   auto r = c->command("MODE MDI", 5s);                // send, wait for DONE/ERROR
//   auto st = c->status(2s);                            // key -> value
//   for (auto& m : c->take_messages()) ...              // MSG ERROR/DISPLAY/TEXT
//
// Replies are matched by serial; operator messages that arrive meanwhile are queued
// in the client (never lost) until take_messages(). Not thread safe: one thread per
// Client.
#pragma once

#include <chrono>
#include <deque>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bus/protocol.hpp"
#include "hal/result.hpp"

namespace hal::bus {

struct Message {
    std::string kind;   // ERROR, DISPLAY, TEXT
    std::string text;
};

using Status = std::map<std::string, std::string>;

class Client {
public:
    // Connects and says HELLO with the role ("client" or "io"). Errors name the path.
    static Result<std::unique_ptr<Client>> connect(const std::string& path, const std::string& role = "client",
                                                   std::chrono::milliseconds timeout = std::chrono::seconds(5));
    ~Client();
    Client(const Client&) = delete;
    Client& operator=(const Client&) = delete;

    // Sends "<serial> line" and returns the serial (no waiting).
    Result<long> send(const std::string& line);
    // Waits for the serial's DONE (ok) or ERROR (error with task's text). RECEIVED
    // is noted on the way (received()).
    Result<void> wait_done(long serial, std::chrono::milliseconds timeout);
    // send + wait_done.
    Result<void> command(const std::string& line, std::chrono::milliseconds timeout);
    bool received(long serial) const;
    Result<Status> status(std::chrono::milliseconds timeout);

    // Messages received so far (oldest first), removed from the client.
    std::vector<Message> take_messages();
    // Reads whatever arrived within timeout (to collect messages without a command).
    Result<void> pump(std::chrono::milliseconds timeout);

    // The io role: raw lines both ways (IOCMD in, IOACK/IOSTAT/IOTOOLS out).
    Result<void> send_raw(const std::string& line);
    std::vector<std::string> take_raw_lines();

    int fd() const { return fd_; }
    int id() const { return id_; }

private:
    Client() = default;
    Result<void> read_some(int timeout_ms);
    void dispatch(const std::string& line);

    int fd_ = -1;
    int id_ = 0;
    bool io_role_ = false;
    long next_serial_ = 1;
    LineBuffer in_;
    std::map<long, std::string> finished_;   // serial -> "" (DONE) or error text
    std::map<long, bool> received_;
    std::map<long, Status> statuses_;
    long status_serial_ = 0;                  // collecting a STATUS block
    size_t status_left_ = 0;
    Status status_block_;
    std::deque<Message> messages_;
    std::deque<std::string> raw_;
    std::string broken_;                      // why the connection is gone
};

}  // namespace hal::bus
