// SPDX-License-Identifier: GPL-2.0-or-later
// options.hpp - emcrsh's command line (emcrsh(1)):
//   emcrsh [-p PORT] [-n NAME] [-w CONNECTPW] [-e ENABLEPW] [-s SESSIONS] [-d PATH]
//          [-- -ini INI [-bus PATH]]
// The launcher starts the display as "emcrsh ARGS -- -ini INI".
#pragma once

#include <string>

#include "hal/result.hpp"

namespace hal::emcrsh {

struct Options {
    int port = 5007;                  // 0: any free port (printed at start)
    std::string name = "EMCNETSVR";   // in HELLO ACK
    std::string connect_pw = "EMC";
    std::string enable_pw = "EMCTOO";
    int max_sessions = -1;            // -1: no limit
    std::string path;                 // default directory of program files (OPEN)
    std::string ini;                  // -- -ini FILE (else $INI_FILE_NAME, else emc.ini)
    std::string bus;                  // -- -bus PATH (else derived from the INI file)
    bool help = false;
};

// Parses argv; errors name the option ("-p: 'x' is not a port number").
Result<Options> parse_options(int argc, const char* const* argv);
const char* usage_text();

}  // namespace hal::emcrsh
