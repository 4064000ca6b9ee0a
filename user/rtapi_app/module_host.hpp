// SPDX-License-Identifier: GPL-2.0-or-later
// module_host.hpp - the modules rtapi_app has dlopen()ed, in load order: loading
// with insmod-style arguments (rtapi_module_param(3rtapi)), rtapi_app_main() with
// its error messages captured, and unloading through rtapi_app_exit().
// Used by the daemon's single thread only.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "hal/result.hpp"
#include "module_args.hpp"

namespace hal {

// The module directory: $HAL_RTLIB_DIR, else <dir of this executable>/../rtlib
// when it exists (build tree), else the installed HAL_INSTALL_RTLIB.
std::filesystem::path module_dir();

class ModuleHost {
public:
    explicit ModuleHost(std::filesystem::path dir);
    ~ModuleHost();  // unloads everything still loaded, newest first
    ModuleHost(const ModuleHost&) = delete;
    ModuleHost& operator=(const ModuleHost&) = delete;

    // Load 'name' (its file is <dir>/<name>.so) with 'args' and run its
    // rtapi_app_main(). On failure nothing stays loaded and the error is one line:
    // the module's own ERR messages, then ours, joined with "; ".
    Result<void> load(const std::string& name, const std::vector<ModuleArg>& args);

    // rtapi_app_exit(), remove the module's HAL components, dlclose(). "all"
    // unloads every module, newest first. Not loaded: "M: not loaded".
    Result<void> unload(const std::string& name);

    std::vector<std::string> list() const;  // names in load order
    bool empty() const { return loaded_.empty(); }

    // rtapi_symbol_get() for the module being loaded: NAME as a loaded module defines
    // it; that module then counts as used by the new one (unloadrt refuses it).
    void* symbol_get(const char* name);

private:
    struct Loaded;
    void unload_one(Loaded& m);

    std::filesystem::path dir_;
    std::vector<std::unique_ptr<Loaded>> loaded_;  // load order
    std::vector<std::string> loading_uses_;  // symbol_get()s of the module being loaded
};

}  // namespace hal
