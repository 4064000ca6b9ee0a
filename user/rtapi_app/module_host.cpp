// SPDX-License-Identifier: GPL-2.0-or-later
// module_host.cpp - dlopen()ing realtime modules into rtapi_app: parameters are
// collected while the object's constructors run, arguments applied, then
// rtapi_app_main() runs with the module recorded as the load context of the HAL
// components it creates (hal_host.h).
#include "module_host.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>

#include "hal_host.h"
#include "module_deps.hpp"
#include "rtapi.h"
#include "rtapi_app.h"
#include "rtapi_modparam_uspace.h"
#include "rtapi_symbol.h"

static_assert(RTAPI_NAME_LEN == 31, "is_module_name() in module_args.cpp assumes 31");

#ifndef HAL_INSTALL_RTLIB
#error "HAL_INSTALL_RTLIB must name the installed module directory"
#endif

namespace hal {
namespace {

struct DlClose {
    void operator()(void* h) const noexcept
    {
        if (h)
            dlclose(h);
    }
};
using DlHandle = std::unique_ptr<void, DlClose>;

// ERR messages printed while one load() runs. Owned by MessageCapture; the
// handler may also be called from module threads, hence the mutex.
struct CaptureState {
    std::mutex lock;
    std::vector<std::string> errors;
    rtapi_msg_handler_t previous = nullptr;
};
CaptureState capture_state;

extern "C" void capture_msg(msg_level_t level, const char* msg)
{
    std::lock_guard<std::mutex> hold(capture_state.lock);
    if (level != RTAPI_MSG_ERR) {
        if (capture_state.previous)
            capture_state.previous(level, msg);
        else
            std::fputs(msg, stderr);
        return;
    }
    // One line per message: the reply and halcmd's error are line-based.
    std::string line(msg);
    while (!line.empty() && (line.back() == '\n' || line.back() == ' '))
        line.pop_back();
    std::replace(line.begin(), line.end(), '\n', ' ');
    if (!line.empty())
        capture_state.errors.push_back(std::move(line));
}

// Routes rtapi_print_msg() ERR output into capture_state while it lives.
class MessageCapture {
public:
    MessageCapture()
    {
        std::lock_guard<std::mutex> hold(capture_state.lock);
        capture_state.errors.clear();
        capture_state.previous = rtapi_get_msg_handler();
        rtapi_set_msg_handler(capture_msg);
    }
    ~MessageCapture()
    {
        rtapi_set_msg_handler(capture_state.previous);
        std::lock_guard<std::mutex> hold(capture_state.lock);
        capture_state.previous = nullptr;
    }
    MessageCapture(const MessageCapture&) = delete;
    MessageCapture& operator=(const MessageCapture&) = delete;

    std::vector<std::string> take()
    {
        std::lock_guard<std::mutex> hold(capture_state.lock);
        return std::move(capture_state.errors);
    }
};

Error module_error(int code, const std::string& module, const std::string& what)
{
    return Error{code, module + ": " + what};
}

// Apply each argument through rtapi_mp_set(), which parses the value by the
// parameter's type and splits comma arrays.
Result<void> apply_args(const std::string& name, const std::vector<ModuleArg>& args,
                        const rtapi_mp_desc* const* descs, int count)
{
    std::vector<std::string> declared;
    for (int i = 0; i < count; ++i)
        declared.emplace_back(descs[i]->name);
    if (auto r = check_module_args(name, args, declared); !r)
        return r;
    for (const ModuleArg& a : args) {
        auto at = std::find(declared.begin(), declared.end(), a.name) - declared.begin();
        char err[256] = "";
        int rc = rtapi_mp_set(descs[at], a.value.c_str(), err, sizeof(err));
        if (rc < 0) {
            std::string why = err[0] ? err : "parameter '" + a.name + "': bad value '" +
                                                 a.value + "'";
            return module_error(rc, name, why);
        }
    }
    return {};
}

}  // namespace

std::filesystem::path module_dir()
{
    if (const char* env = std::getenv("HAL_RTLIB_DIR"); env && *env)
        return env;
    std::error_code ec;
    auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        auto beside = exe.parent_path().parent_path() / "rtlib";
        if (std::filesystem::is_directory(beside, ec))
            return beside;
    }
    return HAL_INSTALL_RTLIB;
}

struct ModuleHost::Loaded {
    std::string name;
    DlHandle handle;
    void (*exit_fn)(void) = nullptr;
    std::vector<std::string> uses;  // loaded modules whose exports this one binds
};

namespace {
// The host whose load() is running a module's rtapi_app_main, for rtapi_symbol_get
// (called from there, in the daemon's command thread, like every load).
ModuleHost* loading_host = nullptr;
}  // namespace

ModuleHost::ModuleHost(std::filesystem::path dir) : dir_(std::move(dir)) {}

void* ModuleHost::symbol_get(const char* name)
{
    for (const auto& m : loaded_) {
        void* addr = dlsym(m->handle.get(), name);
        Dl_info info{};
        // defined by that module itself, not by a library it links
        if (!addr || !dladdr(addr, &info) || !info.dli_fname ||
            std::filesystem::path(info.dli_fname).filename() != m->name + ".so")
            continue;
        loading_uses_.push_back(m->name);
        return addr;
    }
    return nullptr;
}

ModuleHost::~ModuleHost()
{
    (void)unload("all");
}

Result<void> ModuleHost::load(const std::string& name, const std::vector<ModuleArg>& args)
{
    if (!is_module_name(name))
        return module_error(-EINVAL, name, "invalid module name (use 1 to 31 of a-z, 0-9 and _)");
    auto same = [&](const auto& m) { return m->name == name; };
    if (std::any_of(loaded_.begin(), loaded_.end(), same))
        return module_error(-EEXIST, name, "already loaded");
    std::filesystem::path so = dir_ / (name + ".so");
    std::error_code ec;
    if (!std::filesystem::exists(so, ec))
        return module_error(-ENOENT, name, "no such realtime module (" + so.filename().string() + " is not in the module directory)");
    // A previous instance still mapped (another module bound to its symbols) would
    // not run its constructors again, so its parameters could not be set.
    if (DlHandle old{dlopen(so.c_str(), RTLD_NOW | RTLD_NOLOAD)}; old)
        return module_error(-EBUSY, name, "still mapped from an earlier load; unload the "
                                          "modules that use it first");

    rtapi_mp_collect_begin();
    DlHandle handle{dlopen(so.c_str(), RTLD_NOW | RTLD_GLOBAL)};  // later modules use its exports
    std::string dl_error = handle ? "" : dlerror();
    const rtapi_mp_desc** descs = nullptr;
    int count = rtapi_mp_collect_end(&descs);
    if (!handle)
        return module_error(-ENOEXEC, name, "dlopen: " + dl_error);  // the prefix LinuxCNC prints
    if (count < 0)
        return module_error(count, name, "cannot collect its module parameters");
    if (auto r = apply_args(name, args, descs, count); !r)
        return r;

    auto main_fn = reinterpret_cast<int (*)(void)>(dlsym(handle.get(), "rtapi_app_main"));
    auto exit_fn = reinterpret_cast<void (*)(void)>(dlsym(handle.get(), "rtapi_app_exit"));
    if (!main_fn || !exit_fn)
        return module_error(-ENOEXEC, name, so.filename().string() + " has no " +
                                                (main_fn ? "rtapi_app_exit()" : "rtapi_app_main()"));
    auto joined = join_module_args(name, args);
    if (!joined)
        return joined.error();
    std::vector<ModuleFile> before;
    for (const auto& m : loaded_)
        before.push_back({m->name, dir_ / (m->name + ".so")});
    std::vector<std::string> uses = modules_bound_by(so, before);

    MessageCapture capture;
    hal_set_load_context(name.c_str(), joined->c_str());
    loading_uses_.clear();
    loading_host = this;
    int rc = main_fn();
    loading_host = nullptr;
    hal_set_load_context(nullptr, nullptr);
    // rtapi_symbol_get() lookups bind like linked references: those modules stay
    uses.insert(uses.end(), loading_uses_.begin(), loading_uses_.end());
    std::vector<std::string> errors = capture.take();
    if (rc != 0) {
        hal_exit_module_comps(name.c_str());  // whatever init left behind
        handle.reset();
        std::string msg;
        for (const std::string& e : errors)
            msg += e + "; ";
        msg += name + ": rtapi_app_main failed: " + std::strerror(-rc) + " (" +
               std::to_string(rc) + ")";
        return Error{rc < 0 ? rc : -EINVAL, msg};
    }
    // Loaded fine but complained: nobody asked, so the daemon's log gets it.
    for (const std::string& e : errors)
        std::fprintf(stderr, "%s\n", e.c_str());
    loaded_.push_back(
        std::make_unique<Loaded>(Loaded{name, std::move(handle), exit_fn, std::move(uses)}));
    return {};
}

void ModuleHost::unload_one(Loaded& m)
{
    m.exit_fn();
    hal_exit_module_comps(m.name.c_str());
    m.handle.reset();
}

Result<void> ModuleHost::unload(const std::string& name)
{
    if (name == "all") {
        while (!loaded_.empty()) {
            unload_one(*loaded_.back());
            loaded_.pop_back();
        }
        hal_exit_threads();  // threads outlive the module that made them, not the host
        return {};
    }
    auto it = std::find_if(loaded_.begin(), loaded_.end(),
                           [&](const auto& m) { return m->name == name; });
    if (it == loaded_.end())
        return module_error(-ENOENT, name, "not loaded");
    // The kernel's rule: a module whose exports another one calls stays.
    std::string users;
    for (const auto& m : loaded_)
        if (std::find(m->uses.begin(), m->uses.end(), name) != m->uses.end())
            users += (users.empty() ? "" : ", ") + m->name;
    if (!users.empty())
        return module_error(-EBUSY, name, "in use by " + users + " (unload it first)");
    unload_one(**it);
    loaded_.erase(it);
    return {};
}

std::vector<std::string> ModuleHost::list() const
{
    std::vector<std::string> names;
    for (const auto& m : loaded_)
        names.push_back(m->name);
    return names;
}

}  // namespace hal

// rtapi.h: only a module's rtapi_app_main, run by ModuleHost::load, finds symbols.
extern "C" void* rtapi_symbol_get(const char* name)
{
    return hal::loading_host && name ? hal::loading_host->symbol_get(name) : nullptr;
}

// The exporter stays until the caller's module is unloaded (its uses list goes with
// it), so there is nothing to release early.
extern "C" void rtapi_symbol_put(const char*) {}
