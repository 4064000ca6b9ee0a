// SPDX-License-Identifier: GPL-2.0-or-later
// module_deps.cpp - undefined dynamic symbols of a module, and who defines them.
#include "module_deps.hpp"

#include <dlfcn.h>
#include <elf.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>
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

// Names of the global/weak undefined symbols in .dynsym (64-bit ELF only: the
// only kind rtapi_app loads).
std::vector<std::string> undefined_symbols(const std::vector<char>& img)
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
            if (syms[k].st_shndx != SHN_UNDEF || (bind != STB_GLOBAL && bind != STB_WEAK) ||
                syms[k].st_name == 0 || syms[k].st_name >= strtab.sh_size)
                continue;
            const char* name = str + syms[k].st_name;
            if (std::memchr(name, '\0', strtab.sh_size - syms[k].st_name))
                names.emplace_back(name);
        }
    }
    return names;
}

}  // namespace

std::vector<std::string> modules_bound_by(const std::filesystem::path& so,
                                          const std::vector<ModuleFile>& loaded)
{
    std::set<std::string> users;
    if (loaded.empty())
        return {};
    std::error_code ec;
    std::vector<std::pair<std::filesystem::path, std::string>> files;
    for (const ModuleFile& m : loaded)
        files.emplace_back(std::filesystem::weakly_canonical(m.path, ec), m.name);
    for (const std::string& sym : undefined_symbols(read_file(so))) {
        void* addr = dlsym(RTLD_DEFAULT, sym.c_str());  // the scope RTLD_NOW bound it in
        Dl_info info{};
        if (!addr || !dladdr(addr, &info) || !info.dli_fname)
            continue;
        auto where = std::filesystem::weakly_canonical(info.dli_fname, ec);
        for (const auto& [path, name] : files)
            if (path == where)
                users.insert(name);
    }
    return {users.begin(), users.end()};
}

}  // namespace hal
