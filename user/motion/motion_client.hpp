// SPDX-License-Identifier: GPL-2.0-or-later
// motion_client.hpp - hal::MotionClient: userspace side of motmod's command/status
// channel (kernel/motion/motion_if.h): attach to the shared block, claim it as the
// one command writer, send a command and wait for its echo, read a consistent status,
// take queued error messages. Used by motcmd and the tests; the task controller
// (a later issue) is meant to use it too.
#pragma once

#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "hal/result.hpp"
#include "motion_if.h"

namespace hal {

class MotionClient {
public:
    // Attach to motmod's block (key = motmod's key= parameter). Fails with a one-line
    // message when motmod is not loaded or the block is not motmod's.
    static Result<std::unique_ptr<MotionClient>> attach(int key = MOTION_DEFAULT_KEY);
    MotionClient() = default;
    MotionClient(const MotionClient&) = delete;
    MotionClient& operator=(const MotionClient&) = delete;
    ~MotionClient();

    // Become the writer (hdr.writer_pid): refused while another live process holds it.
    Result<void> claim_writer();
    // Send one command (command and its fields; commandNum is set here: the echo + 1,
    // or force_number >= 0 to test motion's sequence check) and wait up to timeout for
    // motion to echo it. Returns the commandStatus (MOTION_CMD_*).
    Result<int> send(motion_command cmd, std::chrono::milliseconds timeout,
                     long force_number = -1);
    // A consistent copy of the status (head == tail around the copy).
    Result<motion_status> status(std::chrono::milliseconds timeout) const;
    // Messages queued since the last call (oldest first), and how many were lost
    // because the ring was full.
    std::vector<std::string> take_errors(unsigned* overflow = nullptr);

private:
    int module_id_ = 0;
    int shmem_id_ = 0;
    motion_shmem* shm_ = nullptr;
    bool is_writer_ = false;
};

// Names for messages: "FREE", "COORD"...
const char* motion_state_name(int state);
const char* motion_cmd_status_name(int status);

}  // namespace hal
