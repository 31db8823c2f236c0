// The build phase of a grading: each submitted file compiled alone in the jail, its object
// checked and all but the stage's API localized, then linked per graded stage as if that stage
// were graded alone (solutions of earlier stages before it, stubs of later ones after it).
#include <algorithm>
#include <set>

#include "grading/grading.h"
#include "grading/stage_specs.h"
#include "grading/test_output.h"
#include "util.h"
#include "workspace/object_check.h"
#include "workspace/workspace_build.h"

namespace fs = std::filesystem;

namespace rt::grader {
namespace {

// "stages/NN/file.cpp" -> "stages_NN_file.cpp": one flat name per file for objects and logs.
std::string flat_name(const std::string& key) {
    std::string name = key;
    std::replace(name.begin(), name.end(), '/', '_');
    return name;
}

std::set<std::string> api_of(const BuildPlan& plan, const std::string& key) {
    return plan.api.count(key) ? plan.api.at(key) : std::set<std::string>{};
}

// Each submitted file of a graded stage: compiled in the jail, checked, localized.
// Returns key -> object; what went wrong goes to `build_errors` (stage -> what the student sees).
std::map<std::string, fs::path> compile_submission(Grading& g,
                                                   std::map<int, std::string>& build_errors) {
    std::map<std::string, fs::path> objects;
    for (const auto& s : g.graded)
        for (const auto& f : s.student_files) {
            const std::string key = s.folder + "/" + f;
            if (!is_compiled_student_file(key) || !g.in.files.count(key) || g_interrupted) continue;
            const std::string name = flat_name(key);
            const fs::path raw = trusted_dir(g.scratch / "objects" / name) / (name + ".o");
            std::string compile_log;
            if (!compile_in_jail(g.w, g.plan, key, g.in.files[key], g.scratch / "compile" / name,
                                 raw, compile_log)) {
                build_errors[s.number] += key +
                                          " does not compile. The compiler's first errors:\n\n" +
                                          first_errors(compile_log);
                continue;
            }
            const fs::path local = raw.parent_path() / (name + ".local.o");
            const std::string problems =
                check_and_localize(raw, api_of(g.plan, key), g.plan, local);
            if (!problems.empty()) {
                build_errors[s.number] +=
                    key +
                    " defines symbols or sections the grader does not allow (main, test "
                    "code, framework functions, code that runs before main). Remove them:\n" +
                    problems;
                continue;
            }
            objects[key] = local;
        }
    return objects;
}

// A starter tree has no solutions: the stages before a graded one use the tree's own files
// (compiled here like any student file; the stub when they do not compile). Only the stages
// before the last graded one are linked so (link_stages): grading stage 01 compiles none.
std::map<std::string, fs::path> compile_own_solutions(
    Grading& g, const std::map<std::string, fs::path>& student_objects) {
    int last_graded = 0;
    for (const auto& s : g.graded) last_graded = std::max(last_graded, s.number);
    std::set<std::string> needed;
    for (const auto& t : g.all_specs)
        if (t.number < last_graded)
            for (const auto& f : t.student_files) needed.insert(t.folder + "/" + f);
    std::map<std::string, fs::path> own;
    for (const auto& key : g.plan.solution_from_source) {
        if (!needed.count(key)) continue;
        if (const auto it = student_objects.find(key); it != student_objects.end()) {
            own[key] = it->second;
            continue;
        }
        std::error_code ec;
        if (!fs::is_regular_file(g.o.source / key, ec)) continue;
        const std::string text = read_text(g.o.source / key);
        const std::string name = flat_name(key);
        const fs::path raw = trusted_dir(g.scratch / "objects" / (name + "-own")) / (name + ".o");
        std::string compile_log;
        if (compile_in_jail(g.w, g.plan, key, text, g.scratch / "compile" / (name + "-own"), raw,
                            compile_log) &&
            check_and_localize(raw, api_of(g.plan, key), g.plan,
                               raw.parent_path() / (name + ".local.o"))
                .empty())
            own[key] = raw.parent_path() / (name + ".local.o");
    }
    return own;
}

// Links the binaries of every graded stage whose files compiled.
void link_stages(Grading& g, std::map<std::string, fs::path>& student_objects,
                 const std::map<std::string, fs::path>& own_solutions,
                 std::map<int, std::string>& build_errors) {
    const auto earlier_stage_object = [&](const std::string& key) -> fs::path {
        if (!g.plan.solution_from_source.count(key)) return solution_object(g.w, key);
        const auto it = own_solutions.find(key);
        return it != own_solutions.end() ? it->second : stub_object(g.w, key);
    };
    for (const auto& s : g.graded) {
        if (build_errors.count(s.number) || g_interrupted) continue;
        std::vector<fs::path> objects;
        for (const auto& t : g.all_specs)
            for (const auto& f : t.student_files) {
                const std::string key = t.folder + "/" + f;
                if (!is_compiled_student_file(key)) continue;
                if (t.number < s.number)
                    objects.push_back(earlier_stage_object(key));
                else if (t.number == s.number && student_objects.count(key))
                    objects.push_back(student_objects[key]);
                else
                    objects.push_back(stub_object(g.w, key));
            }
        std::vector<std::string> targets{"rt", kWorker};
        const fs::path bin = g.scratch / ("stage-" + two_digits(s.number)) / "bin";
        std::string link_log;
        if (!link_stage(g.w, g.plan, objects, targets, bin, link_log)) {
            strip_workspace_roots(g.w, g.scratch, g.glsl_dirs, g.graded, link_log);
            build_errors[s.number] +=
                "Linking your files failed (a function of the stage's API "
                "missing or defined twice?):\n\n" +
                link_log.substr(0, 4000);
            continue;
        }
        // Executable by a sandbox uid, readable by none (they hold earlier stages' solutions).
        const auto exec_only =
            fs::perms::owner_all | fs::perms::group_exec | fs::perms::others_exec;
        fs::permissions(bin.parent_path(), exec_only);
        fs::permissions(bin, exec_only);
        // The judges: the workspace's, built once (they hold no student code).
        for (const auto& group : s.groups) {
            if (!fs::exists(g.w.priv / "judges" / judge_target(group.binary))) continue;
            fs::copy_file(g.w.priv / "judges" / judge_target(group.binary), bin / group.binary,
                          fs::copy_options::overwrite_existing);
            targets.push_back(group.binary);
        }
        for (const auto& t : targets) fs::permissions(bin / t, exec_only);
        fs::remove(bin / "librt_stages.a");
        g.stage_bins[s.number] = bin;
    }
}

// A GPU stage's GLSL as graded: each submitted file, the released stub for each one missing,
// in a folder of its own that the children read (it holds nothing but the student's own text
// and public stubs) and the shader assembler loads at run time. The text is never compiled
// here: the driver compiles it inside the sandboxed test or render.
void stage_glsl(Grading& g) {
    for (const auto& s : g.graded) {
        if (!s.gpu) continue;
        const fs::path dir = g.scratch / ("glsl-" + two_digits(s.number));
        fs::create_directories(dir);
        for (const auto& f : s.student_files) {
            const std::string key = s.folder + "/" + f;
            if (is_compiled_student_file(key)) continue;
            const auto it = g.in.files.find(key);
            write_text(dir / f, it != g.in.files.end() ? it->second : read_text(g.w.src / key));
            fs::permissions(dir / f, fs::perms::owner_read | fs::perms::owner_write |
                                         fs::perms::group_read | fs::perms::others_read);
        }
        fs::permissions(dir, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                                 fs::perms::others_read | fs::perms::others_exec);
        g.glsl_dirs[s.number] = dir;
    }
}

}  // namespace

void build_stages(Grading& g) {
    std::map<int, std::string> build_errors;  // stage -> what the student sees
    stage_glsl(g);
    auto student_objects = compile_submission(g, build_errors);
    const auto own_solutions = compile_own_solutions(g, student_objects);
    link_stages(g, student_objects, own_solutions, build_errors);
    for (const auto& [stage, errors] : build_errors) {
        g.summary.build_failed = true;
        TestOutcome note;
        note.stage = stage;
        note.name = "Build (compiling your files): stage " + two_digits(stage);
        note.number = std::to_string(stage) + ".0";
        note.tags = {"build", "stage" + two_digits(stage)};
        note.output =
            "The build failed, so no test of this stage could run.\n" +
            (g_interrupted ? std::string("(grading was interrupted during the build)\n") : errors);
        g.notes.insert(g.notes.begin(), note);
        for (auto& t : g.outcomes)
            if (t.stage == stage) t.output = "not run: the build failed (see the Build test)\n";
    }
}

}  // namespace rt::grader
