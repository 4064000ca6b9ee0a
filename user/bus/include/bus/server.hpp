// SPDX-License-Identifier: GPL-2.0-or-later
// server.hpp - the task side of the machine bus: a listening Unix-domain socket,
// the connected clients with their input line buffers and output queues. Single
// threaded: the owner calls poll_once() from its loop; complete lines come back
// through the Handler. A client that sends garbage gets error replies; one that does
// not read its replies (output over MAX_OUTPUT) or breaks the protocol badly is
// dropped; neither affects the others.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bus/protocol.hpp"
#include "hal/result.hpp"

namespace hal::bus {

enum class Role { Client, Io };

class Server {
public:
    struct Handler {
        virtual ~Handler() = default;
        // A well-formed command from a client (role Client).
        virtual void on_command(int client, const Request& req) = 0;
        // A line from the io client (IOACK / IOSTAT / IOTOOLS and its lines).
        virtual void on_io_line(int client, const std::string& line) = 0;
        virtual void on_connect(int client, Role role) = 0;
        virtual void on_disconnect(int client, Role role) = 0;
    };

    static constexpr size_t MAX_OUTPUT = 4u << 20;   // bytes queued to one client
    static constexpr int MAX_CLIENTS = 64;
    static constexpr int MAX_BAD_LINES = 100;        // in a row, then the client is dropped

    // Creates the socket at path (its directory too, mode 0750; refused if it exists
    // with other owner or group/world write). A live server on the path: error.
    static Result<std::unique_ptr<Server>> listen(const std::string& path);
    ~Server();
    Server(const Server&) = delete;
    Server& operator=(const Server&) = delete;

    // Waits up to timeout_ms for input, accepts, reads, calls the handler, writes.
    void poll_once(int timeout_ms, Handler& h);

    void send_line(int client, const std::string& line);
    void reply(int client, long serial, const std::string& what);   // "RECEIVED", "DONE", "ERROR text"
    void send_status(int client, long serial, const StatusLines& st);
    // MSG kind text to every client (the io client excluded).
    void broadcast(const std::string& kind, const std::string& text);
    bool is_connected(int client) const { return clients_.count(client) != 0; }
    int io_client() const;   // -1 when no io client is connected
    const std::string& path() const { return path_; }
    size_t client_count() const { return clients_.size(); }

private:
    struct Conn {
        int fd = -1;
        bool hello = false;
        Role role = Role::Client;
        LineBuffer in;
        std::string out;
        int bad_lines = 0;
        bool closing = false;   // flush what is queued, then close
    };
    Server() = default;
    void accept_one(Handler& h);
    void read_from(int id, Conn& c, Handler& h);
    void handle_line(int id, Conn& c, const std::string& line, Handler& h);
    void flush(Conn& c);
    void send_line_to(Conn& c, const std::string& line);
    void drop(int id, Handler& h);
    void bad_line(int id, Conn& c, long serial, const std::string& why);

    int listen_fd_ = -1;
    std::string path_;
    std::map<int, Conn> clients_;
    int next_id_ = 1;
};

}  // namespace hal::bus
