// SPDX-License-Identifier: GPL-2.0-or-later
// gs2_sim - a simulated GS2 drive for tests: a libmodbus RTU server on the master side
// of a pseudo-terminal whose slave is linked at LINK, so gs2_vfd -d LINK talks to it.
//   gs2_sim LINK [TARGET]      commands on stdin, one per line:
//     set REG VALUE   set a holding register (0x2100 status block ...), hex or decimal
//     drop N          ignore the next N requests (the master sees timeouts)
//     hangup          close the pseudo-terminal and make a new one at LINK (cable
//                     pulled and put back: the master sees an I/O error)
//     quit
// Prints "ready" when LINK exists, and "write REG VALUE" (hex REG) for each register
// written. The drive model: 0x2102 (frequency command) follows 0x091A, 0x2103 (output
// frequency) follows it while 0x091B (run) is 1.
#include <fcntl.h>
#include <modbus.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "gs2_drive.hpp"

namespace {

using namespace hal::gs2;

struct Pty {
    int master = -1;
    int slave = -1;        // kept open so the master never sees a hangup between clients
};

bool open_pty(const std::string& link, Pty& p)
{
    p.master = posix_openpt(O_RDWR | O_NOCTTY);
    if (p.master < 0 || grantpt(p.master) < 0 || unlockpt(p.master) < 0)
        return false;
    const char* name = ptsname(p.master);
    p.slave = open(name, O_RDWR | O_NOCTTY);
    if (p.slave < 0)
        return false;
    termios t;
    tcgetattr(p.slave, &t);
    cfmakeraw(&t);
    tcsetattr(p.slave, TCSANOW, &t);
    std::string tmp = link + ".new";
    unlink(tmp.c_str());
    return symlink(name, tmp.c_str()) == 0 && rename(tmp.c_str(), link.c_str()) == 0;
}

void close_pty(Pty& p)
{
    close(p.master);
    close(p.slave);
    p = {};
}

void model(modbus_mapping_t* m)
{
    uint16_t* r = m->tab_registers;
    r[status_base + st_freq_cmd] = r[reg_speed];
    r[status_base + st_freq_out] = r[reg_run] ? r[reg_speed] : 0;
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc < 2 || argc > 3) {
        std::fprintf(stderr, "usage: gs2_sim LINK [TARGET]\n");
        return 1;
    }
    std::string link = argv[1];
    int target = argc == 3 ? std::atoi(argv[2]) : 1;
    modbus_mapping_t* map = modbus_mapping_new(0, 0, 0x2200, 0);
    modbus_t* ctx = modbus_new_rtu("/dev/null", 38400, 'O', 8, 1);   // the device is never opened
    if (!map || !ctx) {
        std::fprintf(stderr, "gs2_sim: %s\n", modbus_strerror(errno));
        return 1;
    }
    modbus_set_slave(ctx, target);
    Pty pty;
    if (!open_pty(link, pty)) {
        std::fprintf(stderr, "gs2_sim: cannot make a pseudo-terminal at %s: %s\n", link.c_str(), std::strerror(errno));
        return 1;
    }
    modbus_set_socket(ctx, pty.master);
    std::printf("ready\n");
    std::fflush(stdout);
    int drop = 0;
    uint8_t query[MODBUS_RTU_MAX_ADU_LENGTH];
    char line[256];
    for (;;) {
        pollfd fds[2] = {{STDIN_FILENO, POLLIN, 0}, {pty.master, POLLIN, 0}};
        if (poll(fds, 2, -1) < 0) {
            if (errno == EINTR)
                continue;
            break;
        }
        if (fds[0].revents) {
            if (!std::fgets(line, sizeof(line), stdin))
                break;
            char cmd[32] = "";
            long a = 0, b = 0;
            int n = std::sscanf(line, "%31s %li %li", cmd, &a, &b);
            std::string c = cmd;
            if (c == "quit")
                break;
            if (c == "set" && n == 3 && a >= 0 && a < 0x2200) {
                map->tab_registers[a] = static_cast<uint16_t>(b);
            } else if (c == "drop" && n == 2) {
                drop = static_cast<int>(a);
            } else if (c == "hangup") {
                close_pty(pty);
                if (!open_pty(link, pty))
                    return 1;
                modbus_set_socket(ctx, pty.master);
            } else if (n > 0) {
                std::fprintf(stderr, "gs2_sim: unknown command: %s", line);
            }
            std::printf("ok %s\n", cmd);
            std::fflush(stdout);
        }
        if (fds[1].revents & POLLIN) {
            int rc = modbus_receive(ctx, query);
            if (rc <= 0)
                continue;                 // not for us, or a broken frame: the master times out
            if (drop > 0) {
                drop--;
                continue;
            }
            modbus_reply(ctx, query, rc, map);
            if (query[1] == 0x06) {       // write single register: address, value
                int reg = (query[2] << 8) | query[3];
                int val = (query[4] << 8) | query[5];
                model(map);
                std::printf("write 0x%04X %d\n", reg, val);
                std::fflush(stdout);
            }
        }
    }
    close_pty(pty);
    unlink(link.c_str());
    modbus_free(ctx);
    modbus_mapping_free(map);
    return 0;
}
