// SPDX-License-Identifier: GPL-2.0-or-later
// bus_test.cpp - the machine bus: request parsing, line buffering, the server under
// garbage (fuzz-like: random bytes, over-long lines, wrong version, a client leaving
// mid-line) while a well-behaved client keeps being served, and the client library.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <random>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <thread>
#include <unistd.h>

#include "bus/client.hpp"
#include "bus/protocol.hpp"
#include "bus/server.hpp"

using namespace hal::bus;

TEST(BusProtocol, ParsesCommands)
{
    auto r = parse_request("12 mode mdi");
    ASSERT_TRUE(r) << r.error().message;
    EXPECT_EQ(r->serial, 12);
    EXPECT_EQ(r->verb, "MODE");
    ASSERT_EQ(r->args.size(), 1u);
    EXPECT_EQ(r->args[0], "mdi");

    auto m = parse_request("3 MDI   G0 X1  Y2  ");
    ASSERT_TRUE(m);
    ASSERT_EQ(m->args.size(), 1u);
    EXPECT_EQ(m->args[0], "G0 X1  Y2");   // rest of line, trailing blanks dropped

    auto o = parse_request("4 OPEN /tmp/a file.ngc");
    ASSERT_TRUE(o);
    EXPECT_EQ(o->args[0], "/tmp/a file.ngc");
    EXPECT_TRUE(parse_request("5 RUN"));
    EXPECT_TRUE(parse_request("5 RUN 12"));
}

TEST(BusProtocol, RefusesBadLines)
{
    EXPECT_EQ(parse_request("x MODE MDI").error().message, "bad serial 'x' (a number 1..2147483647)");
    EXPECT_FALSE(parse_request("0 PING"));
    EXPECT_FALSE(parse_request("-1 PING"));
    EXPECT_FALSE(parse_request("99999999999 PING"));
    EXPECT_EQ(parse_request("7").error().message, "no command after serial 7");
    EXPECT_EQ(parse_request("7 FLY").error().message, "unknown command 'FLY'");
    EXPECT_EQ(parse_request("7 MODE").error().message, "MODE: needs 1 argument (MANUAL|AUTO|MDI), got 0");
    EXPECT_EQ(parse_request("7 MODE A B").error().message, "MODE: needs 1 argument (MANUAL|AUTO|MDI), got 2");
    EXPECT_EQ(parse_request("7 MDI").error().message, "MDI: needs 1 argument (G-CODE LINE), got 0");
    EXPECT_EQ(parse_request(std::string("7 PING\x01")).error().message, "control characters in the line");
    EXPECT_EQ(parse_request("").error().message, "empty line");
}

TEST(BusProtocol, SplitsAndSanitizes)
{
    auto w = split_words("  a  b\tc  ");
    ASSERT_EQ(w.size(), 3u);
    EXPECT_EQ(w[2], "c");
    auto r = split_words("a b c d", 2);
    ASSERT_EQ(r.size(), 2u);
    EXPECT_EQ(r[1], "b c d");
    EXPECT_EQ(sanitize("a\nb\x1b"), "a?b?");
    EXPECT_EQ(sanitize("abcdef", 3), "abc...");
}

TEST(BusProtocol, LineBufferDropsOverlongLines)
{
    LineBuffer b;
    bool too_long = false;
    b.append("1 PING\n2 ST", 11);
    auto l = b.next(&too_long);
    ASSERT_TRUE(l);
    EXPECT_EQ(*l, "1 PING");
    EXPECT_FALSE(b.next(&too_long));
    b.append("ATUS\r\n", 6);
    l = b.next(&too_long);
    ASSERT_TRUE(l);
    EXPECT_EQ(*l, "2 STATUS");
    std::string big(MAX_LINE + 10, 'x');
    b.append(big.data(), big.size());
    EXPECT_FALSE(b.next(&too_long));
    EXPECT_TRUE(too_long);
    EXPECT_LT(b.pending(), MAX_LINE);   // not kept
    b.append("yyy\n3 PING\n", 11);       // the rest of the long line, then a good one
    l = b.next(&too_long);
    ASSERT_TRUE(l);
    EXPECT_EQ(*l, "3 PING");
}

TEST(BusProtocol, SocketPathRules)
{
    EXPECT_EQ(resolve_socket_path("/tmp/x.sock", "").value(), "/tmp/x.sock");
    std::string a = default_socket_path("/nonexistent/a.ini");
    std::string b = default_socket_path("/nonexistent/b.ini");
    EXPECT_NE(a, b);
    EXPECT_NE(a.find("/emcbus-" + std::to_string(getuid()) + "/"), std::string::npos);
    EXPECT_FALSE(resolve_socket_path(std::string(120, 'a'), ""));
}

namespace {

// A test handler: every command is answered RECEIVED + DONE (FAIL -> ERROR), STATUS
// with two lines; io lines are counted.
struct EchoHandler : Server::Handler {
    Server* srv = nullptr;
    std::atomic<int> commands{0}, io_lines{0}, connects{0}, disconnects{0};
    void on_command(int c, const Request& r) override
    {
        ++commands;
        if (r.verb == "STATUS") {
            srv->send_status(c, r.serial, {{"task.state", "ON"}, {"task.mode", "MDI"}});
            return;
        }
        srv->reply(c, r.serial, "RECEIVED");
        if (r.verb == "MDI" && r.args[0] == "SHOUT")
            srv->broadcast("DISPLAY", "hello all");   // before DONE: the sender has it when done
        srv->reply(c, r.serial, r.verb == "MDI" && r.args[0] == "FAIL" ? "ERROR failed on purpose" : "DONE");
    }
    void on_io_line(int, const std::string&) override { ++io_lines; }
    void on_connect(int, Role) override { ++connects; }
    void on_disconnect(int, Role) override { ++disconnects; }
};

struct ServerFixture : ::testing::Test {
    std::string dir, path;
    std::unique_ptr<Server> srv;
    EchoHandler h;
    std::atomic<bool> stop{false};
    std::thread loop;

    void SetUp() override
    {
        char tmpl[] = "/tmp/bus_test.XXXXXX";
        dir = mkdtemp(tmpl);
        path = dir + "/run/bus.sock";
        auto s = Server::listen(path);
        ASSERT_TRUE(s) << s.error().message;
        srv = std::move(*s);
        h.srv = srv.get();
        loop = std::thread([this] {
            while (!stop)
                srv->poll_once(5, h);
        });
    }
    void TearDown() override
    {
        stop = true;
        if (loop.joinable())
            loop.join();
        srv.reset();
        std::string cmd = "rm -rf " + dir;
        ASSERT_EQ(std::system(cmd.c_str()), 0);
    }
    int raw_connect()
    {
        int fd = socket(AF_UNIX, SOCK_STREAM, 0);
        sockaddr_un a{};
        a.sun_family = AF_UNIX;
        std::snprintf(a.sun_path, sizeof a.sun_path, "%s", path.c_str());
        EXPECT_EQ(connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a), 0);
        timeval tv{2, 0};
        setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
        return fd;
    }
    static std::string read_all(int fd)
    {
        std::string out;
        char buf[4096];
        for (;;) {
            ssize_t n = read(fd, buf, sizeof buf);
            if (n <= 0)
                break;
            out.append(buf, static_cast<size_t>(n));
        }
        return out;
    }
};

}  // namespace

TEST_F(ServerFixture, SocketIsOwnerAndGroupOnly)
{
    struct stat st;
    ASSERT_EQ(stat(path.c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0660u);
    ASSERT_EQ(stat((dir + "/run").c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0007, 0u);
    // a second server on the same path is refused while this one lives
    auto again = Server::listen(path);
    ASSERT_FALSE(again);
    EXPECT_NE(again.error().message.find("another task already serves"), std::string::npos);
}

TEST(BusServer, RefusesWorldWritableDirectory)
{
    char tmpl[] = "/tmp/bus_test.XXXXXX";
    std::string dir = mkdtemp(tmpl);
    chmod(dir.c_str(), 0777);
    auto s = Server::listen(dir + "/bus.sock");
    ASSERT_FALSE(s);
    EXPECT_NE(s.error().message.find("world-writable"), std::string::npos);
    rmdir(dir.c_str());
}

TEST_F(ServerFixture, ClientLibraryCommandsStatusMessages)
{
    auto c1 = Client::connect(path);
    ASSERT_TRUE(c1) << c1.error().message;
    auto c2 = Client::connect(path);
    ASSERT_TRUE(c2);
    EXPECT_TRUE((*c1)->command("MODE MDI", std::chrono::seconds(2)));
    auto bad = (*c1)->command("MDI FAIL", std::chrono::seconds(2));
    ASSERT_FALSE(bad);
    EXPECT_EQ(bad.error().message, "failed on purpose");
    auto st = (*c2)->status(std::chrono::seconds(2));
    ASSERT_TRUE(st);
    EXPECT_EQ(st->at("task.state"), "ON");
    EXPECT_EQ(st->at("task.mode"), "MDI");
    EXPECT_TRUE((*c1)->command("MDI SHOUT", std::chrono::seconds(2)));
    // the broadcast reaches both, queued until taken
    ASSERT_TRUE((*c2)->pump(std::chrono::seconds(2)));
    for (auto* c : {c1->get(), c2->get()}) {
        auto m = c->take_messages();
        ASSERT_EQ(m.size(), 1u);
        EXPECT_EQ(m[0].kind, "DISPLAY");
        EXPECT_EQ(m[0].text, "hello all");
    }
}

TEST_F(ServerFixture, WrongHelloIsRefused)
{
    int fd = raw_connect();
    std::string hello = "HELLO 2 client\n";
    ASSERT_EQ(write(fd, hello.data(), hello.size()), static_cast<ssize_t>(hello.size()));
    EXPECT_EQ(read_all(fd), "HELLO ERROR protocol version '2' not supported (this is 1)\n");
    close(fd);
    fd = raw_connect();
    std::string junk = "GET / HTTP/1.0\n";
    ASSERT_EQ(write(fd, junk.data(), junk.size()), static_cast<ssize_t>(junk.size()));
    EXPECT_EQ(read_all(fd).rfind("HELLO ERROR the first line must be", 0), 0u);
    close(fd);
    auto io1 = Client::connect(path, "io");
    ASSERT_TRUE(io1);
    auto io2 = Client::connect(path, "io");
    ASSERT_FALSE(io2);
    EXPECT_NE(io2.error().message.find("an io client is already connected"), std::string::npos);
}

TEST_F(ServerFixture, GarbageNeverDisturbsAnotherClient)
{
    auto good = Client::connect(path);
    ASSERT_TRUE(good);
    std::mt19937 rng(1234);   // fixed seed: the same garbage every run
    for (int round = 0; round < 40; ++round) {
        int fd = raw_connect();
        std::string data = round % 3 ? "HELLO 1 client\n" : "";
        size_t n = rng() % (round % 5 == 0 ? 3 * MAX_LINE : 600);
        for (size_t i = 0; i < n; ++i) {
            unsigned r = rng() % 100;
            data += r < 8 ? '\n' : r < 12 ? static_cast<char>(rng() % 32) : r < 20 ? ' ' :
                    r < 30 ? static_cast<char>('0' + rng() % 10) : static_cast<char>(rng() % 256);
        }
        if (round % 4 == 1)
            data += "1 MDI G0 X1";   // a client leaving in the middle of a line
        ssize_t w = write(fd, data.data(), data.size());
        (void)w;
        if (round % 2)
            shutdown(fd, SHUT_WR);
        close(fd);
        // the well-behaved client is served every time
        ASSERT_TRUE((*good)->command("PING", std::chrono::seconds(2))) << "round " << round;
    }
    auto st = (*good)->status(std::chrono::seconds(2));
    ASSERT_TRUE(st);
    EXPECT_EQ(st->at("task.state"), "ON");
}

TEST_F(ServerFixture, BadLinesGetErrorsNamingTheProblem)
{
    int fd = raw_connect();
    std::string data = "HELLO 1 client\nfoo\n5 FLY\n6 MODE\n" + std::string(MAX_LINE + 5, 'z') + "\n7 PING\n";
    ASSERT_EQ(write(fd, data.data(), data.size()), static_cast<ssize_t>(data.size()));
    shutdown(fd, SHUT_WR);
    std::string out = read_all(fd);
    close(fd);
    EXPECT_NE(out.find("0 ERROR bad serial 'foo'"), std::string::npos) << out;
    EXPECT_NE(out.find("5 ERROR unknown command 'FLY'"), std::string::npos);
    EXPECT_NE(out.find("6 ERROR MODE: needs 1 argument"), std::string::npos);
    EXPECT_NE(out.find("0 ERROR line too long (more than 4096 bytes)"), std::string::npos);
    EXPECT_NE(out.find("7 DONE"), std::string::npos);
}

TEST_F(ServerFixture, EndlessGarbageIsCutOff)
{
    int fd = raw_connect();
    std::string hello = "HELLO 1 client\n";
    ASSERT_EQ(write(fd, hello.data(), hello.size()), static_cast<ssize_t>(hello.size()));
    std::string bad;
    for (int i = 0; i < Server::MAX_BAD_LINES + 10; ++i)
        bad += "x\n";
    ssize_t w = write(fd, bad.data(), bad.size());
    (void)w;
    std::string out = read_all(fd);   // the server closes: read_all returns
    close(fd);
    EXPECT_NE(out.find("too many bad lines, closing the connection"), std::string::npos);
}
