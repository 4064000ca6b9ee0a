// SPDX-License-Identifier: GPL-2.0-or-later
// commands.hpp - the halcmd dispatch table and the handlers, one file per family:
// cmd_load.cpp, cmd_signal.cpp, cmd_value.cpp, cmd_thread.cpp, cmd_show.cpp,
// cmd_save.cpp, cmd_misc.cpp.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hal/result.hpp"

namespace hal::halcmd {

class Session;
using Args = std::span<const std::string>;
using Handler = Result<void> (*)(Session&, Args);

struct Command {
    const char* name;
    int min_args;
    int max_args;            // -1: any number
    bool strips_arrows;      // net/link*: "=>", "<=", "<=>" are dropped first
    Handler run;
    const char* usage;
    const char* help;
};

std::span<const Command> command_table();
const Command* find_command(std::string_view name);
std::vector<std::string> command_names();

// A line's words resolved against the table, before anything runs: "NAME = VALUE" is
// setp, net/link* drop their arrows, the argument count is checked against the
// command's. No words: command is null. Pure (the fuzz target tests/fuzz/ calls it).
struct ParsedCommand {
    const Command* command = nullptr;
    std::vector<std::string> args;
};
Result<ParsedCommand> parse_command(std::vector<std::string> words);

// Fails with a message naming the lock level when any of lock_bits is set.
Result<void> require_unlocked(int lock_bits, std::string_view command);

// Help text of help/-h.
void print_help(std::FILE* out, std::string_view topic);

// Handlers.
Result<void> cmd_loadrt(Session&, Args);
Result<void> cmd_unloadrt(Session&, Args);
Result<void> cmd_loadusr(Session&, Args);
Result<void> cmd_unloadusr(Session&, Args);
Result<void> cmd_waitusr(Session&, Args);
Result<void> cmd_unload(Session&, Args);
Result<void> cmd_newsig(Session&, Args);
Result<void> cmd_delsig(Session&, Args);
Result<void> cmd_linkps(Session&, Args);
Result<void> cmd_linksp(Session&, Args);
Result<void> cmd_linkpp(Session&, Args);
Result<void> cmd_unlinkp(Session&, Args);
Result<void> cmd_net(Session&, Args);
Result<void> cmd_setp(Session&, Args);
Result<void> cmd_getp(Session&, Args);
Result<void> cmd_ptype(Session&, Args);
Result<void> cmd_sets(Session&, Args);
Result<void> cmd_gets(Session&, Args);
Result<void> cmd_stype(Session&, Args);
Result<void> cmd_addf(Session&, Args);
Result<void> cmd_delf(Session&, Args);
Result<void> cmd_start(Session&, Args);
Result<void> cmd_stop(Session&, Args);
Result<void> cmd_lock(Session&, Args);
Result<void> cmd_unlock(Session&, Args);
Result<void> cmd_show(Session&, Args);
Result<void> cmd_list(Session&, Args);
Result<void> cmd_save(Session&, Args);
Result<void> cmd_status(Session&, Args);
Result<void> cmd_echo(Session&, Args);
Result<void> cmd_help(Session&, Args);
Result<void> cmd_source(Session&, Args);
Result<void> cmd_quit(Session&, Args);
Result<void> cmd_alias(Session&, Args);
Result<void> cmd_unalias(Session&, Args);
Result<void> cmd_debug(Session&, Args);
Result<void> cmd_setexact(Session&, Args);

// Shared by unloadusr/unload and halrun's teardown: SIGTERM userspace components
// ("all" or one name) and wait (bounded) until they are gone.
Result<void> unload_user_components(Session* s, const std::string& name);
// Crash clean-up (show, loadusr): reap our dead children, then remove every userspace
// component whose process is gone (hal_comps_remove_dead).
void remove_dead_user_components();

}  // namespace hal::halcmd
