// SPDX-License-Identifier: GPL-2.0-or-later
// protocol.hpp - the machine bus wire format (docs/bus.md): text lines over a
// Unix-domain stream socket between task (the server) and its clients (emcbus,
// iocontrol, emcrsh, halui, GUIs, tests). Shared by the server, the client library
// and the unit tests, so both ends split and check lines the same way.
//
//   client -> task   HELLO 1 client|io [NAME]           first line, once
//                    <serial> <COMMAND> [ARGS]          serial: 1 .. 2^31-1
//   task -> client   HELLO OK 1 <client id> | HELLO ERROR <reason>
//                    <serial> RECEIVED | DONE | ERROR <text>
//                    <serial> STATUS <n>   followed by n lines "key value"
//                    MSG ERROR|DISPLAY|TEXT <text>      operator messages, to every client
//   task <-> io      IOCMD <n> <VERB> [ARGS] / IOACK <n> DONE|ERROR [text] /
//                    IOSTAT key=value ... / IOTOOLS <n> + n tool-table lines
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hal/result.hpp"

namespace hal::bus {

constexpr int PROTOCOL_VERSION = 1;
constexpr size_t MAX_LINE = 4096;          // bytes, newline included
constexpr long MAX_SERIAL = 2147483647L;

// One client command: its name, how many words it takes, whether the last argument
// is the rest of the line (MDI text, file names, which may hold blanks).
struct CommandSpec {
    const char* name;
    int min_args;
    int max_args;
    bool rest_of_line;   // the last argument takes the rest of the line
    const char* usage;   // argument synopsis for emcbus --help and error texts
};

// The command table (docs/bus.md lists the same); nullptr for an unknown name.
// Names are matched case-insensitively and returned upper case.
const CommandSpec* find_command(std::string_view name);
const std::vector<CommandSpec>& commands();

// A parsed client command line.
struct Request {
    long serial = 0;
    std::string verb;                  // upper case
    std::vector<std::string> args;
};

// "<serial> VERB args": checks the serial, the command name and its argument count.
// The error text names what is wrong ("bad serial 'x'", "unknown command 'FOO'",
// "MODE: needs 1 argument (MANUAL|AUTO|MDI)").
Result<Request> parse_request(std::string_view line);

// Words separated by blanks; when max_words > 0 the last word is the rest of the line
// (leading blanks removed, trailing kept).
std::vector<std::string> split_words(std::string_view s, size_t max_words = 0);

// True when s holds no control characters other than tab (no NUL, CR, ESC...).
bool is_printable(std::string_view s);
// Control characters replaced by '?' and the text cut to fit one line: what the server
// puts into messages that quote a client's input.
std::string sanitize(std::string_view s, size_t max_len = 200);

// Collects bytes from a stream and hands out complete lines. A line longer than
// MAX_LINE is reported once as an error and skipped up to its newline.
class LineBuffer {
public:
    void append(const char* data, size_t n);
    // The next complete line without its newline; nullopt when none is complete.
    // Sets *too_long when a line had to be dropped (then returns nullopt once).
    std::optional<std::string> next(bool* too_long);
    size_t pending() const { return buf_.size(); }

private:
    std::string buf_;
    bool skipping_ = false;   // inside an over-long line: drop up to its newline
};

// Status: ordered "key value" pairs (docs/bus.md lists the keys).
using StatusLines = std::vector<std::pair<std::string, std::string>>;

// Default socket path for an INI file: $XDG_RUNTIME_DIR (or /tmp)/emcbus-UID/
// <16 hex digits of the INI file's real path hash>.sock. Empty ini -> "default.sock".
std::string default_socket_path(const std::string& ini_path);
// The socket path a program should use: explicit (-bus) if given, else $EMCBUS, else
// the default for the INI file (-ini, else $INI_FILE_NAME).
Result<std::string> resolve_socket_path(const std::string& explicit_path, const std::string& ini_path);

}  // namespace hal::bus
