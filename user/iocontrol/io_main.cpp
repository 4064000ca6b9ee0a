// SPDX-License-Identifier: GPL-2.0-or-later
// io (iocontrol) - the I/O controller: HAL component `iocontrol` with the 16
// iocontrol.0.* pins of emcrsh-and-halui.md 2.2, talking to task over the machine bus
// as its io client (docs/bus.md "The io client"). Started by the launcher as
// `halcmd loadusr -Wn iocontrol io -ini INI`, before task: it keeps serving HAL and
// retries the bus until task is there, and again if task goes away.
//
//   io -ini FILE [-bus PATH]
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <string>
#include <thread>

#include "bus/client.hpp"
#include "bus/program_args.hpp"
#include "hal.h"
#include "ini/ini_file.hpp"
#include "io_core.hpp"

using namespace hal;
using namespace std::chrono;

namespace {

struct HalPins {
    hal_bit_t* user_enable_out;
    hal_bit_t* user_request_enable;
    hal_bit_t* emc_enable_in;
    hal_bit_t* coolant_mist;
    hal_bit_t* coolant_flood;
    hal_bit_t* lube;
    hal_bit_t* lube_level;
    hal_bit_t* tool_prepare;
    hal_bit_t* tool_prepared;
    hal_bit_t* tool_change;
    hal_bit_t* tool_changed;
    hal_s32_t* tool_prep_number;
    hal_s32_t* tool_prep_pocket;
    hal_s32_t* tool_prep_index;
    hal_s32_t* tool_number;
    hal_s32_t* tool_from_pocket;
};

int export_pins(HalPins* p, int id)
{
    struct B { hal_bit_t** ptr; hal_pin_dir_t dir; const char* name; };
    struct S { hal_s32_t** ptr; const char* name; };
    const B bits[] = {
        {&p->user_enable_out, HAL_OUT, "user-enable-out"}, {&p->user_request_enable, HAL_OUT, "user-request-enable"},
        {&p->emc_enable_in, HAL_IN, "emc-enable-in"},     {&p->coolant_mist, HAL_OUT, "coolant-mist"},
        {&p->coolant_flood, HAL_OUT, "coolant-flood"},    {&p->lube, HAL_OUT, "lube"},
        {&p->lube_level, HAL_IN, "lube_level"},           {&p->tool_prepare, HAL_OUT, "tool-prepare"},
        {&p->tool_prepared, HAL_IN, "tool-prepared"},     {&p->tool_change, HAL_OUT, "tool-change"},
        {&p->tool_changed, HAL_IN, "tool-changed"},
    };
    const S s32s[] = {
        {&p->tool_prep_number, "tool-prep-number"}, {&p->tool_prep_pocket, "tool-prep-pocket"},
        {&p->tool_prep_index, "tool-prep-index"},   {&p->tool_number, "tool-number"},
        {&p->tool_from_pocket, "tool-from-pocket"},
    };
    for (const B& b : bits)
        if (int rc = hal_pin_bit_newf(b.dir, b.ptr, id, "iocontrol.0.%s", b.name); rc)
            return rc;
    for (const S& s : s32s)
        if (int rc = hal_pin_s32_newf(HAL_OUT, s.ptr, id, "iocontrol.0.%s", s.name); rc)
            return rc;
    return 0;
}

void read_inputs(const HalPins& h, io::IoPins& p)
{
    p.emc_enable_in = *h.emc_enable_in;
    p.lube_level = *h.lube_level;
    p.tool_prepared = *h.tool_prepared;
    p.tool_changed = *h.tool_changed;
}

void write_outputs(HalPins& h, const io::IoPins& p)
{
    *h.user_enable_out = p.user_enable_out;
    *h.user_request_enable = p.user_request_enable;
    *h.coolant_mist = p.coolant_mist;
    *h.coolant_flood = p.coolant_flood;
    *h.lube = p.lube;
    *h.tool_prepare = p.tool_prepare;
    *h.tool_change = p.tool_change;
    *h.tool_prep_number = p.tool_prep_number;
    *h.tool_prep_pocket = p.tool_prep_pocket;
    *h.tool_prep_index = p.tool_prep_index;
    *h.tool_number = p.tool_number;
    *h.tool_from_pocket = p.tool_from_pocket;
}

std::string relative_to(const std::string& ini_path, const std::string& file)
{
    if (file.empty() || file[0] == '/')
        return file;
    size_t slash = ini_path.rfind('/');
    return slash == std::string::npos ? file : ini_path.substr(0, slash + 1) + file;
}

// The bus side: connection, IOCMD in, IOACK/IOSTAT/IOTOOLS out.
class Link {
public:
    explicit Link(std::string path) : path_(std::move(path)) {}

    void cycle(io::IoCore& core, io::IoPins& pins, bool completed, long done_serial)
    {
        if (!client_ && !reconnect(core, pins))
            return;
        if (completed && done_serial > 0)
            send("IOACK " + std::to_string(done_serial) + " DONE");
        if (long c = core.take_cancelled(); c > 0)
            send("IOACK " + std::to_string(c) + " ERROR cancelled");
        if (client_) {
            if (auto r = client_->pump(milliseconds(0)); !r) {
                drop(r.error().message);
                return;
            }
            for (const std::string& line : client_->take_raw_lines())
                handle(line, core, pins);
        }
        if (client_ && (tools_changed_ || completed))
            send_tools(core);
        if (client_) {
            std::string st = core.status_line(pins);
            if (st != last_status_) {
                send("IOSTAT " + st);
                last_status_ = st;
            }
        }
    }

private:
    bool reconnect(io::IoCore& core, io::IoPins& pins)
    {
        auto now = steady_clock::now();
        if (now < next_try_)
            return false;
        next_try_ = now + milliseconds(200);
        auto c = bus::Client::connect(path_, "io", milliseconds(1000));
        if (!c)
            return false;   // task not (yet / any more) there: io keeps serving HAL
        client_ = std::move(*c);
        core.reset_serials();
        last_status_.clear();
        send_tools(core);
        send("IOSTAT " + core.status_line(pins));
        last_status_ = core.status_line(pins);
        return true;
    }

    // task went away (restart, shutdown): io keeps serving HAL and reconnects
    void drop(const std::string&)
    {
        client_.reset();
    }

    void send(const std::string& line)
    {
        if (client_)
            if (auto r = client_->send_raw(line); !r)
                drop(r.error().message);
    }

    void send_tools(io::IoCore& core)
    {
        auto lines = core.table_lines();
        std::string block = "IOTOOLS " + std::to_string(lines.size());
        for (const std::string& l : lines)
            block += "\n" + l;
        send(block);
        tools_changed_ = false;
    }

    void handle(const std::string& line, io::IoCore& core, io::IoPins& pins)
    {
        // IOCMD <n> VERB [ARGS]
        auto w = bus::split_words(line);
        if (w.size() < 3 || w[0] != "IOCMD")
            return;
        long serial = std::strtol(w[1].c_str(), nullptr, 10);
        std::vector<std::string> cmd(w.begin() + 2, w.end());
        if (cmd[0] == "LOAD_TOOL_TABLE" && cmd.size() > 1)
            cmd.resize(2);   // a file name is one word on the wire (task checks it)
        std::string err;
        core.command_handled(serial);   // done, pending or refused: its outputs (if any) are set now
        if (core.has_pending() && cmd[0] != "ABORT" && cmd[0] != "ESTOP_ON" && cmd[0] != "INIT") {
            send("IOACK " + std::to_string(serial) + " ERROR io is busy with a tool change");
            return;
        }
        auto out = core.command(cmd, pins, err);
        if (long c = core.take_cancelled(); c > 0)
            send("IOACK " + std::to_string(c) + " ERROR cancelled");
        if (cmd[0] == "INIT" || cmd[0] == "LOAD_TOOL_TABLE" || cmd[0] == "TOOL_SET_OFFSET" ||
            cmd[0] == "TOOL_SET_NUMBER" || cmd[0] == "TOOL_UNLOAD")
            tools_changed_ = true;
        switch (out) {
        case io::IoCore::Outcome::Done:
            send("IOACK " + std::to_string(serial) + " DONE");
            break;
        case io::IoCore::Outcome::Failed:
            send("IOACK " + std::to_string(serial) + " ERROR " + err);
            break;
        case io::IoCore::Outcome::Pending:
            core.set_pending_serial(serial);
            break;
        }
    }

    std::string path_;
    std::unique_ptr<bus::Client> client_;
    steady_clock::time_point next_try_{};
    std::string last_status_;
    bool tools_changed_ = false;
};

}  // namespace

int main(int argc, char** argv)
{
    bus::ProgramArgs args;
    if (int rc = bus::parse_program_args("io", argc, argv, args); rc >= 0)
        return rc;
    const std::string& ini_path = args.ini_path;
    const std::string& bus_path = args.bus_path;
    auto ini = ini::IniFile::load(ini_path);
    if (!ini) {
        std::fprintf(stderr, "io: %s\n", ini.error().message.c_str());
        return 1;
    }
    auto cycle_s = ini->get_double("EMCIO", "CYCLE_TIME", 0.100);
    auto random = ini->get_bool("EMCIO", "RANDOM_TOOLCHANGER", false);
    if (!cycle_s || !random) {
        std::fprintf(stderr, "io: %s\n", (!cycle_s ? cycle_s.error() : random.error()).message.c_str());
        return 1;
    }
    double period = *cycle_s > 0 ? *cycle_s : 0.100;
    std::string table = relative_to(ini_path, ini->find("EMCIO", "TOOL_TABLE").value_or(""));
    auto path = bus::resolve_socket_path(bus_path, ini_path);
    if (!path) {
        std::fprintf(stderr, "io: %s\n", path.error().message.c_str());
        return 1;
    }

    io::IoCore core(table, *random);
    if (auto r = core.load_table(); !r) {
        std::fprintf(stderr, "io: %s\n", r.error().message.c_str());
        return 1;
    }
    volatile std::sig_atomic_t* stop = bus::install_stop_signals();

    int id = hal_init("iocontrol");
    if (id < 0) {
        std::fprintf(stderr, "io: hal_init(iocontrol) failed: %s\n", std::strerror(-id));
        return 1;
    }
    auto* hp = static_cast<HalPins*>(hal_malloc(sizeof(HalPins)));
    if (!hp || export_pins(hp, id) != 0) {
        std::fprintf(stderr, "io: cannot create the iocontrol.0 pins\n");
        hal_exit(id);
        return 1;
    }
    io::IoPins pins;
    write_outputs(*hp, pins);
    hal_ready(id);

    Link link(*path);
    auto next = steady_clock::now();
    while (!*stop) {
        core.end_cycle(pins);   // the previous cycle's user-request-enable pulse ends
        read_inputs(*hp, pins);
        long serial = core.pending_serial();
        bool completed = core.cycle(pins);
        link.cycle(core, pins, completed, serial);
        write_outputs(*hp, pins);
        next += microseconds(static_cast<long>(period * 1e6));
        auto now = steady_clock::now();
        if (next < now)
            next = now;
        std::this_thread::sleep_until(next);
    }
    hal_exit(id);
    return 0;
}
