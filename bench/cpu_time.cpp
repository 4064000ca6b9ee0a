// SPDX-License-Identifier: GPL-2.0-or-later
// cpu_time - run a command and print the CPU time it used (user + system, itself
// and its waited-for children) and the wall time, in seconds: "CPU WALL". Its
// output goes to the file named by -o (default: /dev/null), so that the figure is
// the command's own work. On a shared machine CPU time is the steadier of the two.
// Usage: cpu_time [-o FILE] COMMAND [ARGS...]
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstring>

int main(int argc, char** argv)
{
    const char* out = "/dev/null";
    int first = 1;
    if (argc > 2 && std::strcmp(argv[1], "-o") == 0) {
        out = argv[2];
        first = 3;
    }
    if (first >= argc) {
        std::fprintf(stderr, "usage: cpu_time [-o FILE] COMMAND [ARGS...]\n");
        return 2;
    }
    auto t0 = std::chrono::steady_clock::now();
    pid_t pid = fork();
    if (pid < 0) {
        std::perror("cpu_time: fork");
        return 1;
    }
    if (pid == 0) {
        int fd = open(out, O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd < 0 || dup2(fd, STDOUT_FILENO) < 0) {
            std::perror(out);
            _exit(127);
        }
        execvp(argv[first], argv + first);
        std::perror(argv[first]);
        _exit(127);
    }
    int status = 0;
    struct rusage ru{};
    if (wait4(pid, &status, 0, &ru) < 0) {
        std::perror("cpu_time: wait4");
        return 1;
    }
    double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    double cpu = double(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) +
                 double(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec) / 1e6;
    std::printf("%.6f %.6f\n", cpu, wall);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        std::fprintf(stderr, "cpu_time: %s failed (status %d)\n", argv[first], status);
        return 1;
    }
    return 0;
}
