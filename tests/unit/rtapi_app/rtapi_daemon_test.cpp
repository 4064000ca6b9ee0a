// SPDX-License-Identifier: GPL-2.0-or-later
// rtapi_daemon_test.cpp - the real rtapi_app, started on demand by the client
// library on an instance of its own, loading HAL-free test modules; plus garbage
// on the raw socket, signals and stale sockets.
#include "rtapi_client.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>

namespace {

constexpr const char* testmod = "rtapi_app_testmod";

std::string socket_file(const std::string& instance)
{
    return "/tmp/rtapi-" + std::to_string(getuid()) + "-" + instance + ".sock";
}

bool file_exists(const std::string& path)
{
    return access(path.c_str(), F_OK) == 0;
}

// Each test gets its own RTAPI_INSTANCE, so tests may run in parallel.
class RtapiDaemon : public ::testing::Test {
protected:
    void SetUp() override
    {
        static int serial = 0;
        instance_ = "ut" + std::to_string(getpid()) + "-" + std::to_string(++serial);
        setenv("RTAPI_INSTANCE", instance_.c_str(), 1);
        setenv("RTAPI_APP", RTAPI_APP_PATH, 1);
        setenv("HAL_RTLIB_DIR", TESTMOD_DIR, 1);
        sock_ = socket_file(instance_);
    }
    void TearDown() override
    {
        EXPECT_TRUE(hal::rtapi_shutdown());
        EXPECT_FALSE(file_exists(sock_));
    }

    int connect_raw() const
    {
        int fd = socket(AF_UNIX, SOCK_STREAM, 0);
        sockaddr_un addr{};
        addr.sun_family = AF_UNIX;
        std::strncpy(addr.sun_path, sock_.c_str(), sizeof(addr.sun_path) - 1);
        EXPECT_EQ(connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof(addr)), 0)
            << std::strerror(errno);
        return fd;
    }

    // Send raw bytes (then end our side if asked) and read the whole reply.
    std::string exchange(const std::string& bytes, bool end_request = true) const
    {
        int fd = connect_raw();
        size_t sent = 0;
        while (sent < bytes.size()) {
            ssize_t n = send(fd, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
            if (n <= 0)
                break;  // the daemon stopped reading an overlong request: fine
            sent += static_cast<size_t>(n);
        }
        if (end_request)
            shutdown(fd, SHUT_WR);
        std::string reply;
        char buf[1024];
        for (;;) {
            pollfd p{fd, POLLIN, 0};
            if (poll(&p, 1, 10000) <= 0)
                break;
            ssize_t n = read(fd, buf, sizeof(buf));
            if (n <= 0)
                break;
            reply.append(buf, static_cast<size_t>(n));
        }
        close(fd);
        return reply;
    }

    pid_t daemon_pid() const
    {
        int fd = connect_raw();
        ucred peer{};
        socklen_t len = sizeof(peer);
        EXPECT_EQ(getsockopt(fd, SOL_SOCKET, SO_PEERCRED, &peer, &len), 0);
        close(fd);
        return peer.pid;
    }

    std::vector<std::string> list() const
    {
        auto r = hal::rtapi_list();
        EXPECT_TRUE(r) << (r ? "" : r.error().message);
        return r ? *r : std::vector<std::string>{};
    }

    std::string instance_;
    std::string sock_;
};

std::string load_error(const std::string& module, const std::vector<std::string>& args)
{
    auto r = hal::rtapi_load(module, args);
    EXPECT_FALSE(r);
    return r ? "" : r.error().message;
}

TEST_F(RtapiDaemon, ListAndRunningDoNotStartADaemon)
{
    EXPECT_FALSE(hal::rtapi_running());
    EXPECT_TRUE(list().empty());
    EXPECT_FALSE(hal::rtapi_running());
    EXPECT_FALSE(file_exists(sock_));
}

TEST_F(RtapiDaemon, LoadStartsTheDaemonAndTheLastUnloadEndsIt)
{
    auto r = hal::rtapi_load(testmod, {"count=2"});
    ASSERT_TRUE(r) << r.error().message;
    EXPECT_TRUE(hal::rtapi_running());
    EXPECT_EQ(list(), std::vector<std::string>{testmod});
    auto u = hal::rtapi_unload(testmod);
    ASSERT_TRUE(u) << u.error().message;
    EXPECT_FALSE(hal::rtapi_running());
    EXPECT_FALSE(file_exists(sock_));
}

TEST_F(RtapiDaemon, AppliesParametersBeforeInit)
{
    // fail=5 makes the module show its parameters in its error message.
    auto r = hal::rtapi_load(testmod, {"fail=5", "count=7", "values=1,2,3", "label=hello",
                                       "count=9"});
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, -5);
    EXPECT_EQ(r.error().message,
              "rtapi_app_testmod: count=9 values=1,2,3,0 label=hello; "
              "rtapi_app_testmod: rtapi_app_main failed: Input/output error (-5)");
    EXPECT_TRUE(list().empty());
}

TEST_F(RtapiDaemon, ReportsAFailedInitWithItsMessageAndErrno)
{
    auto r = hal::rtapi_load(testmod, {"fail=22"});
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, -22);
    EXPECT_EQ(r.error().message,
              "rtapi_app_testmod: count=1 values=0,0,0,0 label=none; "
              "rtapi_app_testmod: rtapi_app_main failed: Invalid argument (-22)");
    // Nothing stayed loaded: the same module loads again, with fresh parameters.
    auto again = hal::rtapi_load(testmod, {});
    EXPECT_TRUE(again) << again.error().message;
}

TEST_F(RtapiDaemon, RefusesAnUnknownParameter)
{
    EXPECT_EQ(load_error(testmod, {"count=1", "foo=2"}), "rtapi_app_testmod: unknown parameter 'foo'");
    EXPECT_TRUE(list().empty());
}

TEST_F(RtapiDaemon, RefusesABadParameterValue)
{
    std::string msg = load_error(testmod, {"count=many"});
    EXPECT_EQ(msg.rfind("rtapi_app_testmod: ", 0), 0u) << msg;
    EXPECT_TRUE(list().empty());
}

TEST_F(RtapiDaemon, RefusesArgumentsWithoutValue)
{
    EXPECT_EQ(load_error(testmod, {"count"}),
              "rtapi_app_testmod: parameter 'count' has no value (use count=VALUE)");
    EXPECT_FALSE(hal::rtapi_running());  // refused before any daemon was needed
}

TEST_F(RtapiDaemon, RefusesASecondLoadOfTheSameModule)
{
    ASSERT_TRUE(hal::rtapi_load(testmod, {}));
    auto r = hal::rtapi_load(testmod, {});
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, -EEXIST);
    EXPECT_EQ(r.error().message, "rtapi_app_testmod: already loaded");
    EXPECT_EQ(list(), std::vector<std::string>{testmod});
}

TEST_F(RtapiDaemon, RefusesMissingAndBrokenModules)
{
    EXPECT_EQ(load_error("no_such_module", {}),
              std::string("no_such_module: no such realtime module (no_such_module.so is not in the module directory)"));
    EXPECT_EQ(load_error("rtapi_app_nomain", {}),
              "rtapi_app_nomain: rtapi_app_nomain.so has no rtapi_app_main()");
    std::string msg = load_error("rtapi_app_badsym", {});
    EXPECT_NE(msg.find("rtapi_app_badsym: dlopen: "), std::string::npos) << msg;  // LinuxCNC's prefix
    EXPECT_NE(msg.find("undefined symbol: rtapi_app_badsym_missing"), std::string::npos) << msg;
    EXPECT_EQ(load_error("../etc/x", {}),
              "../etc/x: invalid module name (use 1 to 31 of a-z, 0-9 and _)");
    EXPECT_TRUE(list().empty());
}

TEST_F(RtapiDaemon, UnloadOfAModuleNotLoaded)
{
    auto none = hal::rtapi_unload("pid");  // no daemon at all
    ASSERT_FALSE(none);
    EXPECT_EQ(none.error().message, "pid: not loaded");
    EXPECT_TRUE(hal::rtapi_unload("all"));
    EXPECT_FALSE(hal::rtapi_running());

    ASSERT_TRUE(hal::rtapi_load(testmod, {}));
    auto other = hal::rtapi_unload("pid");
    ASSERT_FALSE(other);
    EXPECT_EQ(other.error().code, -ENOENT);
    EXPECT_EQ(other.error().message, "pid: not loaded");
    EXPECT_TRUE(hal::rtapi_running());  // testmod is still loaded
}

TEST_F(RtapiDaemon, UnloadAllEndsTheDaemon)
{
    ASSERT_TRUE(hal::rtapi_load(testmod, {}));
    ASSERT_TRUE(hal::rtapi_unload("all"));
    EXPECT_FALSE(file_exists(sock_));
    EXPECT_TRUE(list().empty());
}

TEST_F(RtapiDaemon, AnswersGarbageWithErrorsAndKeepsServing)
{
    ASSERT_TRUE(hal::rtapi_load(testmod, {}));
    EXPECT_EQ(exchange("ping\n"), "ok\n");
    EXPECT_EQ(exchange("frobnicate now\n"),
              "error -22\nrtapi_app: unknown request 'frobnicate'\n");
    EXPECT_EQ(exchange("ping extra\n"), "error -22\nrtapi_app: wrong arguments for 'ping'\n");
    EXPECT_EQ(exchange("load\n"), "error -22\nrtapi_app: wrong arguments for 'load'\n");
    EXPECT_EQ(exchange("unload a b\n"), "error -22\nrtapi_app: wrong arguments for 'unload'\n");
    EXPECT_EQ(exchange("\n"), "error -22\nrtapi_app: unknown request ''\n");
    EXPECT_EQ(exchange(std::string("pi\0ng\n", 6)),
              "error -71\nrtapi_app: request is not a line of text\n");
    EXPECT_EQ(exchange("\x01\x02\xff\xfe\x7f\n"),
              "error -71\nrtapi_app: request is not a line of text\n");
    EXPECT_EQ(exchange("lo"), "error -71\nrtapi_app: truncated request (no end of line)\n");
    EXPECT_EQ(exchange(std::string(100 * 1024, 'x')),
              "error -90\nrtapi_app: request longer than 65536 bytes\n");
    EXPECT_EQ(exchange("load ../../bin/sh\n"),
              "error -22\n../../bin/sh: invalid module name (use 1 to 31 of a-z, 0-9 and _)\n");
    EXPECT_EQ(exchange("load rtapi_app_testmod names=\"a\n"),
              "error -22\nrtapi_app_testmod: unterminated quote in 'names=\"a'\n");
    EXPECT_EQ(exchange("list\n"), std::string("ok\n") + testmod + "\n");
    EXPECT_EQ(list(), std::vector<std::string>{testmod});
}

TEST_F(RtapiDaemon, DropsASilentClientAndThenAnswersOthers)
{
    ASSERT_TRUE(hal::rtapi_load(testmod, {}));
    int silent = connect_raw();  // connects, sends nothing, keeps the connection
    auto start = std::chrono::steady_clock::now();
    EXPECT_EQ(exchange("ping\n"), "ok\n");  // not delayed by the silent one
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(8));
    char buf[256] = "";
    ssize_t n = read(silent, buf, sizeof(buf) - 1);
    EXPECT_GT(n, 0);
    EXPECT_STREQ(buf, "error -110\nrtapi_app: no complete request within 3000 ms\n");
    close(silent);
}

// Issue 19, item 6: idle connections used to be served one after another, each
// for its full read timeout. Now none of them delays a request that is complete.
TEST_F(RtapiDaemon, IdleClientsDoNotDelayOthers)
{
    ASSERT_TRUE(hal::rtapi_load(testmod, {}));
    std::vector<int> idle;
    for (int i = 0; i < 25; ++i)
        idle.push_back(connect_raw());
    EXPECT_EQ(exchange("ping\n"), "ok\n");
    EXPECT_EQ(list(), std::vector<std::string>{testmod});
    // Answered while every idle client is still waiting for its own timeout.
    for (int fd : idle) {
        char c;
        EXPECT_EQ(recv(fd, &c, 1, MSG_DONTWAIT), -1);
        EXPECT_EQ(errno, EAGAIN);
    }
    // A client that sent half a line is not blocked by the others either.
    int half = connect_raw();
    ASSERT_EQ(send(half, "pi", 2, MSG_NOSIGNAL), 2);
    EXPECT_EQ(exchange("list\n"), std::string("ok\n") + testmod + "\n");
    ASSERT_EQ(send(half, "ng\n", 3, MSG_NOSIGNAL), 3);
    char buf[16] = "";
    pollfd p{half, POLLIN, 0};
    ASSERT_EQ(poll(&p, 1, 10000), 1);
    EXPECT_EQ(read(half, buf, sizeof(buf) - 1), 3);
    EXPECT_STREQ(buf, "ok\n");
    close(half);
    for (int fd : idle)
        close(fd);
}

TEST_F(RtapiDaemon, ShutdownUnloadsEverythingAndRemovesTheSocket)
{
    ASSERT_TRUE(hal::rtapi_load(testmod, {}));
    ASSERT_TRUE(file_exists(sock_));
    ASSERT_TRUE(hal::rtapi_shutdown());
    EXPECT_FALSE(file_exists(sock_));
    EXPECT_FALSE(hal::rtapi_running());
    EXPECT_TRUE(hal::rtapi_shutdown());  // none running: nothing to do
}

TEST_F(RtapiDaemon, ExitsCleanlyOnSigterm)
{
    ASSERT_TRUE(hal::rtapi_load(testmod, {}));
    pid_t pid = daemon_pid();
    ASSERT_GT(pid, 0);
    ASSERT_EQ(kill(pid, SIGTERM), 0);
    auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    while (kill(pid, 0) == 0 && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    EXPECT_NE(kill(pid, 0), 0) << "rtapi_app still runs after SIGTERM";
    EXPECT_FALSE(file_exists(sock_));
}

TEST_F(RtapiDaemon, ReplacesAStaleSocketFile)
{
    int fd = socket(AF_UNIX, SOCK_STREAM, 0);  // bound, never listening, then gone
    sockaddr_un addr{};
    addr.sun_family = AF_UNIX;
    std::strncpy(addr.sun_path, sock_.c_str(), sizeof(addr.sun_path) - 1);
    ASSERT_EQ(bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof(addr)), 0);
    close(fd);
    ASSERT_TRUE(file_exists(sock_));
    EXPECT_FALSE(hal::rtapi_running());
    auto r = hal::rtapi_load(testmod, {});
    EXPECT_TRUE(r) << r.error().message;
    EXPECT_EQ(list(), std::vector<std::string>{testmod});
}

TEST_F(RtapiDaemon, ReportsAMissingRtapiApp)
{
    setenv("RTAPI_APP", "/nonexistent/rtapi_app", 1);
    EXPECT_EQ(load_error(testmod, {}),
              "rtapi_app: cannot run /nonexistent/rtapi_app: No such file or directory "
              "(set RTAPI_APP)");
}

TEST_F(RtapiDaemon, RefusesAnUnsafeInstanceName)
{
    setenv("RTAPI_INSTANCE", "a/b", 1);
    EXPECT_EQ(load_error(testmod, {}),
              "RTAPI_INSTANCE 'a/b': use 1 to 32 letters, digits, '.', '_' or '-'");
    EXPECT_FALSE(hal::rtapi_running());
    setenv("RTAPI_INSTANCE", instance_.c_str(), 1);
}

}  // namespace
