// SPDX-License-Identifier: GPL-2.0-or-later
// emcrsh (also installed as linuxcncrsh) - the text-mode control server of emcrsh(1):
// clients connect over TCP (telnet, nc, programs) and drive the machine through task's
// bus. Started by hand, from HAL (loadusr), or by the launcher as the display:
//   emcrsh [OPTIONS] -- -ini INI
// Prints "emcrsh: listening on port N" once it accepts connections. Exit status: 0
// after SHUTDOWN, 2 bad usage, 3 cannot listen or no bus path.
#include <signal.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>

#include "bus/protocol.hpp"
#include "server.hpp"

using namespace hal::emcrsh;

int main(int argc, char** argv)
{
    auto opt = parse_options(argc, argv);
    if (!opt) {
        std::fprintf(stderr, "emcrsh: %s\n%s", opt.error().message.c_str(), usage_text());
        return 2;
    }
    if (opt->help) {
        std::fputs(usage_text(), stdout);
        return 0;
    }
    if (opt->ini.empty()) {
        // emcrsh(1): the INI file defaults to emc.ini; the launcher's environment names it
        const char* env = std::getenv("INI_FILE_NAME");
        opt->ini = env && env[0] ? env : "emc.ini";
    }
    auto bus = hal::bus::resolve_socket_path(opt->bus, opt->ini);
    if (!bus) {
        std::fprintf(stderr, "emcrsh: %s\n", bus.error().message.c_str());
        return 3;
    }
    signal(SIGPIPE, SIG_IGN);
    Shared shared(*opt);
    Server server(shared, *bus);
    auto port = server.listen(opt->port);
    if (!port) {
        std::fprintf(stderr, "emcrsh: cannot listen: %s\n", port.error().message.c_str());
        return 3;
    }
    std::printf("emcrsh: listening on port %d\n", *port);
    std::fflush(stdout);
    server.run();
    std::printf("emcrsh: shut down by an enabled session\n");
    std::fflush(stdout);
    // sessions still waiting on task are cut off with the process
    _exit(0);
}
