// SPDX-License-Identifier: GPL-2.0-or-later
// session.cpp - reading commands (file, stdin, command line), substitution, dispatch,
// and the one-line-per-error rule. HAL calls print their own error through
// rtapi_print_msg; a message handler captures it so the line gets our FILE:LINE prefix.
#include "session.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "commands.hpp"
#include "hal_query.h"
#include "input_text.hpp"
#include "realtime.hpp"

namespace hal::halcmd {

namespace {

// The session whose command is running. A C callback has no context pointer, and
// there is one session per process, so this is the one place a global is needed.
Session* g_active_session = nullptr;

void message_trampoline(msg_level_t level, const char* msg)
{
    if (g_active_session)
        g_active_session->on_message(level, msg);
    else
        std::fputs(msg, stderr);
}

std::string strip_newlines(std::string_view s)
{
    while (!s.empty() && (s.back() == '\n' || s.back() == '\r'))
        s.remove_suffix(1);
    return std::string(s);
}

}  // namespace

Session::Session(Options opts) : opts_(std::move(opts))
{
    previous_handler_ = rtapi_get_msg_handler();
    g_active_session = this;
    rtapi_set_msg_handler(message_trampoline);
    if (opts_.verbosity == Verbosity::verbose)
        rtapi_set_msg_level(RTAPI_MSG_INFO);
    else if (opts_.verbosity == Verbosity::debug)
        rtapi_set_msg_level(RTAPI_MSG_ALL);
    // -Q "display nothing" (halcmd(1)): not even what show/getp print.
    if (opts_.verbosity == Verbosity::silent && !std::freopen("/dev/null", "w", stdout))
        std::fclose(stdout);
}

Session::~Session()
{
    if (attached_)
        hal_detach();
    rtapi_set_msg_handler(previous_handler_);
    if (g_active_session == this)
        g_active_session = nullptr;
}

void Session::on_message(msg_level_t level, const char* msg)
{
    if (level == RTAPI_MSG_ERR) {
        captured_.push_back(strip_newlines(msg));
        return;
    }
    bool show = level == RTAPI_MSG_WARN ? opts_.verbosity != Verbosity::silent
              : level == RTAPI_MSG_INFO ? opts_.verbosity >= Verbosity::verbose
                                        : opts_.verbosity >= Verbosity::debug;
    if (show) {
        std::fflush(stdout);
        std::fprintf(stderr, "%s\n", printable(strip_newlines(msg)).c_str());
    }
}

Result<void> Session::check(int rc, std::string_view fallback)
{
    if (rc >= 0)
        return ok();
    if (!captured_.empty()) {
        Error e{rc, captured_.front()};
        captured_.clear();
        return e;
    }
    return Error{rc, std::string(fallback) + ": " + std::strerror(-rc)};
}

void Session::info(const std::string& msg)
{
    if (opts_.verbosity >= Verbosity::verbose)
        std::printf("%s\n", msg.c_str());
}

void Session::report(const Error& e)
{
    failed_ = true;
    if (e.message.empty() || opts_.verbosity == Verbosity::silent)
        return;                           // empty: already reported (e.g. inside "source")
    std::fflush(stdout);                  // keep stdout and stderr in order in one file
    // Messages quote what the user typed: never let its bytes drive the terminal.
    std::fprintf(stderr, "%s%s\n", printable(where_).c_str(), printable(e.message).c_str());
}

Result<void> Session::execute(std::vector<std::string> words)
{
    auto parsed = parse_command(std::move(words));
    if (!parsed)
        return parsed.error();
    if (!parsed->command)
        return ok();
    const Command* c = parsed->command;
    const std::vector<std::string>& args = parsed->args;
    captured_.clear();
    Result<void> r = c->run(*this, args);
    if (r) {
        // An error line printed by a call that still succeeded: pass it on, once.
        for (const std::string& m : captured_)
            if (opts_.verbosity != Verbosity::silent) {
                std::fflush(stdout);
                std::fprintf(stderr, "%s%s\n", printable(where_).c_str(), printable(m).c_str());
            }
    }
    captured_.clear();
    return r;
}

Result<void> Session::execute_line(std::string_view line)
{
    auto words = tokenize(line, subs_);
    if (!words)
        return words.error();
    return execute(std::move(*words));
}

void Session::run_failed(const Error& e, const std::string& where, bool& ok)
{
    std::string saved = where_;
    where_ = where;
    report(e);
    ok = false;
    where_ = saved;
}

void Session::run_logged(std::string_view line, const std::string& where, bool& ok)
{
    std::string saved = where_;
    where_ = where;
    Result<void> r = execute_line(line);
    if (!r) {
        report(r.error());
        ok = false;
    }
    where_ = saved;
}

bool Session::run_stream(std::FILE* in, const std::string& name)
{
    bool ok = true;
    LineReader reader(in);
    std::string physical;
    int line_no = 0;
    int first_line = 0;
    bool pending = false;                 // a continued logical line is being collected
    std::string logical;
    auto where = [&] { return name + ":" + std::to_string(first_line) + ": "; };
    while (!quit_ && (ok || opts_.keep_going) && reader.next(physical)) {
        line_no++;
        if (!pending)
            first_line = line_no;
        // Bytes are checked before anything reads the line as a C string.
        if (auto r = check_line_text(physical); !r) {
            run_failed(Error{r.error().code, (pending ? "line " + std::to_string(line_no) + ": " : "") +
                                                 r.error().message},
                       where(), ok);
            logical.clear();
            pending = false;
            continue;
        }
        pending = join_continuation(logical, physical);
        if (logical.size() > max_line_bytes) {
            run_failed(Error{-E2BIG, "continued line longer than " + std::to_string(max_line_bytes) +
                                         " bytes"},
                       where(), ok);
            logical.clear();
            pending = false;
            continue;
        }
        if (pending)
            continue;
        run_logged(logical, where(), ok);
        logical.clear();
    }
    if (pending && !quit_ && (ok || opts_.keep_going))   // file ended inside a continuation
        run_logged(logical, where(), ok);
    if (const Error* e = reader.error()) {   // never "end of file" in disguise
        first_line = line_no + 1;
        run_failed(*e, where(), ok);
    }
    return ok;
}

bool Session::run_words(const std::vector<std::string>& words)
{
    where_ = "halcmd: ";
    Result<void> r = execute(words);
    if (!r)
        report(r.error());
    return static_cast<bool>(r);
}

Result<void> Session::source(const std::string& path)
{
    if (source_depth_ >= 32)
        return Error{-40, "source: '" + path + "' nested too deeply (a file sourcing itself?)"};
    std::FILE* f = std::fopen(path.c_str(), "r");
    if (!f)
        return Error{-errno, "source: cannot open '" + path + "': " + std::strerror(errno)};
    source_depth_++;
    bool ok = run_stream(f, path);
    source_depth_--;
    std::fclose(f);
    if (!ok)
        return Error{-22, ""};            // each failing line was reported already
    return hal::ok();
}

bool Session::start()
{
    if (!opts_.inifile.empty()) {
        auto ini = IniFile::load(opts_.inifile);
        if (!ini) {
            report(ini.error());
            return false;
        }
        ini_ = std::move(*ini);
    }
    subs_ = process_substitutions(ini_ ? &*ini_ : nullptr);
    // The kernel flavor's HAL segment exists while hal_lib.ko is loaded.
    Result<void> flavor = select_flavor(opts_.flavor);
    if (flavor)
        flavor = rt_prepare();
    if (!flavor) {
        report(flavor.error());
        return false;
    }
    captured_.clear();
    Result<void> r = check(hal_attach(), "cannot attach to the HAL shared memory");
    if (!r) {
        report(r.error());
        return false;
    }
    attached_ = true;
    if (opts_.release_mutex)
        hal_release_mutex();
    if (auto host = rt_check_host(); !host) {
        report(host.error());
        return false;
    }
    return true;
}

int Session::run()
{
    if (opts_.help) {
        if (!opts_.help_topic.empty() && !find_command(opts_.help_topic)) {
            report(Error{-22, "no command '" + opts_.help_topic + "' (try 'halcmd -h')"});
            return 1;
        }
        print_help(stdout, opts_.help_topic);
        return 0;
    }
    if (!start())
        return 1;
    return run_input();
}

int Session::run_keep_going_stdin()
{
    opts_.keep_going = true;
    opts_.from_file = true;
    opts_.file.clear();
    quit_ = false;
    if (isatty(STDIN_FILENO))
        run_interactive();
    else
        run_stream(stdin, "<stdin>");
    std::fflush(stdout);
    return failed_ ? 1 : 0;
}

int Session::run_input()
{
    if (opts_.from_file && !opts_.file.empty()) {
        std::FILE* f = std::fopen(opts_.file.c_str(), "r");
        if (!f) {
            report(Error{-errno, "cannot open '" + opts_.file + "': " + std::strerror(errno)});
            return 1;
        }
        run_stream(f, opts_.file);
        std::fclose(f);
    } else if (!opts_.from_file && !opts_.command.empty()) {
        run_words(opts_.command);
    } else if (isatty(STDIN_FILENO)) {
        run_interactive();
    } else {
        run_stream(stdin, "<stdin>");
    }
    std::fflush(stdout);
    return failed_ ? 1 : 0;
}

}  // namespace hal::halcmd
