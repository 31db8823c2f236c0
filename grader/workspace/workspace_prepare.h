// Preparing the grading workspace (workspace.h): the instructor's tree copied, built and its
// build plan saved, once per change of the tree (workspace_prepare.cpp).
#pragma once

#include <ostream>

#include "grading/grade.h"

namespace rt::grader {

// Builds (or reuses) the grading workspace (workspace.h); prints progress to log. Returns false
// on failure.
bool prepare_workspace(const GradeOptions& options, std::ostream& log);

}  // namespace rt::grader
