// SPDX-License-Identifier: GPL-2.0-or-later
// rsh_client - the emcrsh tests' TCP client (the VM has only busybox).
//
//   rsh_client [-t SECONDS] HOST PORT < script
//
// Each script line is sent with "\r\n" on connection 1, or on connection N when it
// starts with "@N " (opened on first use). After every line the client makes sure the
// server has answered everything: it sends "GET PLAT" and reads up to the
// "PLAT Linux\r\n" reply, which it removes (with its echo) again. So the output is
// deterministic: what the server sent in reply to each line, in script order, line
// ends made visible ("\r", "\n"; other control bytes "\xNN"), a real newline after
// each run of line ends, prefixed "N| " for connections other than 1.
// Directives: "@N !close" closes connection N (shutdown, then read to EOF);
// "@N !garbage COUNT SEED" sends COUNT lines of pseudo-random bytes (no CR/LF, may
// hold NUL), then prints only how many reply bytes came back;
// "@N !long BYTES" sends one line of BYTES 'x' characters; "!sh COMMAND" runs a shell
// command at that point (every earlier line answered; its output goes in between),
// so waits for the machine and checks of pins keep their place in the script.
// A connection the server closed prints "N| (closed)". Exit status 0, 1 on a
// timeout (-t, default 60 s per line) or a connection error, 2 bad usage.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <map>
#include <string>

namespace {

struct Conn {
    int fd = -1;
    bool closed = false;
};

std::string host, port;
double timeout_s = 60;
std::map<int, Conn> conns;

int open_conn()
{
    // numeric IPv4 only: the static build in the VM has no name service
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(static_cast<uint16_t>(std::atoi(port.c_str())));
    if (inet_pton(AF_INET, host.c_str(), &a.sin_addr) != 1) {
        std::fprintf(stderr, "rsh_client: '%s' is not an IPv4 address\n", host.c_str());
        std::exit(2);
    }
    int fd = socket(AF_INET, SOCK_STREAM, 0);
    if (fd < 0 || connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) {
        std::fprintf(stderr, "rsh_client: cannot connect to %s:%s: %s\n", host.c_str(), port.c_str(),
                     std::strerror(errno));
        std::exit(1);
    }
    return fd;
}

void send_all(Conn& c, const std::string& s)
{
    size_t off = 0;
    while (off < s.size() && !c.closed) {
        ssize_t n = send(c.fd, s.data() + off, s.size() - off, MSG_NOSIGNAL);
        if (n <= 0) {
            c.closed = true;   // the server went away: reading will show it
            return;
        }
        off += static_cast<size_t>(n);
    }
}

size_t count(const std::string& s, const std::string& what)
{
    size_t n = 0;
    for (size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + what.size()))
        ++n;
    return n;
}

// Reads until 'got' ends with 'want' and holds it at least 'times' times (want
// empty: until EOF). false on timeout.
bool read_until(Conn& c, std::string& got, const std::string& want, size_t times = 1)
{
    int left_ms = static_cast<int>(timeout_s * 1000);
    char buf[4096];
    while (left_ms > 0) {
        if (!want.empty() && got.size() >= want.size() && got.compare(got.size() - want.size(), want.size(), want) == 0 &&
            count(got, want) >= times)
            return true;
        pollfd p{c.fd, POLLIN, 0};
        int r = poll(&p, 1, 100);
        left_ms -= 100;
        if (r <= 0)
            continue;
        ssize_t n = read(c.fd, buf, sizeof buf);
        if (n <= 0) {
            c.closed = true;
            return true;
        }
        got.append(buf, static_cast<size_t>(n));
    }
    return false;
}

std::string visible(const std::string& s)
{
    std::string o;
    for (size_t i = 0; i < s.size(); ++i) {
        unsigned char ch = static_cast<unsigned char>(s[i]);
        if (ch == '\r' || ch == '\n') {
            o += ch == '\r' ? "\\r" : "\\n";
            if (i + 1 == s.size() || (s[i + 1] != '\r' && s[i + 1] != '\n'))
                o += '\n';
        } else if (ch < 32 || ch >= 127) {
            char b[8];
            std::snprintf(b, sizeof b, "\\x%02x", ch);
            o += b;
        } else {
            o += static_cast<char>(ch);
        }
    }
    if (!o.empty() && o.back() != '\n')
        o += '\n';
    return o;
}

void print(int id, const std::string& text)
{
    std::string v = visible(text);
    std::string prefix = id == 1 ? "" : std::to_string(id) + "| ";
    size_t i = 0;
    while (i < v.size()) {
        size_t e = v.find('\n', i);
        std::cout << prefix << v.substr(i, e - i) << "\n";
        i = e + 1;
    }
    std::cout.flush();
}

// After a request: everything the server sent in reply, without the sync's.
bool sync_and_print(int id, Conn& c, bool count_only, bool line_gets_plat)
{
    std::string got;
    const std::string mark = "PLAT Linux\r\n";
    send_all(c, "GET PLAT\r\n");
    // a request that is itself GET PLAT is answered with the mark too: wait for both
    if (!read_until(c, got, c.closed ? "" : mark, line_gets_plat ? 2 : 1)) {
        std::fprintf(stderr, "rsh_client: connection %d: no reply within %g s\n", id, timeout_s);
        return false;
    }
    if (!c.closed && got.size() >= mark.size()) {
        got.erase(got.size() - mark.size());
        const std::string echo = "GET PLAT\r\n";
        if (got.size() >= echo.size() && got.compare(got.size() - echo.size(), echo.size(), echo) == 0)
            got.erase(got.size() - echo.size());
    }
    if (count_only)
        print(id, "(" + std::to_string(got.size()) + " bytes of replies)");
    else if (!got.empty())
        print(id, got);
    if (c.closed) {
        print(id, "(closed)");
        close(c.fd);
    }
    return true;
}

}  // namespace

int main(int argc, char** argv)
{
    int i = 1;
    if (argc > 2 && std::string(argv[1]) == "-t") {
        timeout_s = std::atof(argv[2]);
        i = 3;
    }
    if (argc - i != 2) {
        std::fprintf(stderr, "usage: rsh_client [-t SECONDS] HOST PORT < script\n");
        return 2;
    }
    host = argv[i];
    port = argv[i + 1];
    std::string line;
    while (std::getline(std::cin, line)) {
        if (line.rfind("!sh ", 0) == 0) {
            std::cout.flush();
            int rc = std::system(line.c_str() + 4);
            (void)rc;   // the command prints what matters
            continue;
        }
        int id = 1;
        if (line.size() > 2 && line[0] == '@' && std::isdigit(static_cast<unsigned char>(line[1]))) {
            size_t sp = line.find(' ');
            id = std::atoi(line.c_str() + 1);
            line = sp == std::string::npos ? "" : line.substr(sp + 1);
        }
        Conn& c = conns[id];
        if (c.fd < 0)
            c.fd = open_conn();
        if (c.closed) {
            print(id, "(closed)");
            continue;
        }
        bool count_only = false;
        if (line == "!close") {
            shutdown(c.fd, SHUT_WR);
            std::string got;
            read_until(c, got, "");
            if (!got.empty())
                print(id, got);
            print(id, "(closed)");
            close(c.fd);
            c.closed = true;
            continue;
        }
        if (line.rfind("!garbage ", 0) == 0) {
            unsigned long count = 0, seed = 1;
            std::sscanf(line.c_str() + 9, "%lu %lu", &count, &seed);
            std::string g;
            for (unsigned long k = 0; k < count; ++k) {
                seed = seed * 6364136223846793005ull + 1442695040888963407ull;
                size_t len = 1 + (seed >> 33) % 200;
                for (size_t b = 0; b < len; ++b) {
                    seed = seed * 6364136223846793005ull + 1442695040888963407ull;
                    char ch = static_cast<char>(seed >> 56);
                    g += (ch == '\r' || ch == '\n') ? '#' : ch;
                }
                g += "\r\n";
            }
            send_all(c, g);
            count_only = true;
        } else if (line.rfind("!long ", 0) == 0) {
            send_all(c, std::string(std::strtoul(line.c_str() + 6, nullptr, 10), 'x') + "\r\n");
        } else {
            send_all(c, line + "\r\n");
        }
        std::string u;
        for (char ch : line)
            u += static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
        bool gets_plat = u.find("GET") != std::string::npos && u.find("PLAT") != std::string::npos;
        if (!sync_and_print(id, c, count_only, gets_plat))
            return 1;
    }
    for (auto& [id, c] : conns)
        if (!c.closed)
            close(c.fd);
    return 0;
}
