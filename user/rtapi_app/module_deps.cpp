// SPDX-License-Identifier: GPL-2.0-or-later
// module_deps.cpp - undefined dynamic symbols of a module, and who defines them.
#include "module_deps.hpp"

#include <elf.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <set>

namespace hal {
namespace {

std::vector<char> read_file(const std::filesystem::path& p)
{
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

template <typename T>
const T* at(const std::vector<char>& img, std::uint64_t off, std::uint64_t count = 1)
{
    if (off > img.size() || count > (img.size() - off) / sizeof(T))
        return nullptr;
    return reinterpret_cast<const T*>(img.data() + off);
}

// Names of the global/weak symbols in .dynsym that 'so' leaves undefined
// (defined = false) or defines (defined = true). 64-bit ELF only: the only kind
// rtapi_app loads.
std::vector<std::string> dynamic_symbols(const std::vector<char>& img, bool defined)
{
    std::vector<std::string> names;
    const auto* eh = at<Elf64_Ehdr>(img, 0);
    if (!eh || std::memcmp(eh->e_ident, ELFMAG, SELFMAG) != 0 ||
        eh->e_ident[EI_CLASS] != ELFCLASS64 || eh->e_shentsize != sizeof(Elf64_Shdr))
        return names;
    const auto* sh = at<Elf64_Shdr>(img, eh->e_shoff, eh->e_shnum);
    if (!sh)
        return names;
    for (unsigned i = 0; i < eh->e_shnum; ++i) {
        if (sh[i].sh_type != SHT_DYNSYM || sh[i].sh_link >= eh->e_shnum ||
            sh[i].sh_entsize != sizeof(Elf64_Sym))
            continue;
        const Elf64_Shdr& strtab = sh[sh[i].sh_link];
        const auto* syms = at<Elf64_Sym>(img, sh[i].sh_offset, sh[i].sh_size / sizeof(Elf64_Sym));
        const char* str = at<char>(img, strtab.sh_offset, strtab.sh_size);
        if (!syms || !str)
            continue;
        for (std::uint64_t k = 0; k < sh[i].sh_size / sizeof(Elf64_Sym); ++k) {
            int bind = ELF64_ST_BIND(syms[k].st_info);
            bool is_defined = syms[k].st_shndx != SHN_UNDEF;
            if (is_defined != defined || (bind != STB_GLOBAL && bind != STB_WEAK) ||
                syms[k].st_name == 0 || syms[k].st_name >= strtab.sh_size)
                continue;
            const char* name = str + syms[k].st_name;
            if (std::memchr(name, '\0', strtab.sh_size - syms[k].st_name))
                names.emplace_back(name);
        }
    }
    return names;
}

// The symbols a file defines, read once per file and modification time: a
// module is parsed again only when it was rebuilt.
const std::set<std::string>& defined_symbols(const std::filesystem::path& p)
{
    struct Entry {
        std::filesystem::file_time_type mtime;
        std::set<std::string> names;
    };
    static std::map<std::filesystem::path, Entry> cache;
    std::error_code ec;
    auto mtime = std::filesystem::last_write_time(p, ec);
    auto it = cache.find(p);
    if (it == cache.end() || it->second.mtime != mtime) {
        auto list = dynamic_symbols(read_file(p), true);
        it = cache.insert_or_assign(p, Entry{mtime, {list.begin(), list.end()}}).first;
    }
    return it->second.names;
}

}  // namespace

std::vector<std::string> modules_bound_by(const std::filesystem::path& so,
                                          const std::vector<ModuleFile>& loaded)
{
    // Not dlsym(RTLD_DEFAULT): glibc then records the defining object as a
    // dependency of rtapi_app itself, and it could never be unmapped again. The
    // global scope is searched in order: rtapi_app, then the modules as loaded.
    std::set<std::string> users;
    if (loaded.empty())
        return {};
    const std::set<std::string>& host = defined_symbols("/proc/self/exe");
    for (const std::string& sym : dynamic_symbols(read_file(so), false)) {
        if (host.count(sym))
            continue;
        for (const ModuleFile& m : loaded)
            if (defined_symbols(m.path).count(sym)) {
                users.insert(m.name);
                break;
            }
    }
    return {users.begin(), users.end()};
}

}  // namespace hal
