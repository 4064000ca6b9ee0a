// SPDX-License-Identifier: GPL-2.0-or-later
// gs2_vfd(1): an Automation Direct GS2 drive as a userspace HAL component. Every
// loop-time seconds: read the status block into the output pins, send speed, run,
// direction and fault reset when they change (all again after a reconnection).
// Errors count in error-count and leave their code in retval; the loop never ends on
// a serial error, only on SIGTERM/SIGINT (halcmd unloadusr).
#include <signal.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <thread>

#include "gs2_drive.hpp"
#include "gs2_link.hpp"
#include "gs2_options.hpp"
#include "gs2_pins.hpp"

namespace {

using namespace hal::gs2;

volatile sig_atomic_t stop_requested = 0;

void on_signal(int) { stop_requested = 1; }

// What was last sent, so unchanged commands are not re-sent every cycle.
struct Sent {
    bool valid = false;            // false: send everything on the next cycle
    uint16_t speed = 0;
    int run = -1, direction = -1;
};

struct Poller {
    const Gs2Options& opts;
    Gs2Pins* p;
    Gs2Link link;
    Sent sent;
    int cycles_since_change = 0;
    double last_speed_cmd = NAN;
    bool link_down = false;        // an outage is reported once, and its end

    void error(const char* what, int rc)
    {
        p->error_count = p->error_count + 1;
        p->retval = rc;
        if (!link_down || opts.verbose)
            std::fprintf(stderr, "%s: %s on %s failed: %s%s\n", opts.name.c_str(), what, opts.device.c_str(),
                         modbus_strerror(-rc), link_down ? "" : "; retrying every loop-time");
        link_down = true;
        sent.valid = false;        // the drive may have restarted: send everything again
    }

    bool write(const char* what, int addr, uint16_t value)
    {
        int rc = link.write_register(addr, value);
        if (rc < 0)
            error(what, rc);
        return rc == 0;
    }

    void poll()
    {
        uint16_t regs[status_count];
        int rc = link.read_registers(status_base, status_count, regs);
        if (rc < 0) {
            error("reading the status registers", rc);
            *p->at_speed = false;
            return;
        }
        if (link_down) {
            std::fprintf(stderr, "%s: the drive on %s answers again\n", opts.name.c_str(), opts.device.c_str());
            link_down = false;
        }
        Status s = decode_status(regs);
        *p->status_1 = s.status1;
        *p->status_2 = s.status2;
        *p->firmware_revision = s.firmware;
        *p->frequency_command = s.freq_cmd;
        *p->frequency_out = s.freq_out;
        *p->output_current = s.current;
        *p->dc_bus_volts = s.dc_bus;
        *p->output_voltage = s.volts_out;
        *p->motor_rpm = s.rpm;
        *p->scale_frequency = s.scale_freq;
        *p->power_factor = s.power_factor;
        *p->load_percentage = s.load;
        *p->is_stopped = s.is_stopped;
        send_commands();
        if (cycles_since_change < 1000000)
            cycles_since_change++;
        *p->at_speed = *p->spindle_on &&
                       at_speed(s.freq_out, s.freq_cmd, p->tolerance, cycles_since_change, p->ack_delay);
    }

    void send_commands()
    {
        double cmd = *p->speed_command;
        if (cmd != last_speed_cmd) {
            last_speed_cmd = cmd;
            cycles_since_change = 0;
        }
        uint16_t speed = speed_to_register(cmd, p->nameplate_hz, p->nameplate_rpm);
        int run = *p->spindle_on ? 1 : 0;
        int dir = direction_register(*p->spindle_fwd, *p->spindle_rev);
        // In order, stopping at the first failure; 'valid' is cleared by error().
        if (!sent.valid || speed != sent.speed) {
            if (!write("setting the speed", reg_speed, speed))
                return;
            sent.speed = speed;
        }
        if (!sent.valid || dir != sent.direction) {
            if (!write("setting the direction", reg_direction, static_cast<uint16_t>(dir)))
                return;
            sent.direction = dir;
        }
        if (!sent.valid || run != sent.run) {
            if (!write("setting run/stop", reg_run, static_cast<uint16_t>(run)))
                return;
            sent.run = run;
        }
        sent.valid = true;
        if (*p->err_reset)
            write("resetting a fault", reg_fault_reset, 1);
    }
};

}  // namespace

int main(int argc, char** argv)
{
    auto opts = parse_gs2_options(std::span<char* const>(argv, static_cast<size_t>(argc)));
    if (!opts) {
        std::fprintf(stderr, "gs2_vfd: %s\n%s", opts.error().message.c_str(), gs2_usage);
        return 1;
    }
    if (opts->help) {
        std::fputs(gs2_usage, stdout);
        return 0;
    }
    struct sigaction sa = {};
    sa.sa_handler = on_signal;
    sigaction(SIGTERM, &sa, nullptr);
    sigaction(SIGINT, &sa, nullptr);

    int id = hal_init(opts->name.c_str());
    if (id < 0) {
        std::fprintf(stderr, "%s: hal_init failed: %s\n", opts->name.c_str(), std::strerror(-id));
        return 1;
    }
    auto* pins = static_cast<Gs2Pins*>(hal_malloc(sizeof(Gs2Pins)));
    if (!pins || export_gs2_pins(pins, id, opts->name) < 0) {
        hal_exit(id);
        return 1;
    }
    hal_ready(id);
    Poller poller{*opts, pins, Gs2Link(*opts), Sent{}, 0, NAN, false};
    auto next = std::chrono::steady_clock::now();
    while (!stop_requested) {
        poller.poll();
        double loop = pins->loop_time;
        if (!(loop >= 0.001) || !(loop <= 60))      // a nonsense setp must not stall or spin
            loop = 0.1;
        next += std::chrono::microseconds(static_cast<long>(loop * 1e6));
        auto now = std::chrono::steady_clock::now();
        if (next < now)
            next = now;
        while (!stop_requested && std::chrono::steady_clock::now() < next)
            std::this_thread::sleep_for(std::min<std::chrono::steady_clock::duration>(
                next - std::chrono::steady_clock::now(), std::chrono::milliseconds(50)));
    }
    if (poller.link.is_open())
        poller.link.write_register(reg_run, 0);   // leave the spindle stopped, best effort
    hal_exit(id);
    return 0;
}
