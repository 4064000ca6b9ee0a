// SPDX-License-Identifier: GPL-2.0-or-later
// options.cpp - see options.hpp.
#include "options.hpp"

namespace hal::comp {

namespace {

Result<void> set_personalities(Options& o, const std::string& v)
{
    int n = 0;
    bool ok = !v.empty() && v.size() <= 4;
    for (char c : v) {
        ok = ok && c >= '0' && c <= '9';
        n = n * 10 + (c - '0');
    }
    if (!ok || n < 1 || n > 1024)
        return Error{-1, "--personalities=" + v + ": give a number of personalities, 1..1024"};
    o.personalities = n;
    return {};
}

}  // namespace

Result<Options> parse_options(std::span<char*> argv)
{
    Options o;
    auto set_mode = [&](Mode m, const std::string& arg) -> Result<void> {
        if (o.mode_given && o.mode != m)
            return Error{-1, "only one of --compile, --preprocess, --document, --view-doc, "
                             "--install, --install-doc may be given (found " + arg + ")"};
        o.mode = m;
        o.mode_given = true;
        return {};
    };
    bool only_files = false;
    for (std::size_t i = 1; i < argv.size(); ++i) {
        std::string a = argv[i];
        Result<void> r;
        if (only_files || a.empty() || a[0] != '-') {
            o.files.push_back(a);
            continue;
        }
        if (a == "--") only_files = true;
        else if (a == "--compile" || a == "-c") r = set_mode(Mode::Compile, a);
        else if (a == "--preprocess" || a == "-p") r = set_mode(Mode::Preprocess, a);
        else if (a == "--document" || a == "-d") r = set_mode(Mode::Document, a);
        else if (a == "--view-doc" || a == "-v") r = set_mode(Mode::ViewDoc, a);
        else if (a == "--install" || a == "-i") r = set_mode(Mode::Install, a);
        else if (a == "--install-doc" || a == "-j") r = set_mode(Mode::InstallDoc, a);
        else if (a == "--userspace" || a == "-u") o.userspace = true;
        else if (a == "--help" || a == "-h") o.help = true;
        else if (a == "-o" || a == "--outfile") {
            if (i + 1 >= argv.size())
                return Error{-1, a + " needs a file name"};
            o.output = argv[++i];
        } else if (a.rfind("--outfile=", 0) == 0) {
            o.output = a.substr(10);
        } else if (a.rfind("--extra-compile-args=", 0) == 0) {
            o.extra_compile_args += (o.extra_compile_args.empty() ? "" : " ") + a.substr(21);
        } else if (a.rfind("--extra-link-args=", 0) == 0) {
            o.extra_link_args += (o.extra_link_args.empty() ? "" : " ") + a.substr(18);
        } else if (a == "--extra-compile-args" || a == "--extra-link-args" || a == "--personalities") {
            if (i + 1 >= argv.size())
                return Error{-1, a + " needs a value"};
            std::string v = argv[++i];
            if (a == "--personalities") {
                if (auto r = set_personalities(o, v); !r)
                    return r.error();
            } else {
                std::string& dst = a == "--extra-link-args" ? o.extra_link_args : o.extra_compile_args;
                dst += (dst.empty() ? "" : " ") + v;
            }
        } else if (a.rfind("--personalities=", 0) == 0) {
            if (auto r = set_personalities(o, a.substr(16)); !r)
                return r.error();
        } else {
            return Error{-1, "unknown option '" + a + "'"};
        }
        if (!r)
            return r.error();
    }
    if (o.help)
        return o;
    if (o.files.empty())
        return Error{-1, "no input file (give a .comp, .c or .py file)"};
    if (!o.output.empty() && o.files.size() > 1)
        return Error{-1, "-o needs exactly one input file"};
    return o;
}

std::string usage(const std::string& prog)
{
    return "usage: " + prog +
           " [--compile|--preprocess|--document|--view-doc] [-o OUT] FILE...\n"
           "       " + prog + " [--install|--install-doc] FILE...\n"
           "       " + prog + " --compile --userspace FILE.comp|FILE.c\n"
           "       " + prog + " --install --userspace FILE.comp|FILE.c|FILE.py\n"
           "  --preprocess  FILE.comp -> FILE.c (the default)\n"
           "  --compile     build a HAL module (NAME.so, or NAME.ko in the kernel flavor) here\n"
           "  --install     build it and install it into the module directory ($HAL_RTLIB_DIR)\n"
           "  --document    FILE.comp -> FILE.9 man page; --view-doc shows it; --install-doc installs it\n"
           "  --userspace   build a userspace component program instead of a realtime module\n"
           "  --extra-compile-args=ARGS, --extra-link-args=ARGS  more compiler / linker arguments\n"
           "  --personalities=N  personality= takes up to N values (default 64)\n"
           "environment: HAL_INCLUDE_DIR (headers), HAL_RTLIB_DIR (modules), HAL_BIN_DIR,\n"
           "  HAL_MAN_DIR, HAL_FLAVOR (sim|kernel), KDIR, HAL_KMOD_BUILD, CC\n";
}

}  // namespace hal::comp
