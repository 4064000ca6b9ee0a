// SPDX-License-Identifier: GPL-2.0-or-later
// shuttlexpress(1): Contour Design ShuttleXpress devices as HAL pins shuttlexpress.N.*,
// read through /dev/hidraw*. Without arguments every hidraw device is probed; with
// arguments only the named ones. Runs until SIGTERM/SIGINT.
#include <fcntl.h>
#include <glob.h>
#include <linux/hidraw.h>
#include <poll.h>
#include <signal.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "hal.h"
#include "shuttle_report.hpp"

namespace {

using namespace hal::shuttle;

volatile sig_atomic_t stop_requested = 0;

void on_signal(int) { stop_requested = 1; }

struct Pins {
    hal_bit_t* button[button_count];
    hal_bit_t* button_not[button_count];
    hal_s32_t* counts;
    hal_s32_t* spring_s32;
    hal_float_t* spring_f;
};

struct Shuttle {
    std::string path;
    int fd = -1;
    Pins* pins = nullptr;
    JogCounter jog;
};

// An open fd if 'path' is a ShuttleXpress; -1 (with a message when 'named') otherwise.
int probe(const std::string& path, bool named)
{
    int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) {
        if (named || errno == EACCES)
            std::fprintf(stderr, "shuttlexpress: cannot open %s: %s%s\n", path.c_str(), std::strerror(errno),
                         errno == EACCES ? " (see UDEV in shuttlexpress(1))" : "");
        return -1;
    }
    hidraw_devinfo info = {};
    if (ioctl(fd, HIDIOCGRAWINFO, &info) < 0 || (info.vendor & 0xffff) != vendor_id ||
        (info.product & 0xffff) != product_id) {
        if (named)
            std::fprintf(stderr, "shuttlexpress: %s is not a ShuttleXpress (0b33:0020)\n", path.c_str());
        close(fd);
        return -1;
    }
    return fd;
}

int export_pins(Pins* p, int id, int n)
{
    int rc = 0;
    for (int b = 0; b < button_count && !rc; b++) {
        rc = hal_pin_bit_newf(HAL_OUT, &p->button[b], id, "shuttlexpress.%d.button-%d", n, b);
        if (!rc)
            rc = hal_pin_bit_newf(HAL_OUT, &p->button_not[b], id, "shuttlexpress.%d.button-%d-not", n, b);
        if (!rc)
            *p->button_not[b] = true;
    }
    if (!rc)
        rc = hal_pin_s32_newf(HAL_OUT, &p->counts, id, "shuttlexpress.%d.counts", n);
    if (!rc)
        rc = hal_pin_s32_newf(HAL_OUT, &p->spring_s32, id, "shuttlexpress.%d.spring-wheel-s32", n);
    if (!rc)
        rc = hal_pin_float_newf(HAL_OUT, &p->spring_f, id, "shuttlexpress.%d.spring-wheel-f", n);
    return rc;
}

void apply(Shuttle& s, const uint8_t (&raw)[report_size])
{
    Report r = decode_report(raw);
    for (int b = 0; b < button_count; b++) {
        *s.pins->button[b] = r.buttons[b];
        *s.pins->button_not[b] = !r.buttons[b];
    }
    *s.pins->counts = s.jog.update(r.jog);
    *s.pins->spring_s32 = r.spring;
    *s.pins->spring_f = r.spring / 7.0;
}

constexpr const char* usage =
    "usage: shuttlexpress [DEVICE ...]\n"
    "  DEVICE: a /dev/hidrawN to use; without any, every /dev/hidraw* that is a\n"
    "          ShuttleXpress (USB 0b33:0020) is used. Pins: shuttlexpress.N.*\n";

}  // namespace

int main(int argc, char** argv)
{
    for (int i = 1; i < argc; i++)
        if (std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0) {
            std::fputs(usage, stdout);
            return 0;
        }
    std::vector<std::string> paths;
    bool named = argc > 1;
    for (int i = 1; i < argc; i++)
        paths.push_back(argv[i]);
    if (!named) {
        glob_t g;
        if (glob("/dev/hidraw*", 0, nullptr, &g) == 0)
            for (size_t i = 0; i < g.gl_pathc; i++)
                paths.push_back(g.gl_pathv[i]);
        globfree(&g);
    }
    std::vector<Shuttle> shuttles;
    for (const std::string& p : paths) {
        int fd = probe(p, named);
        if (fd >= 0)
            shuttles.push_back(Shuttle{p, fd, nullptr, {}});
        else if (named)
            return 1;
    }
    if (shuttles.empty()) {
        std::fprintf(stderr, "shuttlexpress: no ShuttleXpress found among /dev/hidraw*\n");
        return 1;
    }
    struct sigaction sa = {};
    sa.sa_handler = on_signal;
    sigaction(SIGTERM, &sa, nullptr);
    sigaction(SIGINT, &sa, nullptr);
    int id = hal_init("shuttlexpress");
    if (id < 0)
        return 1;
    for (size_t n = 0; n < shuttles.size(); n++) {
        shuttles[n].pins = static_cast<Pins*>(hal_malloc(sizeof(Pins)));
        if (!shuttles[n].pins || export_pins(shuttles[n].pins, id, static_cast<int>(n)) < 0) {
            hal_exit(id);
            return 1;
        }
    }
    hal_ready(id);
    while (!stop_requested) {
        std::vector<pollfd> fds;
        for (const Shuttle& s : shuttles)
            fds.push_back({s.fd, POLLIN, 0});
        if (poll(fds.data(), fds.size(), 100) < 0)
            continue;
        for (size_t n = 0; n < shuttles.size(); n++) {
            Shuttle& s = shuttles[n];
            if (s.fd < 0 || !(fds[n].revents & (POLLIN | POLLERR | POLLHUP)))
                continue;
            uint8_t raw[report_size];
            ssize_t got = read(s.fd, raw, sizeof(raw));
            if (got == static_cast<ssize_t>(report_size)) {
                apply(s, raw);
            } else if (got < 0 && errno != EAGAIN && errno != EINTR) {
                std::fprintf(stderr, "shuttlexpress: %s: %s; its pins keep their last values\n", s.path.c_str(),
                             std::strerror(errno));
                close(s.fd);
                s.fd = -1;
            }
        }
    }
    for (Shuttle& s : shuttles)
        if (s.fd >= 0)
            close(s.fd);
    hal_exit(id);
    return 0;
}
