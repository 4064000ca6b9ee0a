// SPDX-License-Identifier: GPL-2.0-or-later
// fuzz_halcmd_line - halcmd's reading of a .hal file: the byte check, continuation
// joining, the tokenizer with environment and inifile substitution, the command
// parser (dispatch table, setp shorthand, arrows, argument counts; no handler runs)
// and the command-line option parser on the resulting words. Input: any bytes (a
// .hal file).
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "commands.hpp"
#include "input_text.hpp"
#include "line_parser.hpp"
#include "options.hpp"

using namespace hal::halcmd;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    static const IniFile ini = *IniFile::parse("[EMC]\nMACHINE = fuzz\n[AXIS_0]\nSCALE=1.5\n", "f.ini");
    Substitutions subs;
    subs.env = [](const std::string& name) -> std::optional<std::string> {
        if (name == "HOME")
            return std::string("/home/u");
        if (name == "WORDS")
            return std::string("a  b\t$c \"d\"");
        return std::nullopt;
    };
    subs.ini = &ini;
    std::string_view text(reinterpret_cast<const char*>(data), size);
    std::string logical;
    while (!text.empty()) {
        size_t nl = text.find('\n');
        std::string_view line = text.substr(0, nl);
        text = nl == std::string_view::npos ? std::string_view() : text.substr(nl + 1);
        (void)printable(line);
        if (!check_line_text(line))
            continue;
        if (join_continuation(logical, line))
            continue;
        auto words = tokenize(logical, subs);
        logical.clear();
        if (!words)
            continue;
        for (const std::string& w : *words)
            (void)is_arrow(w);
        auto parsed = parse_command(*words);
        if (parsed && parsed->command) {
            int n = static_cast<int>(parsed->args.size());
            if (n < parsed->command->min_args || (parsed->command->max_args >= 0 && n > parsed->command->max_args))
                std::abort();  // the handler would get a count it does not expect
        }
        std::vector<std::string> argv{"halcmd"};
        argv.insert(argv.end(), words->begin(), words->end());
        (void)parse_halcmd_options(argv);
        (void)parse_halrun_options(argv);
    }
    return 0;
}
