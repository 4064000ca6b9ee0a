// SPDX-License-Identifier: GPL-2.0-or-later
// procs.cpp - see procs.hpp.
#include "procs.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <thread>

#include "spawn/spawn.hpp"

namespace hal::launcher {

using namespace std::chrono_literals;

volatile std::sig_atomic_t stop_signal = 0;

static void on_signal(int sig) { stop_signal = sig; }

void install_signal_handlers()
{
    struct sigaction sa {};
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    for (int sig : {SIGINT, SIGTERM, SIGHUP})
        sigaction(sig, &sa, nullptr);
    signal(SIGPIPE, SIG_IGN);
}

static void trace_argv(const std::vector<std::string>& argv)
{
    std::string line = "+";
    for (const std::string& a : argv)
        line += " " + a;
    std::fprintf(stderr, "%s\n", line.c_str());
}

// The child: default signal handling, its own group if asked, then exec (spawn.hpp).
static Result<pid_t> spawn_impl(const std::vector<std::string>& argv, bool new_group, bool trace, int stdin_fd)
{
    if (trace && !argv.empty())
        trace_argv(argv);
    SpawnOptions opt;
    opt.default_signals = true;
    opt.new_group = new_group;
    opt.stdin_fd = stdin_fd;
    return spawn_process(argv, opt);
}

Result<pid_t> spawn(const std::vector<std::string>& argv, bool new_group, bool trace)
{
    return spawn_impl(argv, new_group, trace, -1);
}

int wait_for(pid_t pid, bool interruptible)
{
    int status = 0;
    for (;;) {
        pid_t r = waitpid(pid, &status, interruptible ? WNOHANG : 0);
        if (r == pid)
            break;
        if (r < 0 && errno != EINTR)
            return 127;
        if (interruptible) {
            if (stop_signal)
                return -1;
            std::this_thread::sleep_for(20ms);
        }
    }
    if (WIFEXITED(status))
        return WEXITSTATUS(status);
    if (WIFSIGNALED(status))
        return 128 + WTERMSIG(status);
    return 127;
}

int run_program(const std::vector<std::string>& argv, bool trace, const std::string& stdin_text)
{
    int in[2] = {-1, -1};
    if (!stdin_text.empty() && pipe2(in, O_CLOEXEC) < 0)
        return 127;
    auto pid = spawn_impl(argv, false, trace, in[0]);
    if (in[0] >= 0)
        close(in[0]);
    if (!pid) {
        if (in[1] >= 0)
            close(in[1]);
        std::fprintf(stderr, "%s\n", pid.error().message.c_str());
        return 127;
    }
    if (in[1] >= 0) {
        (void)!write(in[1], stdin_text.data(), stdin_text.size());
        close(in[1]);
    }
    return wait_for(*pid, false);
}

bool alive(pid_t pid)
{
    if (pid <= 0 || (kill(pid, 0) != 0 && errno != EPERM))
        return false;
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    std::string line;
    if (!std::getline(stat, line))
        return true;                   // no /proc: kill() decided
    size_t close = line.rfind(')');
    return !(close != std::string::npos && close + 2 < line.size() && line[close + 2] == 'Z');
}

static bool group_alive(pid_t pgid)
{
    return kill(-pgid, 0) == 0 || errno != ESRCH;
}

void stop_group(pid_t pid, bool is_group)
{
    if (pid <= 0)
        return;
    pid_t target = is_group ? -pid : pid;
    auto gone = [&] {
        waitpid(pid, nullptr, WNOHANG);          // reap our own child
        return is_group ? !group_alive(pid) : !alive(pid);
    };
    if (gone())
        return;
    kill(target, SIGTERM);
    for (int i = 0; i < 20 && !gone(); i++)
        std::this_thread::sleep_for(100ms);
    if (!gone()) {
        kill(target, SIGKILL);
        for (int i = 0; i < 20 && !gone(); i++)
            std::this_thread::sleep_for(100ms);
    }
    waitpid(pid, nullptr, WNOHANG);
}

std::string describe_status(int status)
{
    if (status >= 128)
        return std::string("was killed by signal ") + strsignal(status - 128);
    return "exited with status " + std::to_string(status);
}

}  // namespace hal::launcher
