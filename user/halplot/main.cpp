// SPDX-License-Identifier: GPL-2.0-or-later
// halplot(1): read COUNT samples from a sampler(9) FIFO and have gnuplot draw
// them: one trace per channel, the time axis from the period of the thread that
// runs sampler.N, the legend from the pins feeding the channels.
// Exit status: 0 when the chart was written; 1 otherwise, with a message.
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <span>
#include <string>
#include <vector>

#include "fifo_attach.hpp"
#include "plot_labels.hpp"
#include "plot_options.hpp"
#include "plot_script.hpp"

extern "C" {
#include "hal_query.h"
}

namespace {

namespace fs = std::filesystem;

int fail(const std::string& message)
{
    std::fprintf(stderr, "halplot: %s\n", message.c_str());
    return 1;
}

double value_of(char type, const hal_fifo_value& v)
{
    switch (hal_fifo_type_of(type)) {
    case HAL_FIFO_FLOAT: return v.f;
    case HAL_FIFO_BIT: return v.u ? 1.0 : 0.0;
    case HAL_FIFO_S32: return static_cast<double>(static_cast<int32_t>(v.s));
    case HAL_FIFO_U32: return static_cast<double>(static_cast<uint32_t>(v.u));
    case HAL_FIFO_S64: return static_cast<double>(static_cast<int64_t>(v.s));
    case HAL_FIFO_U64: return static_cast<double>(static_cast<uint64_t>(v.u));
    default: return 0.0;
    }
}

// Runs gnuplot on SCRIPT; its messages go to our stderr.
bool run_gnuplot(const fs::path& script)
{
    pid_t pid = fork();
    if (pid < 0)
        return false;
    if (pid == 0) {
        execlp("gnuplot", "gnuplot", script.c_str(), static_cast<char*>(nullptr));
        std::fprintf(stderr, "halplot: cannot run gnuplot: %s (install gnuplot-nox)\n", std::strerror(errno));
        _exit(127);
    }
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR)
            return false;
    return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

int run(const hal::PlotOptions& opt)
{
    hal::install_stop_handlers();
    auto fifo = hal::FifoAttachment::open({"halplot", "sampler", SAMPLER_SHMEM_KEY}, opt.channel);
    if (!fifo)
        return fail(fifo.error().message);
    hal::FifoAttachment& f = **fifo;
    std::string cfg(f.cfg());
    if (hal_attach() != 0)
        return fail("cannot attach to the HAL shared memory");
    auto ctx = hal::sampler_context(opt.channel, cfg);
    hal_detach();
    if (!ctx)
        return fail(ctx.error().message);

    std::vector<std::vector<double>> rows;
    rows.reserve(opt.count);
    unsigned long gaps = 0;
    while (rows.size() < opt.count) {
        if (hal::stop_requested())
            return fail("interrupted after " + std::to_string(rows.size()) + " samples");
        const hal_fifo_value* rec = hal_fifo_read_slot(f.hdr(), f.data());
        if (!rec) {
            if (!f.is_alive())
                return fail("sampler FIFO " + std::to_string(opt.channel) + " was removed (sampler unloaded)");
            hal::nap();
            continue;
        }
        if (rec[HAL_FIFO_REC_FLAGS].u & HAL_FIFO_GAP)
            gaps++;
        const hal_fifo_value* v = rec + HAL_FIFO_REC_HDR_WORDS;
        std::vector<double> row(cfg.size());
        for (size_t m = 0; m < cfg.size(); m++)
            row[m] = value_of(cfg[m], v[m]);
        hal_fifo_read_done(f.hdr());
        rows.push_back(std::move(row));
    }
    if (gaps)  // the time axis assumes one sample per period
        std::fprintf(stderr, "halplot: warning: %lu overruns: samples were lost, the time axis is compressed there\n",
                     gaps);

    char tmpl[] = "/tmp/halplot.XXXXXX";
    if (!mkdtemp(tmpl))
        return fail(std::string("cannot make a temporary directory: ") + std::strerror(errno));
    fs::path dir = tmpl;
    fs::path data = dir / "samples.dat", script = dir / "plot.gp";
    std::ofstream(data) << hal::plot_data(rows, ctx->period_ns);
    std::ofstream(script) << hal::plot_script(opt, ctx->channels, data.string());
    bool ok = run_gnuplot(script);
    std::error_code ec;
    fs::remove_all(dir, ec);
    if (!ok)
        return fail("gnuplot could not write " + opt.output);
    return 0;
}

}  // namespace

int main(int argc, char** argv)
{
    try {
        auto opt = hal::parse_plot_options(std::span<char* const>(argv, argc));
        if (!opt) {
            std::fprintf(stderr, "halplot: %s\n%s", opt.error().message.c_str(), hal::plot_usage);
            return 1;
        }
        if (opt->help) {
            std::fputs(hal::plot_usage, stdout);
            return 0;
        }
        return run(*opt);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "halplot: %s\n", e.what());
        return 1;
    }
}
