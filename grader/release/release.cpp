// `rt-grade release`: writes a starter tree from the course tree (docs/release.md). The
// marker logic it applies to each student file is in markers.cpp.
#include "release/release.h"

#include "course/manifest.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <set>
#include <system_error>

#include "util.h"

namespace fs = std::filesystem;

namespace rt::grader {

namespace {

// Re-releasing with --force leaves identical files untouched, so their timestamps stay and an
// existing build of the starter tree rebuilds only what changed.
bool same_content(const fs::path& a, const fs::path& b) {
    std::error_code ec;
    if (!fs::is_regular_file(b, ec) || fs::file_size(a, ec) != fs::file_size(b, ec) || ec)
        return false;
    std::string content_a, content_b;
    return read_text_if(a, content_a) && read_text_if(b, content_b) && content_a == content_b;
}

// True if `inner` is `outer` or lies below it (both canonical).
bool is_within(const fs::path& inner, const fs::path& outer) {
    const fs::path relative = inner.lexically_relative(outer);
    if (relative.empty()) return false;
    const auto first = *relative.begin();
    return first != ".." && relative.is_relative();
}

struct FileList {
    std::vector<std::string> files;  // relative, '/'-separated, sorted
    std::string how;                 // for the log
};

// The files to release: git's view when the source is a checkout (so build products, editor
// files and anything ignored never ship), otherwise a directory walk.
std::optional<FileList> list_source_files(const ReleaseOptions& options, std::ostream& errors) {
    const std::string src = shell_quote(options.source.string());
    const auto inside =
        command_output("git -C " + src + " rev-parse --is-inside-work-tree 2>/dev/null");
    FileList list;
    if (inside && trim(*inside) == "true") {
        std::string command = "git -C " + src + " ls-files -z --cached";
        if (options.include_untracked) command += " --others --exclude-standard";
        const auto output = command_output(command);
        if (!output) {
            errors << "rt-grade release: error: 'git ls-files' failed in "
                   << options.source.string() << "; check that git works there\n";
            return std::nullopt;
        }
        std::set<std::string> unique;  // --cached and --others never overlap, but be safe
        std::size_t start = 0;
        while (start < output->size()) {
            std::size_t end = output->find('\0', start);
            if (end == std::string::npos) end = output->size();
            if (end > start) unique.insert(output->substr(start, end - start));
            start = end + 1;
        }
        list.files.assign(unique.begin(), unique.end());
        list.how = options.include_untracked ? "git: tracked and untracked, non-ignored files"
                                             : "git: tracked files";
        if (list.files.empty()) {
            errors << "rt-grade release: error: git tracks no files in " << options.source.string()
                   << "; commit (or 'git add') the tree, or pass --include-untracked\n";
            return std::nullopt;
        }
        return list;
    }
    if (fs::exists(options.source / ".git")) {
        errors << "rt-grade release: error: " << options.source.string()
               << " has a .git but git cannot read it; install git or fix the checkout\n";
        return std::nullopt;
    }
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(options.source, ec);
         !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        const fs::path relative = it->path().lexically_relative(options.source);
        const std::string name = it->path().filename().string();
        if (it->is_directory() && !it->is_symlink()) {
            // Build trees live in build*/ at the top (see .gitignore); .git is never copied.
            if (name == ".git" || (it.depth() == 0 && name.starts_with("build")))
                it.disable_recursion_pending();
            continue;
        }
        if (it->is_regular_file() || it->is_symlink())
            list.files.push_back(relative.generic_string());
    }
    if (ec) {
        errors << "rt-grade release: error: cannot walk " << options.source.string() << ": "
               << ec.message() << "; check the --source directory\n";
        return std::nullopt;
    }
    std::sort(list.files.begin(), list.files.end());
    list.how = "directory walk (not a git checkout; build*/ and .git/ skipped)";
    return list;
}

// A stage file whose regions were rewritten, held until every file has been validated.
struct Rewritten {
    std::string relative;
    std::string text;
};

// What pass 1 decides: files copied as they are, files rewritten, and every problem found.
struct ReleasePlan {
    std::vector<std::string> problems;
    std::vector<Rewritten> rewritten;
    std::set<std::string> copied;
    std::map<std::string, StageInfo> stages;  // every stage folder, for RELEASE.txt
    int stripped = 0, kept = 0;               // solution regions

    const StageInfo& stage_info(const fs::path& source, const std::string& folder) {
        auto it = stages.find(folder);
        if (it == stages.end())
            it = stages.emplace(folder, read_stage_info(source / folder / "stage.json")).first;
        return it->second;
    }
};

// --source and --out resolved, or the one-line error that stops the release.
std::string resolve_paths(ReleaseOptions& options, const ReleaseOptions& given) {
    std::error_code ec;
    options.source = fs::weakly_canonical(fs::absolute(options.source), ec);
    if (ec || !fs::is_directory(options.source))
        return "source " + given.source.string() +
               " is not a directory; pass --source with the course tree";
    options.out = fs::weakly_canonical(fs::absolute(options.out), ec);
    if (ec) return "cannot resolve --out " + given.out.string() + ": " + ec.message();
    const std::string out = "--out " + options.out.string();
    if (options.out == options.source || is_within(options.out, options.source))
        return out + " is inside the source tree " + options.source.string() +
               "; choose a directory outside it (it would be copied into itself)";
    if (is_within(options.source, options.out))
        return out + " contains the source tree; choose a directory outside it";
    if (fs::exists(options.out) && !fs::is_directory(options.out))
        return out + " exists and is not a directory; choose another path";
    if (fs::exists(options.out) && !fs::is_empty(options.out) && !options.force)
        return out + " is not empty; pass --force to write over it, or choose an empty directory";
    return "";
}

// Why a file with solution markers may not hold them ("" when it may): it must be a student
// file its stage's stage.json lists.
std::string markers_problem(ReleasePlan& plan, const fs::path& source,
                            const std::optional<StageRef>& stage) {
    if (!stage)
        return "error: solution markers outside a stage folder (only stages/NN-name/ student "
               "files may hold solutions); move the solution into a stage's student file or "
               "remove the markers";
    const StageInfo& info = plan.stage_info(source, stage->folder);
    if (!info.problem.empty())
        return "error: " + stage->folder + "/stage.json " + info.problem +
               "; give the stage a stage.json listing its \"student_files\"";
    if (std::find(info.student_files.begin(), info.student_files.end(), stage->relative) ==
        info.student_files.end())
        return "error: file has solution markers but is not listed in " + stage->folder +
               "/stage.json \"student_files\"; add \"" + stage->relative +
               "\" there or remove the markers";
    return "";
}

// Folders that quote the reference solutions outside their markers stay with the instructor: the
// benchmarks' back-ends (tools/bench: the tuned BVH that stage 06's reference once was, the
// stage 11 path tracer's strategies) and the mutation corpus (grader/tests/mutations: each
// mutation quotes the reference lines it changes).
bool instructor_only(const std::string& relative) {
    for (const char* folder : {"tools/bench/", "grader/tests/mutations/"})
        if (relative.starts_with(folder)) return true;
    return false;
}

// Pass 1 for one file of the tree: copied, rewritten (its regions stripped or kept, and its stub
// kept for `rt-grade .`), skipped, or a problem.
void plan_file(ReleasePlan& plan, const ReleaseOptions& options, const std::string& relative) {
    std::error_code ec;
    const fs::path path = options.source / relative;
    const auto status = fs::symlink_status(path, ec);
    if (ec || !fs::exists(status)) return;  // tracked but deleted in the working tree
    const auto stage = stage_of(relative);
    if (stage) plan.stage_info(options.source, stage->folder);  // every stage is in RELEASE.txt
    // Hidden tests (stages/NN-name/hidden/, named in grading.json) stay with the grader.
    if (stage && stage->relative.starts_with("hidden/")) return;
    if (instructor_only(relative)) return;
    if (fs::is_symlink(status) || !fs::is_regular_file(status)) {
        if (fs::is_symlink(status)) plan.copied.insert(relative);
        return;  // directories here are git submodules: not part of a starter tree
    }
    std::string content;
    if (!read_text_if(path, content)) {
        plan.problems.push_back(relative +
                                ":1: error: cannot read the file; check its permissions");
        return;
    }
    const bool solved = stage && stage->number <= options.solved_through;
    MarkerResult result = process_markers(content, solved ? RegionMode::Keep : RegionMode::Strip);
    if (!result.has_markers) {
        plan.copied.insert(relative);
        return;
    }
    for (const MarkerError& error : result.errors)
        plan.problems.push_back(format_error(relative, error));
    const std::string problem = markers_problem(plan, options.source, stage);
    if (!problem.empty())
        plan.problems.push_back(format_error(relative, {result.first_marker_line, problem}));
    if (!result.errors.empty() || !problem.empty()) return;
    (solved ? plan.kept : plan.stripped) += result.regions;
    plan.rewritten.push_back({relative, std::move(result.text)});
    // The stub as released, whatever --solved-through says: `rt-grade .` in the starter tree
    // builds its grading copy from it and tells started stages from untouched ones.
    plan.rewritten.push_back({std::string(kStarterStubs) + "/" + relative,
                              process_markers(content, RegionMode::Strip).text});
}

// The students' README replaces the instructor's (no instructor commands in a starter tree), and
// every stage.json ships (they describe the stages to students and tools).
void plan_readme_and_stages(ReleasePlan& plan, const fs::path& source) {
    std::string readme;
    if (read_text_if(source / "grader/templates/starter_README.md", readme)) {
        plan.copied.erase("README.md");
        plan.rewritten.push_back({"README.md", readme});
    }
    for (const auto& [folder, info] : plan.stages) {
        const std::string relative = folder + "/stage.json";
        if (fs::is_regular_file(source / relative)) plan.copied.insert(relative);
    }
}

// Pass 2, the files: copies (symbolic links as links) and rewritten files, each written only when
// its content changed, so an existing build of the starter tree stays valid.
void write_files(const ReleasePlan& plan, const ReleaseOptions& options) {
    fs::create_directories(options.out);
    for (const std::string& relative : plan.copied) {
        const fs::path from = options.source / relative;
        const fs::path to = options.out / relative;
        fs::create_directories(to.parent_path());
        if (fs::is_symlink(fs::symlink_status(from))) {
            if (fs::exists(fs::symlink_status(to))) fs::remove(to);
            fs::copy_symlink(from, to);
        } else if (!same_content(from, to)) {
            fs::copy_file(from, to, fs::copy_options::overwrite_existing);
        }
    }
    for (const Rewritten& file : plan.rewritten) {
        const fs::path to = options.out / file.relative;
        fs::create_directories(to.parent_path());
        std::string existing;
        if (fs::is_regular_file(to) && read_text_if(to, existing) && existing == file.text)
            continue;
        std::ofstream out(to, std::ios::binary | std::ios::trunc);
        out << file.text;
        out.close();
        if (!out)
            throw fs::filesystem_error("cannot write", to,
                                       std::make_error_code(std::errc::io_error));
        fs::permissions(to, fs::status(options.source / file.relative).permissions());
    }
}

// Pass 2, RELEASE.txt: how the files were listed and which stages are solved.
void write_release_txt(const ReleasePlan& plan, const ReleaseOptions& options,
                       const std::string& how) {
    std::ofstream release(options.out / "RELEASE.txt", std::ios::trunc);
    release << "Starter tree written by `rt-grade release`.\n"
            // The files, not where they were: the instructor's path means nothing to a student
            // and says more about the instructor's machine than it should.
            << "Files: " << how << "\n"
            << "Solved through stage: " << options.solved_through << "\n\n"
            << "Stages:\n";
    for (const auto& [folder, info] : plan.stages) {
        const auto stage = stage_of(folder + "/");
        const bool solved = stage && stage->number <= options.solved_through;
        release << "  " << folder.substr(std::string_view("stages/").size())
                << (info.title.empty() ? "" : " (" + info.title + ")") << ": "
                << (solved ? "solved -- the solution is included"
                           : "not solved -- stubs to implement")
                << "\n";
    }
    release.close();
    if (!release)
        throw fs::filesystem_error("cannot write", options.out / "RELEASE.txt",
                                   std::make_error_code(std::errc::io_error));
}

}  // namespace

int run_release(const ReleaseOptions& options_in, std::ostream& log, std::ostream& errors) {
    ReleaseOptions options = options_in;
    if (const std::string problem = resolve_paths(options, options_in); !problem.empty()) {
        errors << "rt-grade release: error: " << problem << "\n";
        return 2;
    }
    const auto list = list_source_files(options, errors);
    if (!list) return 2;
    // Pass 1: read and check everything; nothing is written unless it all checks out.
    ReleasePlan plan;
    for (const std::string& relative : list->files) plan_file(plan, options, relative);
    plan_readme_and_stages(plan, options.source);
    if (!plan.problems.empty()) {
        for (const std::string& problem : plan.problems) errors << problem << "\n";
        errors << "rt-grade release: " << plan.problems.size() << " error(s); nothing written to "
               << options.out.string() << "\n";
        return 2;
    }
    // Pass 2: write.
    try {
        write_files(plan, options);
        write_release_txt(plan, options, list->how);
    } catch (const fs::filesystem_error& e) {
        errors << "rt-grade release: error: " << e.what() << "; the starter tree in "
               << options.out.string() << " is incomplete\n";
        return 1;
    }
    log << "rt-grade release: " << plan.copied.size() + plan.rewritten.size() << " files copied to "
        << options.out.string() << " (" << plan.rewritten.size() << " rewritten), " << plan.stripped
        << " regions stripped, " << plan.kept << " regions kept (solved through stage "
        << options.solved_through << ")\n";
    return 0;
}

}  // namespace rt::grader
