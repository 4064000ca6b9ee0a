// SPDX-License-Identifier: GPL-2.0-or-later
// fifo_attach.hpp - what halsampler and halstreamer share: attaching to the
// shared-memory FIFO of a loaded sampler(9)/streamer(9) (layout in
// kernel/components/streamer_fifo.h), stop-on-signal handling, number parsing.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "hal/result.hpp"
#include "streamer_fifo.h"

namespace hal {

// Which FIFO family a tool talks to.
struct FifoKind {
    const char* tool;       // "halsampler": prefix of messages, RTAPI module name
    const char* component;  // "sampler": named in messages
    int base_key;           // SAMPLER_SHMEM_KEY or STREAMER_SHMEM_KEY
};

// One attached FIFO: the RTAPI module registration and both segments, all
// released by the destructor.
class FifoAttachment {
public:
    static Result<std::unique_ptr<FifoAttachment>> open(const FifoKind& kind, int channel);
    FifoAttachment() = default;
    FifoAttachment(const FifoAttachment&) = delete;
    FifoAttachment& operator=(const FifoAttachment&) = delete;
    ~FifoAttachment();

    hal_fifo_hdr* hdr() const { return hdr_; }
    hal_fifo_value* data() const { return data_; }
    std::string_view cfg() const { return hdr_->cfg; }
    // False once the realtime side unloaded (it clears the magic word).
    bool is_alive() const { return hal_fifo_is_published(hdr_) != 0; }

private:
    int module_id_ = 0;
    int hdr_id_ = 0;
    int data_id_ = 0;
    hal_fifo_hdr* hdr_ = nullptr;
    hal_fifo_value* data_ = nullptr;
};

// SIGINT/SIGTERM set a flag instead of killing the tool, so it can release
// the FIFO and exit with the status its page asks for. SIGPIPE is ignored
// (a closed pipe becomes a write error).
void install_stop_handlers();
bool stop_requested();
// Wait before retrying an empty/full FIFO; returns early on a signal.
void nap();

// Decimal number in [min, max], or nothing.
std::optional<long long> parse_number(std::string_view text, long long min, long long max);

}  // namespace hal
