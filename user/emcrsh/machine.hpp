// SPDX-License-Identifier: GPL-2.0-or-later
// machine.hpp - what a session needs from task: commands (with emcrsh's waits),
// the status map and operator messages. BusMachine talks to task over the machine bus
// (docs/bus.md), one connection per session; the unit tests use a fake.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "bus/client.hpp"
#include "hal/result.hpp"

namespace hal::emcrsh {

enum class Wait { NONE, RECEIVED, DONE };

class Machine {
public:
    virtual ~Machine() = default;
    // Sends a bus command (docs/bus.md) and waits as asked: NONE not at all, RECEIVED
    // until task accepted it, DONE until it finished. timeout_s <= 0: no limit. An
    // error: refused, failed, timed out or no bus (the text says which).
    virtual Result<void> command(const std::string& line, Wait wait, double timeout_s) = 0;
    // Waits for the last command sent (SET WAIT).
    virtual Result<void> wait_last(Wait wait, double timeout_s) = 0;
    virtual Result<bus::Status> status() = 0;
    // Operator messages and errors of commands not waited for, oldest first.
    virtual std::vector<bus::Message> take_messages() = 0;
};

class BusMachine : public Machine {
public:
    explicit BusMachine(std::string socket_path) : path_(std::move(socket_path)) {}
    Result<void> command(const std::string& line, Wait wait, double timeout_s) override;
    Result<void> wait_last(Wait wait, double timeout_s) override;
    Result<bus::Status> status() override;
    std::vector<bus::Message> take_messages() override;
    // The bus connection's descriptor (-1 when not connected) and reading what
    // arrived, so an idle session keeps draining task's messages.
    int fd() const { return c_ ? c_->fd() : -1; }
    void pump();

private:
    Result<bus::Client*> client();
    Result<void> wait_for(long serial, Wait wait, double timeout_s);
    void reap();
    Result<void> lost(const Error& e);

    std::string path_;
    std::unique_ptr<bus::Client> c_;
    long last_ = 0;                 // serial of the last command sent
    std::vector<long> unwaited_;    // sent, not waited to the end: reaped later
    std::vector<bus::Message> errors_;
};

}  // namespace hal::emcrsh
