#pragma once
/// \file
/// \brief The browser viewer of a rigid-body problem: one self-contained HTML page showing a
/// problem, a path along it, the closest points at every state and the clearance along the way
/// (issue 18). Written by `adsd plan --html` and `adsd view`; the page is made by viewer_page.h.

#include <string>

#include <ompl/geometric/PathGeometric.h>

#include "adsd/planner/planning_problem.h"
#include "adsd/planner/problem_file.h"
#include "viewer_page.h"

namespace adsd::app {

/// \brief Writes the viewer page for \p problem to \p file.
///
/// With a \p path, the states shown are the path interpolated to the space's validity-checking
/// resolution, as adsd::planner::measurePath() samples it, so the page's clearance minimum is the
/// one `adsd plan` prints. Without one (null), the start and the goal. At each state: the
/// checker's clearance, and the witness points of the exact distance from adsd::distance over the
/// robot and environment mesh pairs (world frame). \p source says in the page where the path came
/// from. The page is written to a temporary file renamed on success, so a failure leaves nothing
/// half-written; throws adsd::InputError naming \p file when it cannot be written.
ViewerSummary writeViewerHtml(const std::string& file, const planner::ProblemFile& problemFile,
                              const planner::PlanningProblem& problem, const ompl::geometric::PathGeometric* path,
                              const std::string& source);

}  // namespace adsd::app
