// SPDX-License-Identifier: GPL-2.0-or-later
// fifo_attach.cpp - attach to a sampler/streamer FIFO through the ULAPI RTAPI
// (rtapi_init + rtapi_shmem_new with the same sizes the realtime side used).
#include "fifo_attach.hpp"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <unistd.h>

namespace hal {

namespace {

std::string hex_key(int key)
{
    char buf[16];
    std::snprintf(buf, sizeof(buf), "0x%08x", static_cast<unsigned>(key));
    return buf;
}

volatile std::sig_atomic_t stop_flag = 0;

extern "C" void on_stop_signal(int) { stop_flag = 1; }

}  // namespace

Result<std::unique_ptr<FifoAttachment>> FifoAttachment::open(const FifoKind& kind, int channel)
{
    auto fifo = std::make_unique<FifoAttachment>();
    std::string who = std::string(kind.component) + " FIFO " + std::to_string(channel);
    // Module names must be unique among the RTAPI users of this session.
    std::string modname = std::string(kind.tool) + std::to_string(getpid());

    fifo->module_id_ = rtapi_init(modname.c_str());
    if (fifo->module_id_ < 0) {
        int rc = fifo->module_id_;
        fifo->module_id_ = 0;
        return Error{rc, std::string("cannot initialize RTAPI: ") + std::strerror(-rc)};
    }
    Error missing{-ENOENT, "no " + who + " exists; load it first, e.g. 'loadrt " +
                               kind.component + " depth=100 cfg=ff'"};
    // The same size as the realtime side asks for, so this either finds its
    // segment or makes an empty one (the kernel flavor only finds).
    int hdr_key = kind.base_key + channel;
    fifo->hdr_id_ = rtapi_shmem_new(hdr_key, fifo->module_id_, sizeof(hal_fifo_hdr));
    if (fifo->hdr_id_ < 0) {
        int rc = fifo->hdr_id_;
        fifo->hdr_id_ = 0;
        if (rc == -ENOENT)
            return missing;
        return Error{rc, "cannot open " + who + " (shared memory key " + hex_key(hdr_key) +
                             "): " + std::strerror(-rc)};
    }
    void* p = nullptr;
    if (int rc = rtapi_shmem_getptr(fifo->hdr_id_, &p); rc < 0 || !p)
        return Error{rc < 0 ? rc : -EFAULT, "cannot map " + who};
    fifo->hdr_ = static_cast<hal_fifo_hdr*>(p);
    if (!hal_fifo_is_published(fifo->hdr_))
        return missing;
    if (!hal_fifo_geometry_ok(fifo->hdr_))
        return Error{-EINVAL, who + " has a damaged header"};
    int data_key = kind.base_key + HAL_FIFO_DATA_KEY_OFFSET + channel;
    fifo->data_id_ = rtapi_shmem_new(data_key, fifo->module_id_, fifo->hdr_->data_size);
    if (fifo->data_id_ < 0) {
        int rc = fifo->data_id_;
        fifo->data_id_ = 0;
        return Error{rc, "cannot open the records of " + who + " (shared memory key " +
                             hex_key(data_key) + "): " + std::strerror(-rc)};
    }
    if (int rc = rtapi_shmem_getptr(fifo->data_id_, &p); rc < 0 || !p)
        return Error{rc < 0 ? rc : -EFAULT, "cannot map the records of " + who};
    fifo->data_ = static_cast<hal_fifo_value*>(p);
    return fifo;
}

FifoAttachment::~FifoAttachment()
{
    if (data_id_ > 0)
        rtapi_shmem_delete(data_id_, module_id_);
    if (hdr_id_ > 0)
        rtapi_shmem_delete(hdr_id_, module_id_);
    if (module_id_ > 0)
        rtapi_exit(module_id_);
}

void install_stop_handlers()
{
    struct sigaction sa{};
    sa.sa_handler = on_stop_signal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = 0;  // no SA_RESTART: a blocking read returns on the signal
    sigaction(SIGINT, &sa, nullptr);
    sigaction(SIGTERM, &sa, nullptr);
    std::signal(SIGPIPE, SIG_IGN);
}

bool stop_requested() { return stop_flag != 0; }

void nap()
{
    // 10 ms: short against a FIFO of a few hundred samples at 1 kHz.
    struct timespec ts{0, 10 * 1000 * 1000};
    nanosleep(&ts, nullptr);
}

std::optional<long long> parse_number(std::string_view text, long long min, long long max)
{
    if (text.empty() || text.size() > 20)
        return std::nullopt;
    if (!(text[0] == '-' || (text[0] >= '0' && text[0] <= '9')))
        return std::nullopt;  // strtoll would skip blanks and accept '+'
    std::string s(text);
    char* end = nullptr;
    errno = 0;
    long long v = std::strtoll(s.c_str(), &end, 10);
    if (errno || *end || v < min || v > max)
        return std::nullopt;
    return v;
}

}  // namespace hal
