// SPDX-License-Identifier: GPL-2.0-or-later
// module_deps.hpp - which loaded modules a freshly dlopen()ed module binds to.
// The kernel refuses to remove a module whose exports another module uses
// ("in use"); rtapi_app gets the same rule from this: the undefined symbols of
// the new module's dynamic symbol table, matched against what rtapi_app and the
// loaded modules define, in the global scope's search order (ELF files only; no
// dynamic-linker calls, which would pin the objects in memory).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace hal {

struct ModuleFile {
    std::string name;             // module name
    std::filesystem::path path;   // its .so
};

// The names of the modules in 'loaded' that define a symbol 'so' (already
// dlopen()ed) leaves undefined. A file that cannot be read as ELF yields none:
// the check is a safety net, not a loader.
std::vector<std::string> modules_bound_by(const std::filesystem::path& so,
                                          const std::vector<ModuleFile>& loaded);

}  // namespace hal
