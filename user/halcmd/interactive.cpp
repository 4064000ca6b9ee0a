// SPDX-License-Identifier: GPL-2.0-or-later
// interactive.cpp - the readline loop of interactive halcmd: prompt "halcmd: ",
// history, and tab completion through the pure complete() of completion.cpp.
#include <readline/history.h>
#include <readline/readline.h>

#include <cstdlib>
#include <memory>
#include <cstring>
#include <string>
#include <vector>

#include "commands.hpp"
#include "completion.hpp"
#include "module_dir.hpp"
#include "session.hpp"
#include "snapshot.hpp"

namespace hal::halcmd {

namespace {

// readline's C callbacks carry no context: the candidates of the completion in
// progress live here until the generator has handed them all out.
std::vector<std::string> g_candidates;
size_t g_next_candidate = 0;

char* candidate_generator(const char*, int state)
{
    if (state == 0)
        g_next_candidate = 0;
    if (g_next_candidate >= g_candidates.size())
        return nullptr;
    return strdup(g_candidates[g_next_candidate++].c_str());   // readline frees it
}

char** attempt_completion(const char*, int, int end)
{
    static const std::vector<std::string> modules = list_modules(rtlib_dir());
    Snapshot snap = take_snapshot();
    CompletionSources src;
    src.hal = &snap;
    src.commands = command_names();
    src.modules = modules;
    Completion c = complete(std::string_view(rl_line_buffer, static_cast<size_t>(end)), src);
    if (c.filenames) {
        rl_attempted_completion_over = 0;      // readline's own file name completion
        return nullptr;
    }
    rl_attempted_completion_over = 1;
    g_candidates = std::move(c.candidates);
    return rl_completion_matches("", candidate_generator);
}

struct FreeLine {
    void operator()(char* p) const noexcept { std::free(p); }
};

}  // namespace

bool Session::run_interactive()
{
    rl_readline_name = "halcmd";
    rl_attempted_completion_function = attempt_completion;
    rl_completer_word_break_characters = const_cast<char*>(" \t\n");
    // "No prompt will be printed if both -s and -f are specified" (halcmd(1)).
    const char* prompt = opts_.script_mode && opts_.from_file ? "" : "halcmd: ";
    bool ok = true;
    std::string logical;
    while (!quit_) {
        std::unique_ptr<char, FreeLine> line(readline(logical.empty() ? prompt : "> "));
        if (!line) {
            std::printf("\n");
            break;                               // end of input (Ctrl-D)
        }
        if (line.get()[0] != '\0')
            add_history(line.get());
        if (join_continuation(logical, line.get()))
            continue;
        bool line_ok = true;
        run_logged(logical, "halcmd: ", line_ok);  // interactive: always keep going
        ok = ok && line_ok;
        logical.clear();
    }
    return ok;
}

}  // namespace hal::halcmd
