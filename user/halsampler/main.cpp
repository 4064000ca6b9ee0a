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
    unsigned long long printed = 0;

    while (!hal::stop_requested()) {
        const hal_fifo_value* rec = hal_fifo_read_slot(f.hdr(), f.data());
        if (!rec) {
            if (std::fflush(out.get()) != 0)
                break;
            if (!f.is_alive())
                return fail("sampler FIFO " + std::to_string(opt.channel) +
                            " was removed (sampler unloaded)");
            hal::nap();
            continue;
        }
        if (rec[HAL_FIFO_REC_FLAGS].u & HAL_FIFO_GAP)
            std::fputs("overrun\n", out.get());
        std::string line = hal::format_sample(cfg, rec, opt.tag);
        hal_fifo_read_done(f.hdr());
        if (std::fputs(line.c_str(), out.get()) < 0)
            break;
        if (opt.count && ++printed >= opt.count) {
            if (std::fflush(out.get()) != 0)
                break;
            return 0;
        }
    }
    if (std::ferror(out.get()) || std::fflush(out.get()) != 0)
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
