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

int drop_requests = 0;                    // "drop N": requests still to be ignored

// One stdin command (see the top of the file); false for "quit" or when a new
// pseudo-terminal cannot be made.
bool run_command(const std::string& line, modbus_mapping_t* map, modbus_t* ctx, Pty& pty,
                 const std::string& link)
{
    char cmd[32] = "";
    long a = 0, b = 0;
    int n = std::sscanf(line.c_str(), "%31s %li %li", cmd, &a, &b);
    std::string c = cmd;
    if (c == "quit")
        return false;
    if (c == "set" && n == 3 && a >= 0 && a < 0x2200) {
        map->tab_registers[a] = static_cast<uint16_t>(b);
    } else if (c == "drop" && n == 2) {
        drop_requests = static_cast<int>(a);
    } else if (c == "hangup") {
        close_pty(pty);
        if (!open_pty(link, pty)) {
            std::fprintf(stderr, "gs2_sim: cannot make a pseudo-terminal at %s: %s\n", link.c_str(),
                         std::strerror(errno));
            return false;
        }
        modbus_set_socket(ctx, pty.master);
    } else if (n > 0) {
        std::fprintf(stderr, "gs2_sim: unknown command: %s\n", line.c_str());
    }
    std::printf("ok %s\n", cmd);
    std::fflush(stdout);
    return true;
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
    uint8_t query[MODBUS_RTU_MAX_ADU_LENGTH];
    std::string pending;                  // stdin read so far, up to an incomplete line
    for (;;) {
        pollfd fds[2] = {{STDIN_FILENO, POLLIN, 0}, {pty.master, POLLIN, 0}};
        if (poll(fds, 2, -1) < 0) {
            if (errno == EINTR)
                continue;
            break;
        }
        if (fds[0].revents) {
            // Read what is there and run every whole line in it: a test sends several
            // commands at once, and buffered stdio (fgets) would keep all but the first
            // in its buffer, out of poll()'s sight, until more input came.
            char buf[512];
            ssize_t got = read(STDIN_FILENO, buf, sizeof(buf));
            if (got < 0 && errno == EINTR)
                continue;
            if (got <= 0)
                break;
            pending.append(buf, static_cast<size_t>(got));
            bool quit = false;
            for (size_t nl; !quit && (nl = pending.find('\n')) != std::string::npos;) {
                std::string line = pending.substr(0, nl);
                pending.erase(0, nl + 1);
                quit = !run_command(line, map, ctx, pty, link);
            }
            if (quit)
                break;
            continue;                     // poll again: "hangup" may have replaced pty.master
        }
        if (fds[1].revents & POLLIN) {
            int rc = modbus_receive(ctx, query);
            if (rc <= 0)
                continue;                 // not for us, or a broken frame: the master times out
            if (drop_requests > 0) {
                drop_requests--;
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
