// SPDX-License-Identifier: GPL-2.0-or-later
// commands.cpp - the dispatch table: names, argument counts, usage and help of every
// halcmd(1) command, and "help"/-h output built from it.
#include "commands.hpp"

#include <algorithm>
#include <cstdio>

#include "line_parser.hpp"

namespace hal::halcmd {

namespace {

const Command table[] = {
    {"loadrt", 1, -1, false, cmd_loadrt, "loadrt MODNAME [ARG=VALUE ...]",
     "Load realtime module MODNAME with the given module arguments."},
    {"unloadrt", 1, 1, false, cmd_unloadrt, "unloadrt MODNAME|all",
     "Unload realtime module MODNAME, or all realtime modules."},
    {"loadusr", 1, -1, false, cmd_loadusr, "loadusr [-W|-Wn NAME|-w|-i] PROGRAM [ARGS ...]",
     "Start a userspace program, usually a userspace component. -W waits until a component named\n"
     "like the program is ready, -Wn NAME until component NAME is ready, -w until the program\n"
     "exits (a nonzero exit status fails the command unless -i is given)."},
    {"unloadusr", 1, 1, false, cmd_unloadusr, "unloadusr COMPNAME|all",
     "Send SIGTERM to userspace component COMPNAME (or all of them) and wait until it is gone."},
    {"waitusr", 1, 1, false, cmd_waitusr, "waitusr COMPNAME",
     "Wait until userspace component COMPNAME has left HAL (usually: its program exited)."},
    {"unload", 1, 1, false, cmd_unload, "unload COMPNAME|all",
     "Unload a userspace component or realtime module; 'all' unloads everything."},
    {"newsig", 2, 2, false, cmd_newsig, "newsig SIGNAME TYPE",
     "Create signal SIGNAME of TYPE bit, s32, u32, s64, u64 or float."},
    {"delsig", 1, 1, false, cmd_delsig, "delsig SIGNAME",
     "Delete signal SIGNAME; pins linked to it are unlinked."},
    {"linkps", 2, 2, true, cmd_linkps, "linkps PINNAME [ARROW] SIGNAME",
     "Link pin PINNAME to signal SIGNAME, breaking any previous link of the pin."},
    {"linksp", 2, 2, true, cmd_linksp, "linksp SIGNAME [ARROW] PINNAME",
     "Same as linkps with the arguments reversed."},
    {"linkpp", 2, 2, true, cmd_linkpp, "linkpp PINNAME1 [ARROW] PINNAME2",
     "Obsolete (use net): create a signal named PINNAME1 and link both pins to it."},
    {"unlinkp", 1, 1, false, cmd_unlinkp, "unlinkp PINNAME", "Break the link of pin PINNAME."},
    {"net", 2, -1, true, cmd_net, "net SIGNAME PINNAME ...",
     "Create SIGNAME with the type of the first pin if it does not exist, then link each pin\n"
     "to it. Arrows (=>, <=, <=>) may be written between the names; they are ignored."},
    {"setp", 2, 2, false, cmd_setp, "setp NAME VALUE",
     "Set parameter or unlinked input pin NAME to VALUE ('NAME = VALUE' is the same).\n"
     "A parameter wins over a pin of the same name."},
    {"getp", 1, 1, false, cmd_getp, "getp NAME", "Print the value of parameter or pin NAME."},
    {"ptype", 1, 1, false, cmd_ptype, "ptype NAME", "Print the type of parameter or pin NAME."},
    {"sets", 2, 2, false, cmd_sets, "sets SIGNAME VALUE",
     "Set signal SIGNAME to VALUE; fails if the signal has a writer."},
    {"gets", 1, 1, false, cmd_gets, "gets SIGNAME", "Print the value of signal SIGNAME."},
    {"stype", 1, 1, false, cmd_stype, "stype SIGNAME", "Print the type of signal SIGNAME."},
    {"addf", 2, 3, false, cmd_addf, "addf FUNCTNAME THREADNAME [POSITION]",
     "Add function FUNCTNAME to thread THREADNAME, after the functions already there."},
    {"delf", 2, 2, false, cmd_delf, "delf FUNCTNAME THREADNAME",
     "Remove function FUNCTNAME from thread THREADNAME."},
    {"start", 0, 0, false, cmd_start, "start", "Start the realtime threads."},
    {"stop", 0, 0, false, cmd_stop, "stop", "Stop the realtime threads."},
    {"lock", 0, 1, false, cmd_lock, "lock [none|load|config|tune|params|run|all]",
     "Lock HAL against loading, configuration, parameter changes or starting/stopping\n"
     "threads (default: all). 'tune' is load and config: parameters can still be tuned.\n"
     "'lock none' clears every lock."},
    {"unlock", 0, 1, false, cmd_unlock, "unlock [none|load|config|tune|params|run|all]",
     "Clear the given lock (default: all)."},
    {"alias", 3, 3, false, cmd_alias, "alias pin|param NAME ALIAS",
     "Give pin or parameter NAME a second name ALIAS; both names then work everywhere."},
    {"unalias", 2, 2, false, cmd_unalias, "unalias pin|param NAME",
     "Remove alias NAME, or every alias of the pin or parameter NAME."},
    {"debug", 0, 1, false, cmd_debug, "debug [LEVEL]",
     "Set the RTAPI message level (0 none, 1 errors, 2 warnings, 3 info, 4 debug, 5 all)\n"
     "of halcmd and of the realtime side; without LEVEL, print the current level."},
    {"setexact_for_test_suite_only", 0, 0, false, cmd_setexact, "setexact_for_test_suite_only",
     "Take thread periods exactly as asked, whatever the clock gives, so test results\n"
     "repeat. Must come before the first thread; not for running real hardware."},
    {"show", 0, -1, false, cmd_show, "show [comp|pin|sig|param|funct|thread|alias|all] [PATTERN ...]",
     "Print HAL objects. A pattern matches names starting with it, or as a glob (*, ?, [...])."},
    {"list", 1, -1, false, cmd_list, "list comp|pin|sig|param|funct|thread|alias [PATTERN ...]",
     "Print the names of HAL objects on one line."},
    {"save", 0, 2, false, cmd_save,
     "save [comp|alias|sig|sigu|link|linka|net|neta|netl|netla|param|unconnected|thread|all] [FILE]",
     "Print HAL commands that rebuild the current HAL (to FILE if given). Without an item:\n"
     "comp, alias, sigu, netla, param and thread; 'all' adds the values of unconnected\n"
     "input pins and undriven signals, so that the output rebuilds the HAL exactly."},
    {"status", 0, 1, false, cmd_status, "status [lock|mem|all]", "Print the lock level and memory use."},
    {"echo", 0, -1, false, cmd_echo, "echo [WORDS ...]", "Print the words."},
    {"help", 0, 1, false, cmd_help, "help [COMMAND]", "List the commands, or explain one."},
    {"source", 1, 1, false, cmd_source, "source FILE.hal", "Execute the commands of FILE.hal."},
    {"quit", 0, 0, false, cmd_quit, "quit", "Stop reading commands."},
    {"exit", 0, 0, false, cmd_quit, "exit", "Stop reading commands."},
};

}  // namespace

std::span<const Command> command_table()
{
    return table;
}

const Command* find_command(std::string_view name)
{
    for (const Command& c : table)
        if (name == c.name)
            return &c;
    return nullptr;
}

std::vector<std::string> command_names()
{
    std::vector<std::string> names;
    for (const Command& c : table)
        names.emplace_back(c.name);
    return names;
}

Result<ParsedCommand> parse_command(std::vector<std::string> words)
{
    ParsedCommand p;
    if (words.empty())
        return p;
    if (words.size() == 3 && words[1] == "=")        // "name = value" is setp
        words = {"setp", words[0], words[2]};
    p.command = find_command(words[0]);
    if (!p.command)
        return Error{-22, "unknown command '" + words[0] + "' (try 'help')"};
    for (size_t i = 1; i < words.size(); i++)
        if (!p.command->strips_arrows || !is_arrow(words[i]))
            p.args.push_back(std::move(words[i]));
    int n = static_cast<int>(p.args.size());
    if (n < p.command->min_args || (p.command->max_args >= 0 && n > p.command->max_args))
        return Error{-22, std::string(p.command->name) + ": wrong number of arguments (usage: " +
                              p.command->usage + ")"};
    return p;
}

void print_help(std::FILE* out, std::string_view topic)
{
    if (!topic.empty()) {
        const Command* c = find_command(topic);
        if (c)
            std::fprintf(out, "%s\n\n%s\n", c->usage, c->help);
        return;
    }
    std::fputs("Usage: halcmd [-kqQsRvV] [-i INIFILE] [-f [FILE] | COMMAND [ARGS]]\n"
               "       halcmd -h [COMMAND]\n"
               "Options: -f read commands from FILE (stdin without FILE), -i INIFILE for\n"
               "[SECTION]VAR substitution, -k keep going after errors, -q errors only (default),\n"
               "-Q silent, -s script-friendly output, -R release the HAL mutex, -v verbose,\n"
               "-V debug.\n\nCommands:\n",
               out);
    for (const Command& c : table)
        std::fprintf(out, "  %s\n", c.usage);
}

}  // namespace hal::halcmd
