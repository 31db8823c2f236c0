// `rt-grade batch DIR --out OUT --slurm`: a class graded on a Slurm cluster, as a job array
// whose task N grades line N of a manifest, and a collector job that writes what a local batch
// writes (docs/grading.md, "A class on a Slurm cluster"). OUT must be on storage every node
// sees, and so must the source tree and the grading workspace (--cache):
//
//   OUT/.slurm/manifest.json   the options and every submission, in the batch's order
//   OUT/.slurm/grade.sbatch    the array: task N runs `rt-grade slurm-task OUT N`
//   OUT/.slurm/collect.sbatch  runs `rt-grade slurm-collect OUT` after every task has ended
//   OUT/.slurm/input/          a zipped export, unpacked once here
//   OUT/.slurm/rows/N.json     what task N graded (its row of scores.csv)
//   OUT/.slurm/logs/           each task's output
//
// Task ids name manifest lines, never folder order, so rerunning a failed task N grades the
// same submission again and replaces only its row.
#pragma once

#include <filesystem>
#include <ostream>

#include "grading/grade.h"

namespace rt::grader {

struct SlurmRequest {
    std::filesystem::path input;  // a folder of submissions or an export (folder or .zip)
    std::filesystem::path out;    // OUT, on shared storage
    bool latest_only = false;     // of an export, each student's newest submission
    bool submit = true;           // run sbatch; false: write the scripts and say how to submit
};

// Prepares the workspace, writes the manifest and both scripts and (with `submit`) submits them.
int run_slurm_batch(const GradeOptions& base, const SlurmRequest& request, std::ostream& log);

// One array task: grades the manifest's submission `index` into OUT/NAME/ and OUT/.slurm/rows/.
int run_slurm_task(const std::filesystem::path& out, long index, std::ostream& log);

// The collector: OUT/scores.csv, changes.csv and index.html from every task's row; a task that
// left no row is a grader error in its row, named with the command that reruns it (exit 1).
int run_slurm_collect(const std::filesystem::path& out, std::ostream& log);

}  // namespace rt::grader
