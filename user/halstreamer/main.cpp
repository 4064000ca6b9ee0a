// SPDX-License-Identifier: GPL-2.0-or-later
// halstreamer(1): copy lines of values from stdin or a file into a streamer(9)
// FIFO, waiting while it is full. A bad line is reported ("line N: ...") and
// skipped. Exit status: 0 at end of input; 1 on an initialization or read
// error, or when terminated before the input ends.
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <span>

#include "fifo_attach.hpp"
#include "stream_parse.hpp"

namespace {

struct FileCloser {
    void operator()(std::FILE* f) const noexcept
    {
        if (f && f != stdin)
            std::fclose(f);
    }
};
using FilePtr = std::unique_ptr<std::FILE, FileCloser>;

struct LineBuffer {  // getline(3)'s buffer, which it may reallocate
    char* data = nullptr;
    size_t capacity = 0;
    LineBuffer() = default;
    LineBuffer(const LineBuffer&) = delete;
    LineBuffer& operator=(const LineBuffer&) = delete;
    ~LineBuffer() { std::free(data); }
};

int fail(const std::string& message)
{
    std::fprintf(stderr, "halstreamer: %s\n", message.c_str());
    return 1;
}

// Block until the FIFO has room, then store one record. False when stopped
// by a signal or when the streamer went away.
bool put_record(hal::FifoAttachment& f, const std::vector<hal_fifo_value>& values, int channel,
                int& status)
{
    hal_fifo_value* rec;
    while (!(rec = hal_fifo_write_slot(f.hdr(), f.data()))) {
        if (hal::stop_requested())
            return false;
        if (!f.is_alive()) {
            status = fail("streamer FIFO " + std::to_string(channel) +
                          " was removed (streamer unloaded)");
            return false;
        }
        hal::nap();
    }
    rec[HAL_FIFO_REC_SAMPLE].u = 0;
    rec[HAL_FIFO_REC_FLAGS].u = 0;
    for (size_t m = 0; m < values.size(); m++)
        rec[HAL_FIFO_REC_HDR_WORDS + m] = values[m];
    hal_fifo_write_done(f.hdr());
    return true;
}

int run(const hal::StreamerOptions& opt)
{
    hal::install_stop_handlers();
    auto fifo = hal::FifoAttachment::open({"halstreamer", "streamer", STREAMER_SHMEM_KEY},
                                          opt.channel);
    if (!fifo)
        return fail(fifo.error().message);
    FilePtr in{opt.filename.empty() ? stdin : std::fopen(opt.filename.c_str(), "r")};
    if (!in)
        return fail(opt.filename + ": " + std::strerror(errno));
    hal::FifoAttachment& f = **fifo;
    std::string cfg(f.cfg());
    LineBuffer buf;
    unsigned long lineno = 0;
    int status = 1;

    for (;;) {
        errno = 0;
        ssize_t len = getline(&buf.data, &buf.capacity, in.get());
        if (len < 0) {
            if (hal::stop_requested())
                return 1;
            if (std::ferror(in.get()))
                return fail(std::string("read error: ") + std::strerror(errno));
            return 0;  // end of input
        }
        lineno++;
        std::string_view line(buf.data, static_cast<size_t>(len));
        if (hal::is_blank_line(line))
            continue;
        auto values = hal::parse_stream_line(cfg, line);
        if (!values) {
            std::fprintf(stderr, "halstreamer: line %lu: %s\n", lineno,
                         values.error().message.c_str());
            continue;
        }
        if (!put_record(f, *values, opt.channel, status))
            return status;
        if (hal::stop_requested())
            return 1;
    }
}

}  // namespace

int main(int argc, char** argv)
{
    try {
        auto opt = hal::parse_streamer_options(std::span<char* const>(argv, argc));
        if (!opt) {
            std::fprintf(stderr, "halstreamer: %s\n%s", opt.error().message.c_str(),
                         hal::streamer_usage);
            return 1;
        }
        if (opt->help) {
            std::fputs(hal::streamer_usage, stdout);
            return 0;
        }
        return run(*opt);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "halstreamer: %s\n", e.what());
        return 1;
    }
}
