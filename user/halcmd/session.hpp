// SPDX-License-Identifier: GPL-2.0-or-later
// session.hpp - one halcmd run: options, substitution sources, where input comes
// from, and the error rule of RULINGS.md: exactly one line per failed command
// ("FILE:LINE: message" or "halcmd: message"), stop at the first unless -k.
#pragma once

#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hal/result.hpp"
#include "ini/ini_file.hpp"
#include "line_parser.hpp"
#include "options.hpp"
#include "rtapi.h"

namespace hal::halcmd {

class Session {
public:
    explicit Session(Options opts);
    ~Session();
    Session(const Session&) = delete;
    Session& operator=(const Session&) = delete;

    // Everything halcmd does after option parsing; returns the exit status.
    int run();
    // Load the -i inifile and attach to HAL. Error: already printed.
    bool start();
    // After start(): the file, the command-line command, or stdin (readline on a tty).
    int run_input();
    // halrun -I: an interactive "halcmd -kf" after the first run.
    int run_keep_going_stdin();
    // Commands from a stream (file, stdin, "source"); false if any failed.
    bool run_stream(std::FILE* in, const std::string& name);
    // Readline loop with completion (interactive.cpp); false if any command failed.
    bool run_interactive();
    // One command given as words (command line); false if it failed.
    bool run_words(const std::vector<std::string>& words);
    bool failed() const { return failed_; }

    // --- for command handlers ---
    Result<void> execute(std::vector<std::string> words);
    const Options& options() const { return opts_; }
    bool script_mode() const { return opts_.script_mode; }
    // Turns a HAL return code into a result. On failure the error is the message the
    // HAL call printed (captured), else "fallback: strerror".
    Result<void> check(int rc, std::string_view fallback);
    // -v: one line saying what a command did.
    void info(const std::string& msg);
    Result<void> source(const std::string& path);
    void request_quit() { quit_ = true; }

    // rtapi message handler target (see session.cpp).
    void on_message(msg_level_t level, const char* msg);

private:
    Result<void> execute_line(std::string_view line);
    void report(const Error& e);
    void run_logged(std::string_view line, const std::string& where, bool& ok);
    void run_failed(const Error& e, const std::string& where, bool& ok);

    Options opts_;
    std::optional<IniFile> ini_;
    Substitutions subs_;
    std::string where_ = "halcmd: ";      // prefix of error lines for the running command
    std::vector<std::string> captured_;   // RTAPI_MSG_ERR lines of the running command
    int source_depth_ = 0;
    bool quit_ = false;
    bool failed_ = false;
    bool attached_ = false;
    rtapi_msg_handler_t previous_handler_ = nullptr;
};

}  // namespace hal::halcmd
