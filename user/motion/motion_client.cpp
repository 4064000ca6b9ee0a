// SPDX-License-Identifier: GPL-2.0-or-later
// motion_client.cpp - hal::MotionClient (motion_client.hpp).
#include "motion_client.hpp"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <thread>
#include <unistd.h>

#include "rtapi.h"

namespace hal {

namespace {

using Clock = std::chrono::steady_clock;

bool process_alive(int pid)
{
    return pid > 0 && (kill(pid, 0) == 0 || errno == EPERM);
}

}  // namespace

Result<std::unique_ptr<MotionClient>> MotionClient::attach(int key)
{
    auto c = std::make_unique<MotionClient>();
    std::string modname = "motclient" + std::to_string(getpid());

    c->module_id_ = rtapi_init(modname.c_str());
    if (c->module_id_ < 0) {
        int rc = c->module_id_;
        c->module_id_ = 0;
        return Error{rc, std::string("cannot initialize RTAPI: ") + std::strerror(-rc)};
    }
    Error missing{-ENOENT, "motmod is not loaded (no command block with key " +
                               std::to_string(key) + "): 'loadrt motmod' first"};
    // the size motmod asks for: this finds its block (or makes an empty one that
    // goes away with us; the kernel flavor only finds)
    c->shmem_id_ = rtapi_shmem_new(key, c->module_id_, sizeof(motion_shmem));
    if (c->shmem_id_ < 0) {
        int rc = c->shmem_id_;
        c->shmem_id_ = 0;
        if (rc == -ENOENT)
            return missing;
        return Error{rc, "cannot open motion's shared memory (key " + std::to_string(key) +
                             "): " + std::strerror(-rc)};
    }
    void* p = nullptr;
    if (int rc = rtapi_shmem_getptr(c->shmem_id_, &p); rc < 0 || !p)
        return Error{rc < 0 ? rc : -EFAULT, "cannot map motion's shared memory"};
    c->shm_ = static_cast<motion_shmem*>(p);
    if (__atomic_load_n(&c->shm_->hdr.magic, __ATOMIC_ACQUIRE) != MOTION_IF_MAGIC)
        return missing;
    if (c->shm_->hdr.version != MOTION_IF_VERSION || c->shm_->hdr.size != sizeof(motion_shmem))
        return Error{-EPROTO, "motion's shared memory (key " + std::to_string(key) +
                                  ") has another layout version: rebuild this tool"};
    return c;
}

MotionClient::~MotionClient()
{
    if (is_writer_ && shm_) {
        int me = getpid();
        __atomic_compare_exchange_n(&shm_->hdr.writer_pid, &me, 0, false, __ATOMIC_RELEASE,
                                    __ATOMIC_RELAXED);
    }
    if (shmem_id_ > 0)
        rtapi_shmem_delete(shmem_id_, module_id_);
    if (module_id_ > 0)
        rtapi_exit(module_id_);
}

Result<void> MotionClient::claim_writer()
{
    int me = getpid();
    for (int tries = 0; tries < 3; ++tries) {
        int holder = __atomic_load_n(&shm_->hdr.writer_pid, __ATOMIC_ACQUIRE);
        if (holder == me)
            break;
        if (holder != 0 && process_alive(holder))
            return Error{-EBUSY, "another process (pid " + std::to_string(holder) +
                                     ") is sending motion commands"};
        if (__atomic_compare_exchange_n(&shm_->hdr.writer_pid, &holder, me, false,
                                        __ATOMIC_ACQ_REL, __ATOMIC_ACQUIRE)) {
            is_writer_ = true;
            return ok();
        }
    }
    if (__atomic_load_n(&shm_->hdr.writer_pid, __ATOMIC_ACQUIRE) == me) {
        is_writer_ = true;
        return ok();
    }
    return Error{-EBUSY, "another process is sending motion commands"};
}

Result<int> MotionClient::send(motion_command cmd, std::chrono::milliseconds timeout,
                               long force_number)
{
    if (!is_writer_)
        if (auto r = claim_writer(); !r)
            return r.error();
    uint32_t num = force_number >= 0 ? static_cast<uint32_t>(force_number)
                                     : __atomic_load_n(&shm_->status.commandNumEcho, __ATOMIC_ACQUIRE) + 1;
    cmd.commandNum = 0;
    // every field first, the number last: the handler takes the command when it changes
    std::memcpy(&shm_->command, &cmd, offsetof(motion_command, commandNum));
    std::memcpy(reinterpret_cast<char*>(&shm_->command) + offsetof(motion_command, joint),
                reinterpret_cast<const char*>(&cmd) + offsetof(motion_command, joint),
                sizeof(cmd) - offsetof(motion_command, joint));
    __atomic_store_n(&shm_->command.commandNum, num, __ATOMIC_RELEASE);
    auto deadline = Clock::now() + timeout;
    while (__atomic_load_n(&shm_->status.commandNumEcho, __ATOMIC_ACQUIRE) != num) {
        if (Clock::now() > deadline)
            return Error{-ETIMEDOUT, "motion did not take the command within " +
                                         std::to_string(timeout.count()) +
                                         " ms: is motion-command-handler on a running thread?"};
        std::this_thread::sleep_for(std::chrono::microseconds(100));
    }
    return static_cast<int>(__atomic_load_n(&shm_->status.commandStatus, __ATOMIC_ACQUIRE));
}

Result<motion_status> MotionClient::status(std::chrono::milliseconds timeout) const
{
    motion_status s;
    auto deadline = Clock::now() + timeout;
    for (;;) {
        uint32_t head = __atomic_load_n(&shm_->status.head, __ATOMIC_ACQUIRE);
        uint32_t tail = __atomic_load_n(&shm_->status.tail, __ATOMIC_ACQUIRE);
        if (head == tail) {
            std::memcpy(&s, const_cast<const motion_status*>(&shm_->status), sizeof(s));
            __atomic_thread_fence(__ATOMIC_ACQUIRE);
            if (__atomic_load_n(&shm_->status.head, __ATOMIC_ACQUIRE) == head &&
                s.head == s.tail && s.head == head)
                return s;
        }
        if (Clock::now() > deadline)
            return Error{-ETIMEDOUT, "no consistent motion status within " +
                                         std::to_string(timeout.count()) + " ms"};
        std::this_thread::sleep_for(std::chrono::microseconds(50));
    }
}

std::vector<std::string> MotionClient::take_errors(unsigned* overflow)
{
    std::vector<std::string> out;
    motion_error_ring* r = &shm_->error;
    uint32_t head = __atomic_load_n(&r->head, __ATOMIC_ACQUIRE);
    uint32_t tail = __atomic_load_n(&r->tail, __ATOMIC_ACQUIRE);
    if (head - tail > MOTION_ERR_NUM)  // damaged tail: take what the ring holds
        tail = head - MOTION_ERR_NUM;
    for (; tail != head; ++tail) {
        const char* m = r->msg[tail % MOTION_ERR_NUM];
        out.emplace_back(m, strnlen(m, MOTION_ERR_LEN));
    }
    __atomic_store_n(&r->tail, tail, __ATOMIC_RELEASE);
    if (overflow)
        *overflow = __atomic_exchange_n(&r->overflow, 0u, __ATOMIC_ACQ_REL);
    return out;
}

const char* motion_state_name(int state)
{
    switch (state) {
    case MOTION_DISABLED: return "DISABLED";
    case MOTION_FREE: return "FREE";
    case MOTION_TELEOP: return "TELEOP";
    case MOTION_COORD: return "COORD";
    default: return "?";
    }
}

const char* motion_cmd_status_name(int status)
{
    switch (status) {
    case MOTION_CMD_OK: return "OK";
    case MOTION_CMD_UNKNOWN: return "UNKNOWN_COMMAND";
    case MOTION_CMD_INVALID: return "INVALID_COMMAND";
    case MOTION_CMD_INVALID_PARAMS: return "INVALID_PARAMS";
    case MOTION_CMD_BAD_EXEC: return "BAD_EXEC";
    default: return "?";
    }
}

}  // namespace hal
