// The grading bundle (bundle.h) as a list of named steps: the workspace's trees copied, the
// plan's commands made to run anywhere, the headers and libraries the target lacks shipped.
#include "package/bundle.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <utility>

#include "util.h"

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace rt::grader {
namespace {

// The compiler the commands name on the target: the same name on Debian 12 and Ubuntu 22.04
// (target_packages.txt), and the compiler the workspace was built with on Debian 12.
constexpr const char* kTargetCompiler = "/usr/bin/g++-12";

// Headers the target's compiler brings with it (g++-12's own dependencies): never shipped, so
// the C library's and libstdc++'s headers always match the target's libraries.
const std::set<std::string> kCompilerHeaderPackages = {
    "libc6-dev",    "linux-libc-dev", "libstdc++-12-dev", "libgcc-12-dev", "libcrypt-dev",
    "libtirpc-dev", "libnsl-dev",     "gcc-12",           "g++-12",        "cpp-12",
};

// What one bundle needs to know while it is written.
struct Bundling {
    const BundleRequest& r;
    fs::path cache;    // BUNDLE/cache
    fs::path src;      // BUNDLE/cache/workspace/src
    fs::path build;    // BUNDLE/cache/workspace/src/build
    fs::path lib;      // BUNDLE/cache/runtime/lib
    fs::path include;  // BUNDLE/cache/runtime/include
    std::set<std::string> target_sonames;
    std::ostream& log;
};

void copy_file_into(const fs::path& from, const fs::path& to) {
    fs::create_directories(to.parent_path());
    fs::copy_file(from, to, fs::copy_options::overwrite_existing);
}

// Does the path `path` (a command's argument) lie inside the folder `dir`?
bool is_under(const std::string& path, const fs::path& dir) {
    const std::string d = dir.string() + "/";
    return path.starts_with(d);
}

// The public tree: what a grading's children read (framework headers, stage files, scenes,
// shaders). Hidden tests, the build and the instructor's tools stay behind.
void copy_public_tree(const Bundling& b) {
    const fs::path from = b.r.workspace.src;
    const std::set<std::string> kept = {"framework", "stages", "shaders"};
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(from, ec);
         !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        const fs::path rel = it->path().lexically_relative(from);
        const std::string name = it->path().filename().string();
        const bool dropped = (it.depth() == 0 && !kept.count(name)) ||
                             (it.depth() == 2 && *rel.begin() == "stages" && name == "hidden");
        if (dropped) {
            it.disable_recursion_pending();
            continue;
        }
        if (it->is_regular_file()) copy_file_into(it->path(), b.src / rel);
    }
}

// The private folder as it is: judges, pristine objects, references, plan, secret.
void copy_private(const Bundling& b) {
    fs::create_directories(b.cache / "private");
    fs::copy(b.r.workspace.priv, b.cache / "private",
             fs::copy_options::recursive | fs::copy_options::overwrite_existing);
    fs::permissions(b.cache / "private", fs::perms::owner_all);
}

// A shared library's soname (its DT_SONAME), or its file name when it has none.
std::string soname_of(const fs::path& library) {
    const auto out = command_output("readelf -d -W " + shell_quote(library.string()) +
                                    " 2>/dev/null | sed -n 's/.*(SONAME).*\\[\\(.*\\)\\]/\\1/p'");
    const std::string name(trim(out.value_or("")));
    return name.empty() ? library.filename().string() : name;
}

// A library a link command names by its system path, shipped into runtime/lib under the name
// the loader will ask for; returns the command's new argument.
std::string ship_link_library(const Bundling& b, const std::string& arg) {
    const fs::path real = fs::canonical(arg);
    const bool shared = arg.find(".so") != std::string::npos;
    const std::string name = shared ? soname_of(real) : fs::path(arg).filename().string();
    copy_file_into(real, b.lib / name);
    return std::string(kCachePlaceholder) + "/runtime/lib/" + name;
}

// The cache's own paths as the placeholder, wherever they occur in an argument.
std::string placeheld(std::string arg, const fs::path& cache) {
    const std::string from = cache.string();
    for (std::size_t p; (p = arg.find(from)) != std::string::npos;)
        arg.replace(p, from.size(), kCachePlaceholder);
    return arg;
}

// A link command made portable: the target's compiler, the build's inputs copied into the
// bundle, system libraries shipped, the build tree's run paths dropped (LD_LIBRARY_PATH and
// the libraries' own $ORIGIN find them).
std::vector<std::string> portable_link(const Bundling& b, const std::vector<std::string>& argv) {
    const Workspace& w = b.r.workspace;
    std::vector<std::string> out = {kTargetCompiler};
    for (std::size_t i = 1; i < argv.size(); ++i) {
        const std::string& a = argv[i];
        std::error_code ec;
        if (a.starts_with("-Wl,-rpath")) continue;
        if (a.starts_with("/") && !is_under(a, w.cache) && fs::is_regular_file(a, ec) &&
            (a.ends_with(".a") || a.find(".so") != std::string::npos)) {
            out.push_back(ship_link_library(b, a));
            continue;
        }
        if (is_under(a, w.build) && fs::is_regular_file(a, ec))
            copy_file_into(a, b.build / fs::path(a).lexically_relative(w.build));
        else if (!a.starts_with("-") && !a.starts_with("@") && fs::is_regular_file(w.build / a, ec))
            copy_file_into(w.build / a, b.build / a);
        out.push_back(placeheld(a, w.cache));
    }
    return out;
}

// A compile command made portable: the target's compiler, the shipped headers searched before
// the system's, the system's third-party include folders read from the bundle.
std::vector<std::string> portable_compile(const Bundling& b, const std::vector<std::string>& argv) {
    const std::string shipped = std::string(kCachePlaceholder) + "/runtime/include";
    std::vector<std::string> out = {kTargetCompiler, "-isystem", shipped};
    for (std::size_t i = 1; i < argv.size(); ++i) {
        std::string a = argv[i];
        const std::string system = "/usr/include";
        for (const std::string flag : {"-isystem", "-I"}) {
            if (a.starts_with(flag + system + "/"))  // -I/usr/include/X
                a = flag + shipped + a.substr(flag.size() + system.size());
            else if (a.starts_with(system + "/") && argv[i - 1] == flag)  // -isystem /usr/include/X
                a = shipped + a.substr(system.size());
        }
        out.push_back(placeheld(a, b.r.workspace.cache));
    }
    return out;
}

// The files a compile reads, from the compiler's own dependency list (-M).
std::vector<std::string> included_files(const std::vector<std::string>& compile,
                                        const fs::path& file, const std::string& text,
                                        const fs::path& scratch) {
    const fs::path copy = scratch / file.filename();
    write_text(copy, text);
    std::vector<std::string> argv;
    for (std::size_t i = 0; i < compile.size(); ++i) {
        const std::string& a = compile[i];
        if (a == "-o" || a == "-MT" || a == "-MF") {
            ++i;
            continue;
        }
        if (a == "-c" || a == "-MD") continue;
        argv.push_back(a == file.string() ? copy.string() : a);
    }
    argv.insert(argv.begin() + 1, {"-iquote", file.parent_path().string(), "-M"});
    std::string deps;
    if (run_argv(argv, scratch, deps) != 0)
        throw std::runtime_error("listing the headers of " + file.string() + " failed:\n" + deps);
    std::vector<std::string> files;
    std::istringstream words(deps);
    for (std::string w; words >> w;)
        if (w != "\\" && !w.ends_with(":")) files.push_back(w);
    return files;
}

// The Debian package that owns each file (dpkg -S), for files under /usr/include.
std::map<std::string, std::string> owners(const std::set<std::string>& files) {
    std::map<std::string, std::string> owner;
    if (files.empty()) return owner;
    std::string command = "dpkg -S";
    for (const auto& f : files) command += " " + shell_quote(f);
    const auto out = command_output(command + " 2>/dev/null");
    std::istringstream lines(out.value_or(""));
    for (std::string line; std::getline(lines, line);) {
        const auto colon = line.find(": ");
        if (colon == std::string::npos) continue;
        std::string package = line.substr(0, colon);
        package = package.substr(0, package.find(':'));  // libfoo-dev:amd64
        owner[line.substr(colon + 2)] = package;
    }
    return owner;
}

// Every header of each third-party package a student file reaches (the whole package, so an
// honest student may include any of its headers, as on the instructor's machine).
void ship_headers(const Bundling& b) {
    const Workspace& w = b.r.workspace;
    const json plan = json::parse(read_text(w.priv / "plan.json"));
    const fs::path scratch = b.cache / "header-scan";
    fs::create_directories(scratch);
    std::set<std::string> system_headers;
    for (const auto& [key, argv] : plan.at("compile").items()) {
        for (const std::string kind : {".stub", ".solution"}) {
            const fs::path text = w.priv / "pristine" / (key + kind);
            std::error_code ec;
            if (!fs::is_regular_file(text, ec)) continue;
            for (const auto& f : included_files(argv.get<std::vector<std::string>>(), w.src / key,
                                                read_text(text), scratch))
                if (f.starts_with("/usr/include/")) system_headers.insert(f);
        }
    }
    fs::remove_all(scratch);
    std::set<std::string> packages;
    for (const auto& [file, package] : owners(system_headers))
        if (!kCompilerHeaderPackages.count(package)) packages.insert(package);
    for (const auto& package : packages) {
        const auto list = command_output("dpkg -L " + shell_quote(package));
        std::istringstream lines(list.value_or(""));
        int count = 0;
        for (std::string f; std::getline(lines, f);) {
            std::error_code ec;
            if (!f.starts_with("/usr/include/") || !fs::is_regular_file(f, ec)) continue;
            copy_file_into(f, b.include / f.substr(13));
            ++count;
        }
        b.log << "package: headers of " << package << " (" << count << " files)\n";
    }
}

// plan.json with portable commands (the instructor's own plan is left as it was).
void write_portable_plan(const Bundling& b) {
    json plan = json::parse(read_text(b.r.workspace.priv / "plan.json"));
    for (auto& [key, argv] : plan.at("compile").items())
        argv = portable_compile(b, argv.get<std::vector<std::string>>());
    for (auto& [target, argv] : plan.at("link").items())
        argv = portable_link(b, argv.get<std::vector<std::string>>());
    write_text(b.cache / "private" / "plan.json", plan.dump(1));
}

// The libraries `elf` needs, by soname, with where the loader finds them here (ldd).
std::map<std::string, std::string> needed_libraries(const fs::path& elf) {
    std::map<std::string, std::string> found;
    const auto out = command_output("ldd " + shell_quote(elf.string()) + " 2>/dev/null");
    std::istringstream lines(out.value_or(""));
    for (std::string line; std::getline(lines, line);) {
        std::istringstream words(line);
        std::string name, arrow, path;
        if (!(words >> name >> arrow >> path) || arrow != "=>") continue;
        found[name] = path;
    }
    return found;
}

bool is_elf(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    char magic[4] = {};
    in.read(magic, 4);
    return in.gcount() == 4 && std::string(magic, 4) ==
                                   "\x7f"
                                   "ELF";
}

// Every library a shipped program or library needs that the target does not provide, copied
// into runtime/lib (repeated until nothing new is needed), each finding its neighbours there.
void ship_libraries(const Bundling& b, const std::vector<fs::path>& programs) {
    std::vector<fs::path> todo = programs;
    for (const auto& e : fs::directory_iterator(b.lib))
        if (is_elf(e.path())) todo.push_back(e.path());
    std::set<std::string> shipped;
    while (!todo.empty()) {
        const fs::path elf = todo.back();
        todo.pop_back();
        for (const auto& [name, path] : needed_libraries(elf)) {
            if (b.target_sonames.count(name) || shipped.count(name)) continue;
            if (path == "not")
                throw std::runtime_error(elf.string() + " needs " + name +
                                         ", which this machine does not have (ldd)");
            shipped.insert(name);
            if (!fs::exists(b.lib / name)) copy_file_into(fs::canonical(path), b.lib / name);
            todo.push_back(b.lib / name);
        }
    }
    for (const auto& e : fs::directory_iterator(b.lib))
        if (is_elf(e.path()) && e.path().filename().string().find(".so") != std::string::npos &&
            run_trusted("patchelf --set-rpath '$ORIGIN' " + shell_quote(e.path().string())) != 0)
            throw std::runtime_error("patchelf failed on " + e.path().string());
}

// Where rt-grade goes, finding the bundled libraries from its own folder.
void ship_rt_grade(const Bundling& b, const fs::path& bundle) {
    copy_file_into(b.r.rt_grade, bundle / "bin" / "rt-grade");
    fs::permissions(bundle / "bin" / "rt-grade",
                    fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                        fs::perms::others_read | fs::perms::others_exec);
    const std::string set = "patchelf --set-rpath '$ORIGIN/../cache/runtime/lib' " +
                            shell_quote((bundle / "bin" / "rt-grade").string());
    if (run_trusted(set) != 0) throw std::runtime_error("patchelf failed on rt-grade");
}

// The programs that run from the bundle as they are: rt-grade, the judges, the reference
// renderer. Their build-tree run paths are dropped (they named the instructor's folders).
std::vector<fs::path> prebuilt_programs(const Bundling& b, const fs::path& bundle) {
    std::vector<fs::path> programs = {bundle / "bin" / "rt-grade"};
    for (const auto& dir : {b.cache / "private" / "judges", b.cache / "private" / "bin"}) {
        std::error_code ec;
        for (const auto& e : fs::directory_iterator(dir, ec)) {
            if (!is_elf(e.path())) continue;
            run_trusted("patchelf --remove-rpath " + shell_quote(e.path().string()));
            programs.push_back(e.path());
        }
    }
    return programs;
}

void write_package_json(const Bundling& b) {
    const json info = {
        {"made_by", "rt-grade package"},
        {"built_on",
         trim(command_output(". /etc/os-release && echo \"$PRETTY_NAME\"").value_or("unknown"))},
        {"compiler", kTargetCompiler},
        {"workspace_key", read_text(b.r.workspace.priv / "key")},
    };
    write_text(b.cache / "package.json", info.dump(1) + "\n");
}

}  // namespace

std::vector<TargetPackage> read_target_packages(const fs::path& source) {
    const fs::path file = source / "grader" / "package" / "target_packages.txt";
    std::istringstream lines(read_text(file));
    std::vector<TargetPackage> packages;
    int number = 0;
    for (std::string line; std::getline(lines, line);) {
        ++number;
        if (trim(line).empty() || line.starts_with("#")) continue;
        std::vector<std::string> cells;
        std::istringstream row(line);
        for (std::string cell; std::getline(row, cell, '|');) cells.emplace_back(trim(cell));
        if (cells.size() != 4 || (cells[1] != "always" && cells[1] != "gpu") || cells[3].empty())
            throw std::runtime_error(file.string() + ":" + std::to_string(number) +
                                     ": expected 'package | always or gpu | sonames or - | why'");
        TargetPackage p{cells[0], cells[1] == "gpu", {}};
        std::istringstream names(cells[2]);
        for (std::string n; names >> n;)
            if (n != "-") p.sonames.push_back(n);
        packages.push_back(std::move(p));
    }
    return packages;
}

void require_packaging_tools() {
    // Each program with the Debian package that installs it (scripts/install-deps.sh lists all).
    const std::vector<std::pair<std::string, std::string>> tools = {
        {"patchelf", "patchelf"}, {"readelf", "binutils"}, {"nm", "binutils"}, {"ldd", "libc-bin"},
        {"dpkg", "dpkg"},         {"zip", "zip"},          {"tar", "tar"}};
    for (const auto& [program, package] : tools) {
        if (run_trusted("command -v " + program + " > /dev/null") == 0) continue;
        throw std::runtime_error(program + " is not installed (Debian package " + package +
                                 "): run scripts/install-deps.sh, or apt-get install " + package);
    }
}

bool write_bundle(const BundleRequest& r, std::ostream& log, std::ostream& err) {
    const fs::path cache = r.out / "cache";
    Bundling b{r,
               cache,
               cache / "workspace" / "src",
               cache / "workspace" / "src" / "build",
               cache / "runtime" / "lib",
               cache / "runtime" / "include",
               {},
               log};
    for (const auto& p : r.packages) b.target_sonames.insert(p.sonames.begin(), p.sonames.end());
    try {
        fs::create_directories(b.lib);
        fs::create_directories(b.include);
        copy_public_tree(b);
        copy_private(b);
        write_portable_plan(b);
        ship_headers(b);
        ship_rt_grade(b, r.out);
        ship_libraries(b, prebuilt_programs(b, r.out));
        write_package_json(b);
    } catch (const std::exception& e) {
        err << "rt-grade: error: the grading bundle: " << e.what() << "\n";
        return false;
    }
    return true;
}

bool audit_bundle(const fs::path& source, const fs::path& bundle, std::ostream& log) {
    std::string out;
    const int code = run_trusted(
        "bash " + shell_quote((source / "grader" / "package" / "audit_bundle.sh").string()) + " " +
            shell_quote(bundle.string()) + " " +
            shell_quote((source / "grader" / "package" / "target_packages.txt").string()),
        &out);
    log << out;
    return code == 0;
}

}  // namespace rt::grader
