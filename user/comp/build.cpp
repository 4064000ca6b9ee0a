// SPDX-License-Identifier: GPL-2.0-or-later
// build.cpp - see build.hpp. External programs (cc, make, man) run through fork/exec
// with an argument vector, never through a shell, so file names need no quoting.
#include "build.hpp"

#include <sys/utsname.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "comp_config.h"
#include "gen_c.hpp"
#include "gen_doc.hpp"
#include "parser.hpp"

namespace hal::comp {

namespace fs = std::filesystem;

namespace {

std::vector<std::string> split_colon(const std::string& s)
{
    std::vector<std::string> out;
    std::stringstream ss(s);
    std::string part;
    while (std::getline(ss, part, ':'))
        if (!part.empty())
            out.push_back(part);
    return out;
}

std::string env_or(const char* name, const std::string& fallback)
{
    const char* v = std::getenv(name);
    return v && *v ? std::string(v) : fallback;
}

// A scratch directory removed with everything in it when it goes out of scope.
class TempDir {
public:
    TempDir()
    {
        std::string tmpl = (fs::temp_directory_path() / "comp.XXXXXX").string();
        if (!mkdtemp(tmpl.data()))
            throw std::runtime_error("cannot create a temporary directory: " +
                                     std::string(std::strerror(errno)));
        path_ = tmpl;
    }
    ~TempDir()
    {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    const fs::path& path() const { return path_; }

private:
    fs::path path_;
};

Result<void> run(const std::vector<std::string>& args)
{
    std::vector<char*> argv;
    for (const auto& a : args)
        argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    pid_t pid = fork();
    if (pid < 0)
        return Error{-errno, "cannot start " + args[0] + ": " + std::strerror(errno)};
    if (pid == 0) {
        execvp(argv[0], argv.data());
        std::fprintf(stderr, "comp: cannot run %s: %s\n", argv[0], std::strerror(errno));
        _exit(127);
    }
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0)
        return {};
    return Error{-1, args[0] + " failed (exit status " +
                         std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + ")"};
}

Result<std::string> read_file(const std::string& file)
{
    std::ifstream in(file, std::ios::binary);
    if (!in)
        return Error{-ENOENT, file + ": cannot open: " + std::strerror(errno)};
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

Result<void> write_file(const fs::path& file, const std::string& text)
{
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    if (out)
        out << text;
    if (!out)
        return Error{-EIO, file.string() + ": cannot write: " + std::strerror(errno)};
    return {};
}

// Read and check a .comp. As halcompile does, the component must be named as its file
// (the module is loaded by the file's name, its pins by the component's).
Result<Component> load_comp(const std::string& file, const Options& o)
{
    auto text = read_file(file);
    if (!text)
        return text.error();
    std::string warnings;
    auto comp = parse_comp(*text, file, &warnings);
    if (!warnings.empty())
        std::fputs(warnings.c_str(), stderr);
    if (!comp)
        return comp;
    std::string stem = fs::path(file).stem().string();
    if (comp->name != stem)
        return Error{-1, file + ":" + std::to_string(comp->line) + ": component name '" + comp->name +
                             "' does not match the file name '" + stem + "': rename one of them"};
    comp->max_personalities = o.personalities;
    return comp;
}

std::string today()
{
    std::time_t t = std::time(nullptr);
    char buf[32];
    std::strftime(buf, sizeof(buf), "%Y-%m-%d", std::localtime(&t));
    return buf;
}

std::string kernel_release()
{
    struct utsname u {};
    uname(&u);
    return u.release;
}

bool ends_with(const std::string& s, const std::string& tail)
{
    return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

std::vector<std::string> words(const std::string& s)
{
    std::vector<std::string> out;
    std::istringstream ss(s);
    std::string w;
    while (ss >> w)
        out.push_back(w);
    return out;
}

// The C source to compile for 'file' (a .comp is preprocessed into dir) and facts about it.
struct Source {
    fs::path c_file;
    std::string module;  // output name: the file's base name
    bool uses_fp = true;
    bool userspace = false;
    // Kernel flavor: the FP code's own translation unit (FP code only in *_fp objects,
    // compiled with SSE; the rest without): comp's FP part of the generated file, or
    // NAME_fp.c beside a hand-written NAME.c. Empty: one object, without SSE.
    fs::path fp_file;
    std::string compile_args, link_args;
};

Result<Source> prepare(const std::string& file, const fs::path& dir, const Options& o)
{
    bool force_userspace = o.userspace;
    Source s;
    s.module = fs::path(file).stem().string();
    if (ends_with(file, ".c")) {
        s.c_file = fs::absolute(file);
        s.userspace = force_userspace;
        s.compile_args = o.extra_compile_args;
        s.link_args = o.extra_link_args;
        fs::path fp = fs::absolute(file).parent_path() / (s.module + "_fp.c");
        if (fs::exists(fp))
            s.fp_file = fp;
        return s;
    }
    auto comp = load_comp(file, o);
    if (!comp)
        return comp.error();
    s.userspace = force_userspace || comp->is_userspace();
    if (force_userspace && !comp->is_userspace())
        return Error{-1, file + ": --userspace given but the component has no 'option userspace'"};
    s.uses_fp = false;
    for (const Function& f : comp->functions)
        s.uses_fp = s.uses_fp || f.fp;
    s.compile_args = comp->option_value("extra_compile_args") + " " + o.extra_compile_args;
    s.link_args = comp->option_value("extra_link_args") + " " + o.extra_link_args;
    s.c_file = dir / (s.module + ".c");
    if (auto r = write_file(s.c_file, generate_c(*comp)); !r)
        return r.error();
    if (s.uses_fp && !s.userspace)
        s.fp_file = s.c_file;  // the same file with -D__COMP_PART_FP (gen_c.cpp)
    return s;
}

void add_includes(std::vector<std::string>& cmd, const std::string& file, const Paths& p)
{
    cmd.push_back("-I" + fs::absolute(file).parent_path().string());  // the .comp's own headers
    for (const auto& d : p.include_dirs)
        cmd.push_back("-I" + d);
}

// Simulated flavor: the flags of hal_rt_module() in the top-level CMakeLists.txt.
Result<fs::path> compile_sim(const Source& s, const std::string& file, const Paths& p,
                             const fs::path& out)
{
    std::vector<std::string> cmd = {env_or("CC", "cc"), "-std=gnu11", "-O2", "-g", "-fPIC",
                                    "-shared", "-DRTAPI"};
    for (const auto& f : words(COMP_RT_C_FLAGS))
        cmd.push_back(f);
    for (const auto& f : words(COMP_SANITIZE_FLAGS))   // empty but in a sanitizer build
        cmd.push_back(f);
    add_includes(cmd, file, p);
    for (const auto& w : words(s.compile_args))
        cmd.push_back(w);
    cmd.insert(cmd.end(), {"-o", out.string(), s.c_file.string()});
    if (!s.fp_file.empty() && s.fp_file != s.c_file)
        cmd.push_back(s.fp_file.string());
    for (const auto& w : words(s.link_args))
        cmd.push_back(w);
    if (auto r = run(cmd); !r)
        return Error{-1, file + ": compiling failed"};
    return out;
}

// Kernel flavor: a one-module kbuild tree in 'dir', linked against rtapi/hal_lib's symbols.
Result<fs::path> compile_kernel(const Source& s, const std::string& file, const Paths& p,
                                const fs::path& dir, const fs::path& out)
{
    // KDIR as kernel/Makefile.kmod chooses it: the running kernel's build directory,
    // else the (non-rt) Debian header package.
    std::string kdir = env_or("KDIR", "/lib/modules/" + kernel_release() + "/build");
    if (!std::getenv("KDIR") && !fs::exists(fs::path(kdir) / "Makefile")) {
        std::error_code ec;
        for (const auto& e : fs::directory_iterator("/usr/src", ec)) {
            std::string n = e.path().filename().string();
            if (n.starts_with("linux-headers-") && ends_with(n, "-amd64") && !ends_with(n, "-rt-amd64"))
                kdir = e.path().string();
        }
    }
    auto release = read_file(kdir + "/include/config/kernel.release");
    if (!release)
        return Error{-ENOENT, file + ": no kernel headers in " + kdir + " (set KDIR)"};
    std::string kver = release->substr(0, release->find_first_of("\n"));
    std::string kmod_build = env_or("HAL_KMOD_BUILD", std::string(COMP_KMOD_BUILD_DIR) + "/" + kver);
    fs::path symvers = fs::path(kmod_build) / "Module.symvers";
    if (!fs::exists(symvers))
        return Error{-ENOENT, file + ": " + symvers.string() +
                                  " not found: build the kernel modules first (make kmod) or set HAL_KMOD_BUILD"};
    fs::create_directories(dir);
    if (s.c_file.parent_path() != dir)
        fs::copy_file(s.c_file, dir / (s.module + ".c"), fs::copy_options::overwrite_existing);
    std::ostringstream kb;
    kb << "ccflags-y += -DRTAPI -I" << fs::absolute(file).parent_path().string();
    for (const auto& d : p.include_dirs)
        kb << " -I" << d;
    kb << " " << s.compile_args << "\nobj-m += " << s.module << ".o\n";
    if (!s.fp_file.empty()) {
        // two objects, as kernel/kmod-manifest.sh builds them: the glue NAME_main.o
        // without SSE, NAME_fp.o with the FP flags of kernel/Kbuild
        std::string glue = s.module + "_main", fp = s.module + "_fp";
        bool comp_parts = s.fp_file == s.c_file;
        auto r = comp_parts ? write_file(dir / (glue + ".c"),
                                         "#define __COMP_PART_GLUE\n#include \"" + s.module + ".c\"\n")
                            : write_file(dir / (glue + ".c"), "#include \"" + s.c_file.string() + "\"\n");
        if (!r)
            return r.error();
        r = comp_parts ? write_file(dir / (fp + ".c"), "#define __COMP_PART_FP\n#include \"" + s.module + ".c\"\n")
                       : write_file(dir / (fp + ".c"), "#include \"" + s.fp_file.string() + "\"\n");
        if (!r)
            return r.error();
        kb << s.module << "-y := " << glue << ".o " << fp << ".o\n"
           << "CFLAGS_" << fp << ".o += -msse -msse2 -fno-math-errno -ffp-contract=off\n"
           << "CFLAGS_REMOVE_" << fp << ".o += -mno-sse -mno-sse2 -mno-mmx -mno-80387 "
              "-mno-fp-ret-in-387\n";
    }
    if (auto r = write_file(dir / "Kbuild", kb.str()); !r)
        return r.error();
    if (auto r = run({"make", "-C", kdir, "M=" + dir.string(),
                      "KBUILD_EXTRA_SYMBOLS=" + symvers.string(), "modules"});
        !r)
        return Error{-1, file + ": kbuild failed"};
    fs::copy_file(dir / (s.module + ".ko"), out, fs::copy_options::overwrite_existing);
    return out;
}

Result<fs::path> compile_userspace(const Source& s, const std::string& file, const Paths& p,
                                   const fs::path& out)
{
    std::vector<std::string> cmd = {env_or("CC", "cc"), "-std=gnu11", "-O2", "-g", "-DULAPI"};
    // A sanitizer build's hal_ul/rtapi_ul are instrumented: link the runtime they need.
    for (const auto& f : words(COMP_SANITIZE_FLAGS))
        cmd.push_back(f);
    add_includes(cmd, file, p);
    for (const auto& w : words(s.compile_args))
        cmd.push_back(w);
    cmd.insert(cmd.end(), {"-o", out.string(), s.c_file.string()});
    for (const auto& l : p.ul_libs)
        cmd.push_back(l);
    for (const auto& w : words(s.link_args))
        cmd.push_back(w);
    cmd.insert(cmd.end(), {"-lpthread", "-lrt", "-lm"});
    if (auto r = run(cmd); !r)
        return Error{-1, file + ": compiling failed"};
    return out;
}

Result<void> install_file(const fs::path& from, const fs::path& dir, bool executable)
{
    std::error_code ec;
    fs::create_directories(dir, ec);
    fs::path to = dir / from.filename();
    fs::copy_file(from, to, fs::copy_options::overwrite_existing, ec);
    if (ec)
        return Error{-ec.value(), "cannot install " + to.string() + ": " + ec.message()};
    fs::permissions(to, executable ? fs::perms(0755) : fs::perms(0644), ec);
    return {};
}

Result<void> do_build(const Options& o, const std::string& file, const Paths& p)
{
    if (ends_with(file, ".py")) {
        if (o.mode != Mode::Install || !o.userspace)
            return Error{-1, file + ": a .py file can only be installed (--install --userspace)"};
        return install_file(file, p.bin_dir, true);
    }
    TempDir tmp;
    auto src = prepare(file, tmp.path(), o);
    if (!src)
        return src.error();
    bool kernel = !src->userspace && p.flavor == "kernel";
    std::string ext = src->userspace ? "" : kernel ? ".ko" : ".so";
    fs::path out = o.mode == Mode::Install ? tmp.path() / (src->module + ext + ".out")
                   : o.output.empty()     ? fs::path(src->module + ext)
                                          : fs::path(o.output);
    Result<fs::path> built = src->userspace ? compile_userspace(*src, file, p, out)
                             : kernel       ? compile_kernel(*src, file, p, tmp.path() / "kbuild", out)
                                            : compile_sim(*src, file, p, out);
    if (!built)
        return built.error();
    if (o.mode != Mode::Install)
        return {};
    fs::path final_name = tmp.path() / (src->module + ext);
    fs::rename(out, final_name);
    if (src->userspace)
        return install_file(final_name, p.bin_dir, true);
    if (kernel)  // the helper loads modules from one directory per kernel release
        return install_file(final_name, fs::path(p.rtlib_dir) / kernel_release(), false);
    return install_file(final_name, p.rtlib_dir, false);
}

}  // namespace

// Where the halrun on PATH (else this comp) loads modules from: a run-in-place tree's
// rtlib/ beside bin/, or an installed prefix's lib/hal/rtlib; else the compiled-in one.
std::string halrun_module_dir()
{
    std::vector<fs::path> exes;
    if (const char* path = std::getenv("PATH"))
        for (const std::string& d : split_colon(path))
            if (!d.empty() && fs::exists(fs::path(d) / "halrun")) {
                exes.push_back(fs::path(d) / "halrun");
                break;
            }
    std::error_code ec;
    if (fs::path self = fs::read_symlink("/proc/self/exe", ec); !ec)
        exes.push_back(self);
    for (const fs::path& exe : exes) {
        fs::path bin = fs::canonical(exe, ec).parent_path();
        if (ec)
            continue;
        if (fs::is_directory(bin.parent_path() / "rtlib", ec))
            return (bin.parent_path() / "rtlib").string();
        if (fs::is_directory(bin.parent_path() / "lib/hal/rtlib", ec))
            return (bin.parent_path() / "lib/hal/rtlib").string();
    }
    return COMP_INSTALL_RTLIB_DIR;
}

Paths find_paths()
{
    Paths p;
    if (const char* inc = std::getenv("HAL_INCLUDE_DIR"); inc && *inc) {
        p.include_dirs = split_colon(inc);
    } else {
        // An installed comp finds the installed headers; one in the build tree the sources.
        std::error_code ec;
        fs::path exe = fs::read_symlink("/proc/self/exe", ec);
        bool in_build = !ec && exe.parent_path() == fs::path(COMP_BUILD_BIN_DIR);
        p.include_dirs = in_build || !fs::is_directory(COMP_INSTALL_INCLUDE_DIR)
                             ? split_colon(COMP_SOURCE_INCLUDE_DIRS)
                             : std::vector<std::string>{COMP_INSTALL_INCLUDE_DIR};
        p.ul_libs = in_build || !fs::exists(COMP_INSTALL_UL_LIBS_PROBE) ? split_colon(COMP_BUILD_UL_LIBS)
                                                                        : split_colon(COMP_INSTALL_UL_LIBS);
    }
    if (p.ul_libs.empty())
        p.ul_libs = split_colon(fs::exists(COMP_INSTALL_UL_LIBS_PROBE) ? COMP_INSTALL_UL_LIBS
                                                                       : COMP_BUILD_UL_LIBS);
    p.rtlib_dir = env_or("HAL_RTLIB_DIR", halrun_module_dir());
    p.bin_dir = env_or("HAL_BIN_DIR", COMP_INSTALL_BIN_DIR);
    p.man9_dir = env_or("HAL_MAN_DIR", COMP_INSTALL_MAN9_DIR);
    std::string flavor = env_or("HAL_FLAVOR", "");
    if (flavor.empty())
        flavor = fs::exists("/proc/rtapi") ? "kernel" : "sim";  // rtapi.ko loaded: kernel flavor
    p.flavor = flavor;
    return p;
}

Result<void> process_file(const Options& o, const std::string& file, const Paths& p)
{
    bool is_comp = ends_with(file, ".comp");
    if (!is_comp && !ends_with(file, ".c") && !ends_with(file, ".py"))
        return Error{-1, file + ": not a .comp, .c or .py file"};
    if (p.flavor != "sim" && p.flavor != "kernel")
        return Error{-1, "HAL_FLAVOR must be sim or kernel, not '" + p.flavor + "'"};
    switch (o.mode) {
    case Mode::Compile:
    case Mode::Install:
        return do_build(o, file, p);
    case Mode::Preprocess:
    case Mode::Document:
    case Mode::ViewDoc:
    case Mode::InstallDoc: {
        if (!is_comp)
            return Error{-1, file + ": only a .comp file can be preprocessed or documented"};
        auto comp = load_comp(file, o);
        if (!comp)
            return comp.error();
        fs::path base = fs::path(file).replace_extension();
        if (o.mode == Mode::Preprocess)
            return write_file(o.output.empty() ? base.string() + ".c" : o.output, generate_c(*comp));
        std::string doc = generate_doc(*comp, today());
        if (o.mode == Mode::Document)
            return write_file(o.output.empty() ? base.string() + ".9" : o.output, doc);
        if (o.mode == Mode::InstallDoc) {
            std::error_code ec;
            fs::create_directories(p.man9_dir, ec);
            return write_file(fs::path(p.man9_dir) / (base.filename().string() + ".9"), doc);
        }
        TempDir tmp;
        fs::path page = tmp.path() / (base.filename().string() + ".9");
        if (auto r = write_file(page, doc); !r)
            return r;
        return run({"man", "-l", page.string()});
    }
    }
    return {};
}

}  // namespace hal::comp
