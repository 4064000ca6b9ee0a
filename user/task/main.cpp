// SPDX-License-Identifier: GPL-2.0-or-later
// milltask - the task controller (docs/task.md). Started by the launcher as
// `halcmd loadusr -Wn inihal milltask -ini INI`: it makes the HAL component `inihal`
// ready once the machine bus is listening, so the launcher's next steps and every
// client find it.
//
//   milltask -ini FILE [-bus PATH]
#include <csignal>
#include <cstdio>
#include <cstring>
#include <string>

#include "bus/program_args.hpp"
#include "bus/server.hpp"
#include "hal.h"
#include "ini/ini_file.hpp"
#include "motion_client.hpp"
#include "position_file.hpp"
#include "rs274/interp.hpp"
#include "task.hpp"

int main(int argc, char** argv)
{
    hal::bus::ProgramArgs args;
    if (int rc = hal::bus::parse_program_args("milltask", argc, argv, args); rc >= 0)
        return rc;
    const std::string& ini_path = args.ini_path;
    const std::string& bus_path = args.bus_path;
    auto ini = hal::ini::IniFile::load(ini_path);
    if (!ini) {
        std::fprintf(stderr, "milltask: %s\n", ini.error().message.c_str());
        return 1;
    }
    auto cfg = hal::task::read_task_config(*ini);
    if (!cfg) {
        std::fprintf(stderr, "milltask: %s\n", cfg.error().message.c_str());
        return 1;
    }
    if (!cfg->position_file.empty()) {
        // the joints where the last run left them (position_file.hpp)
        auto pos = hal::task::read_position_file(cfg->position_file);
        if (!pos) {
            std::fprintf(stderr, "milltask: [TRAJ]POSITION_FILE: %s\n", pos.error().message.c_str());
            return 1;
        }
        cfg->motor_offset = hal::task::motor_offsets_for(*pos);
    }
    rs274::Config icfg;
    std::string err;
    if (!rs274::Config::from_ini(ini_path, icfg, err)) {
        std::fprintf(stderr, "milltask: %s\n", err.c_str());
        return 1;
    }
    icfg.in_task = true;
    auto path = hal::bus::resolve_socket_path(bus_path, ini_path);
    if (!path) {
        std::fprintf(stderr, "milltask: %s\n", path.error().message.c_str());
        return 1;
    }
    auto motion = hal::MotionClient::attach();
    if (!motion) {
        std::fprintf(stderr, "milltask: %s\n", motion.error().message.c_str());
        return 1;
    }
    if (auto r = (*motion)->claim_writer(); !r) {
        std::fprintf(stderr, "milltask: %s\n", r.error().message.c_str());
        return 1;
    }
    auto server = hal::bus::Server::listen(*path);
    if (!server) {
        std::fprintf(stderr, "milltask: %s\n", server.error().message.c_str());
        return 1;
    }
    volatile std::sig_atomic_t* stop = hal::bus::install_stop_signals();

    // the ini.* pins; #<_hal[...]> in the start-up code reads HAL already
    int id = hal_init("inihal");
    if (id < 0) {
        std::fprintf(stderr, "milltask: hal_init(inihal) failed: %s\n", std::strerror(-id));
        return 1;
    }
    auto pins = hal::task::IniHal::create(id, *cfg);
    if (!pins) {
        std::fprintf(stderr, "milltask: %s\n", pins.error().message.c_str());
        hal_exit(id);
        return 1;
    }
    hal::task::Task task(std::move(*cfg), std::move(icfg), std::move(*motion), std::move(*server));
    task.set_inihal(std::move(*pins));
    if (!task.init(err)) {
        std::fprintf(stderr, "milltask: %s\n", err.c_str());
        hal_exit(id);
        return 1;
    }
    // `loadusr -Wn inihal` waits for this component: ready = the bus is listening
    hal_ready(id);
    task.run(stop);
    hal_exit(id);
    return 0;
}
