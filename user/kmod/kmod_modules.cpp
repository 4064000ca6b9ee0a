// SPDX-License-Identifier: GPL-2.0-or-later
// kmod_modules.cpp - loadrt/unloadrt for the kernel flavor (kmod.hpp): the checks
// rtapi_app makes in the simulated flavor, made here before emc_module_helper runs,
// so both flavors word their errors alike; and reading back the module's own error
// messages from rtapi.ko's ring (/proc/rtapi/messages), since insmod only tells the
// errno.
#include "hal/kmod.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>

#include "module_args.hpp"

namespace hal::kmod {
namespace fs = std::filesystem;

namespace {

const char* const messages_file = "/proc/rtapi/messages";
// The hidden parameter that carries the joined arguments (rtapi_app_kmod.h).
const char* const args_param = "hal_loadrt_args";

struct ProcModule {
    std::string name;
    int refcount = 0;
    std::vector<std::string> users;   // modules that use this one
};

// /proc/modules: "name size refcount user1,user2, state address", newest first.
std::vector<ProcModule> proc_modules()
{
    std::vector<ProcModule> out;
    std::ifstream in("/proc/modules");
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        ProcModule m;
        std::string size, users;
        words >> m.name >> size >> m.refcount >> users;
        std::istringstream list(users);
        for (std::string u; std::getline(list, u, ',');)
            if (!u.empty() && u != "-")
                m.users.push_back(u);
        out.push_back(std::move(m));
    }
    return out;
}

bool is_core(const std::string& name)
{
    return name == "rtapi" || name == "hal_lib";
}

// rtapi.ko reaches Linux's parport layer only through this module, which links
// against parport.ko (kernel/rtapi/rtapi_parport_linux.h). It is no HAL module: it
// comes and goes with the modules that claim ports.
const char* const parport_linux = "rtapi_parport_linux";

// True when the .ko at 'path' imports 'symbol' (a NUL-terminated name in its
// string table; the module's own exports are not in modules loadrt loads).
bool imports_symbol(const std::string& path, const std::string& symbol)
{
    std::ifstream in(path, std::ios::binary);
    std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return data.find(std::string(1, '\0') + symbol + std::string(1, '\0')) != std::string::npos;
}

std::string first_line(const std::string& text)
{
    return text.substr(0, text.find('\n'));
}

// The line rtapi_app_kmod.h logs when rtapi_app_main fails: "NAME: rtapi_app_main
// failed (RC)". Returns true and sets rc when 'msg' is it.
bool is_init_failure(const std::string& msg, const std::string& name, int& rc)
{
    std::string head = name + ": rtapi_app_main failed (";
    if (msg.compare(0, head.size(), head) != 0 || msg.back() != ')')
        return false;
    try {
        rc = std::stoi(msg.substr(head.size(), msg.size() - head.size() - 1));
    } catch (const std::exception&) {
        return false;
    }
    return true;
}

// A failed insert: the module's messages, the init failure worded as rtapi_app
// words it (module_host.cpp), or insmod's complaint when init never ran.
Error insert_error(const std::string& name, const HelperRun& run, unsigned long long seq)
{
    std::string msg;
    int code = run.status == 2 ? -EPERM : -EIO;
    bool init_failed = false;
    for (const std::string& m : error_messages_since(seq)) {
        int rc = 0;
        std::string line = m;
        if (is_init_failure(m, name, rc)) {
            line = name + ": rtapi_app_main failed: " + std::strerror(-rc) + " (" +
                   std::to_string(rc) + ")";
            code = rc < 0 ? rc : -EINVAL;
            init_failed = true;
        }
        msg += (msg.empty() ? "" : "; ") + line;
    }
    if (!init_failed) {
        std::string why = first_line(run.err);
        if (why.empty())
            why = "emc_module_helper exit status " + std::to_string(run.status);
        msg += (msg.empty() ? "" : "; ") + name + ": " + why;
    }
    return Error{code, msg};
}

// Before a module that claims parallel ports (imports hal_parport_get) is inserted:
// when Linux's parport layer is loaded, rtapi_parport_linux too, so that ports Linux
// drives can be claimed through it whether parport came before or after rtapi.ko.
Result<void> prepare_parport(const std::string& ko)
{
    std::error_code ec;
    if (module_loaded(parport_linux) || !fs::exists("/sys/module/parport", ec) ||
        !imports_symbol(ko, "hal_parport_get"))
        return ok();
    unsigned long long seq = next_message_seq();
    HelperRun r = run_helper({"insert", parport_linux});
    if (r.status != 0)
        return insert_error(parport_linux, r, seq);
    return ok();
}

Result<void> remove(const std::string& name)
{
    HelperRun r = run_helper({"remove", name});
    if (r.status != 0) {
        std::string why = first_line(r.err);
        return Error{r.status == 2 ? -EPERM : -EBUSY,
                     name + ": cannot unload: " + (why.empty() ? "emc_module_helper failed" : why)};
    }
    return ok();
}

}  // namespace

std::vector<std::string> hal_modules()
{
    std::vector<ProcModule> all = proc_modules();
    std::set<std::string> users;
    for (const ProcModule& m : all)
        if (is_core(m.name))
            users.insert(m.users.begin(), m.users.end());
    std::vector<std::string> out;
    for (const ProcModule& m : all)
        if (!is_core(m.name) && m.name != parport_linux && users.count(m.name))
            out.push_back(m.name);
    return out;
}

Result<void> load_core()
{
    for (const char* core : {"rtapi", "hal_lib"}) {
        if (module_loaded(core))
            continue;
        unsigned long long seq = next_message_seq();
        HelperRun r = run_helper(core_insert_argv(core));
        if (r.status != 0)
            return insert_error(core, r, seq);
    }
    return ok();
}

Result<std::vector<std::string>> declared_params(const std::string& ko_path)
{
    std::ifstream in(ko_path, std::ios::binary);
    if (!in)
        return Error{-errno, ko_path + ": " + std::strerror(errno)};
    std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    // modinfo strings are NUL-separated; a module (not built-in) has no name prefix.
    const std::string tag("\0parmtype=", 10);
    std::vector<std::string> names;
    for (size_t at = data.find(tag); at != std::string::npos; at = data.find(tag, at + 1)) {
        size_t start = at + tag.size();
        size_t colon = data.find(':', start);
        if (colon != std::string::npos)
            names.push_back(data.substr(start, colon - start));
    }
    return names;
}

unsigned long long next_message_seq()
{
    std::ifstream in(messages_file);
    std::string word;
    unsigned long long seq = 0;
    if (in >> word >> seq && word == "next")
        return seq;
    return 0;
}

std::vector<std::string> error_messages_since(unsigned long long first)
{
    std::vector<std::string> out;
    std::ifstream in(messages_file);
    std::string line;
    std::getline(in, line);                        // "next N"
    while (std::getline(in, line)) {
        std::istringstream words(line);
        unsigned long long seq = 0;
        int level = 0;
        if (!(words >> seq >> level) || seq < first || level != 1)   // 1: RTAPI_MSG_ERR
            continue;
        std::string text;
        std::getline(words >> std::ws, text);
        out.push_back(text);
    }
    return out;
}

Result<void> load_module(const std::string& name, const std::vector<std::string>& items)
{
    if (!is_module_name(name))
        return Error{-EINVAL, name + ": invalid module name (use 1 to 31 of a-z, 0-9 and _)"};
    auto args = parse_module_args(name, items);
    if (!args)
        return args.error();
    std::string ko = module_dir() + "/" + name + ".ko";
    std::error_code ec;
    if (is_core(name) || !fs::exists(ko, ec))
        return Error{-ENOENT, name + ": no such realtime module (" + name +
                                  ".ko is not in the module directory)"};
    if (module_loaded(name))
        return Error{-EEXIST, name + ": already loaded"};
    auto declared = declared_params(ko);
    if (!declared)
        return declared.error();
    std::erase(*declared, std::string(args_param));   // ours, not the user's
    if (auto r = check_module_args(name, *args, *declared); !r)
        return r;
    auto joined = join_module_args(name, *args);
    if (!joined)
        return joined.error();
    if (auto r = load_core(); !r)
        return r;
    std::vector<std::string> argv{"insert", name};
    for (const ModuleArg& a : *args)   // the kernel's parser takes "name=\"a b\""
        argv.push_back(a.name + "=" +
                       (a.value.find(' ') != std::string::npos ? "\"" + a.value + "\"" : a.value));
    // The kernel's quoting has no escapes and knows only double quotes, so the
    // joined form's own quotes become single ones (which loadrt reads alike);
    // arguments holding both kinds are not recorded (show comp and save lack them).
    if (joined->find('\'') == std::string::npos)
        std::replace(joined->begin(), joined->end(), '"', '\'');
    if (!joined->empty() && joined->find('"') == std::string::npos)
        argv.push_back(std::string(args_param) + "=\"" + *joined + "\"");
    if (auto r = prepare_parport(ko); !r)
        return r;
    unsigned long long seq = next_message_seq();
    HelperRun r = run_helper(argv);
    if (r.status != 0)
        return insert_error(name, r, seq);
    return ok();
}

Result<void> unload_module(const std::string& name)
{
    if (name != "all") {
        std::vector<std::string> mods = hal_modules();
        if (std::find(mods.begin(), mods.end(), name) == mods.end())
            return Error{-ENOENT, name + ": not loaded"};
        return remove(name);
    }
    // Dependents first: take whatever nobody uses, until nothing is left.
    for (;;) {
        std::vector<std::string> mods = hal_modules();
        if (mods.empty())
            return module_loaded(parport_linux) ? remove(parport_linux) : ok();
        bool progress = false;
        for (const ProcModule& m : proc_modules()) {
            if (m.refcount != 0 || std::find(mods.begin(), mods.end(), m.name) == mods.end())
                continue;
            if (auto r = remove(m.name); !r)
                return r;
            progress = true;
        }
        if (!progress)
            return Error{-EBUSY, mods.front() + ": cannot unload: still in use"};
    }
}

Result<void> reload_hal_lib()
{
    if (module_loaded("hal_lib"))
        if (auto r = remove("hal_lib"); !r)
            return r;
    return load_core();
}

Result<void> shutdown()
{
    if (auto r = unload_module("all"); !r)
        return r;
    for (const char* core : {"hal_lib", "rtapi"})
        if (module_loaded(core))
            if (auto r = remove(core); !r)
                return r;
    return ok();
}

}  // namespace hal::kmod
