// SPDX-License-Identifier: GPL-2.0-or-later
// halsampler(1): copy samples from a sampler(9) FIFO to stdout or a file.
// Exit status: 0 after printing COUNT samples (-n); 1 on an initialization or
// write error, or when terminated (so always 1 without -n).
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <span>

#include "fifo_attach.hpp"
#include "sample_format.hpp"
#include "sampler_options.hpp"

namespace {

struct FileCloser {
    void operator()(std::FILE* f) const noexcept
    {
        if (f && f != stdout)
            std::fclose(f);
    }
};
using FilePtr = std::unique_ptr<std::FILE, FileCloser>;

int fail(const std::string& message)
{
    std::fprintf(stderr, "halsampler: %s\n", message.c_str());
    return 1;
}

// Output collects in one big buffer written with a single fwrite when it is nearly
// full or the FIFO is empty (issue 20: no per-sample library or system call).
class OutBuffer {
public:
    explicit OutBuffer(std::FILE* f) : f_(f), buf_(new char[capacity]) {}
    char* room()
    {
        if (capacity - used_ < hal::max_sample_line + 8)
            flush_data();
        return buf_.get() + used_;
    }
    void commit(char* end) { used_ = static_cast<size_t>(end - buf_.get()); }
    // Hand everything to the file; false on a write error.
    bool flush()
    {
        flush_data();
        return ok_ && std::fflush(f_) == 0;
    }

private:
    static constexpr size_t capacity = 1 << 20;
    void flush_data()
    {
        if (used_ && std::fwrite(buf_.get(), 1, used_, f_) != used_)
            ok_ = false;
        used_ = 0;
    }
    std::FILE* f_;
    std::unique_ptr<char[]> buf_;  // not zero-filled: a megabyte of memset per run
    size_t used_ = 0;
    bool ok_ = true;
};

int run(const hal::SamplerOptions& opt)
{
    hal::install_stop_handlers();
    auto fifo = hal::FifoAttachment::open({"halsampler", "sampler", SAMPLER_SHMEM_KEY},
                                          opt.channel);
    if (!fifo)
        return fail(fifo.error().message);
    FilePtr out{opt.filename.empty() ? stdout : std::fopen(opt.filename.c_str(), "w")};
    if (!out)
        return fail(opt.filename + ": " + std::strerror(errno));
    hal::FifoAttachment& f = **fifo;
    std::string cfg(f.cfg());
    hal_fifo_hdr* h = f.hdr();
    const rtapi_u32 slots = h->slots;  // checked by open(): geometry_ok
    const rtapi_u32 rec_words = hal_fifo_rec_words(h->num_pins);
    unsigned long long printed = 0;
    OutBuffer buf(out.get());

    while (!hal::stop_requested()) {
        // One look at the producer's index for many records, and 'out' handed back
        // every 256 of them, so the realtime side gets its room back while we format.
        rtapi_u32 pos = h->out;  // ours: no other writer
        rtapi_u32 in = __atomic_load_n(&h->in, __ATOMIC_ACQUIRE);
        if (pos >= slots || in >= slots || in == pos) {
            if (!buf.flush())
                break;
            if (!f.is_alive())
                return fail("sampler FIFO " + std::to_string(opt.channel) +
                            " was removed (sampler unloaded)");
            hal::nap();
            continue;
        }
        rtapi_u32 avail = hal_fifo_count(in, pos, slots);
        for (rtapi_u32 k = 0; k < avail; k++) {
            const hal_fifo_value* rec = f.data() + static_cast<size_t>(pos) * rec_words;
            char* p = buf.room();
            if (rec[HAL_FIFO_REC_FLAGS].u & HAL_FIFO_GAP) {
                std::memcpy(p, "overrun\n", 8);
                p += 8;
            }
            buf.commit(hal::format_sample_to(p, cfg, rec, opt.tag));
            pos = hal_fifo_next(pos, slots);
            bool done = opt.count && ++printed >= opt.count;
            if (done || (k & 255) == 255 || k + 1 == avail)
                __atomic_store_n(&h->out, pos, __ATOMIC_RELEASE);
            if (done)
                return buf.flush() ? 0 : fail(std::string("write error: ") + std::strerror(errno));
        }
    }
    if (!buf.flush() || std::ferror(out.get()))
        return fail(std::string("write error: ") + std::strerror(errno));
    return 1;  // terminated before COUNT samples (or without -n)
}

}  // namespace

int main(int argc, char** argv)
{
    try {
        auto opt = hal::parse_sampler_options(std::span<char* const>(argv, argc));
        if (!opt) {
            std::fprintf(stderr, "halsampler: %s\n%s", opt.error().message.c_str(),
                         hal::sampler_usage);
            return 1;
        }
        if (opt->help) {
            std::fputs(hal::sampler_usage, stdout);
            return 0;
        }
        return run(*opt);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "halsampler: %s\n", e.what());
        return 1;
    }
}
