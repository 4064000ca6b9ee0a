// SPDX-License-Identifier: GPL-2.0-or-later
// spawn.cpp - see spawn.hpp.
#include "spawn/spawn.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>

namespace hal {

Result<pid_t> spawn_process(const std::vector<std::string>& argv, const SpawnOptions& opt)
{
    if (argv.empty())
        return Error{-22, "nothing to run"};
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) < 0)
        return Error{-errno, std::string("pipe: ") + std::strerror(errno)};
    std::fflush(nullptr);
    pid_t pid = fork();
    if (pid < 0) {
        int e = errno;
        close(fds[0]);
        close(fds[1]);
        return Error{-e, std::string("fork: ") + std::strerror(e)};
    }
    if (pid == 0) {
        if (opt.default_signals)
            for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGPIPE})
                signal(sig, SIG_DFL);
        if (opt.new_group)
            setpgid(0, 0);
        if (opt.stdin_fd >= 0) {
            dup2(opt.stdin_fd, 0);
            close(opt.stdin_fd);
        }
        std::vector<char*> cargv;
        for (const std::string& a : argv)
            cargv.push_back(const_cast<char*>(a.c_str()));
        cargv.push_back(nullptr);
        close(fds[0]);
        execvp(cargv[0], cargv.data());
        int e = errno;
        (void)!write(fds[1], &e, sizeof e);
        _exit(127);
    }
    if (opt.new_group)
        setpgid(pid, pid);   // also here: no race with a kill of the group
    close(fds[1]);
    int child_errno = 0;
    ssize_t n;
    do {
        n = read(fds[0], &child_errno, sizeof child_errno);
    } while (n < 0 && errno == EINTR);
    close(fds[0]);
    if (n == static_cast<ssize_t>(sizeof child_errno)) {
        while (waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {
        }
        return Error{-child_errno, "cannot run '" + argv[0] + "': " + std::strerror(child_errno)};
    }
    return pid;
}

}  // namespace hal
