#pragma once
/// \file
/// \brief The browser viewer of an arm problem (issue 17): the same page as a rigid robot's
/// (viewer_html.h, viewer/viewer.html), with one drawn body per link with collision geometry.
/// Written by `adsd plan ARM.cfg --html` and `adsd view ARM.cfg`.

#include <string>

#include <ompl/geometric/PathGeometric.h>

#include "adsd/planner/arm_planning_problem.h"
#include "viewer_page.h"

namespace adsd::app {

/// \brief Writes the viewer page of the arm problem \p problem to \p file.
///
/// With a \p path, the states shown are those at which `adsd plan` measures the path's clearance
/// (armClearanceSamples(), then the space's validity-checking resolution as measurePath() does),
/// so the page's minimum is the printed one; without one (null), the start and the goal. At each
/// state: every link's world pose from adsd::planner::forwardKinematics, the problem's checker's
/// clearance, and the closest points of the pair that realizes it, link against obstacle or link
/// against link (the checked pairs: ArmScene::selfPairs), from adsd::distance. The page draws
/// each link's collision mesh (ArmValidityCheckerBase::bodyMesh) once and moves it by these
/// poses; "up" on the page is the axis of the movable joint that carries all others (an arm's base
/// joint turns about the vertical), pointing from the base towards the arm at the start, or +z for
/// a robot without one (a humanoid, REP 103). The problem's space must be set
/// up (SimpleSetup::setup), as it is before solving. Written as writeViewerPage() writes; throws
/// adsd::InputError naming \p file when it cannot be written.
ViewerSummary writeArmViewerHtml(const std::string& file, const planner::ArmPlanningProblem& problem,
                                 const ompl::geometric::PathGeometric* path, const std::string& source);

/// \brief Throws adsd::InputError, naming \p where (the problem file), when \p problem has nothing
/// the page could show: no link with collision geometry (nothing to draw), or no obstacle and no
/// enabled link pair (no clearance). writeArmViewerHtml checks it too (naming the problem);
/// `adsd view` and `adsd plan --html` ask first, `adsd plan` before planning, so that it fails with
/// nothing written (it wrote the path file first, an outside review).
void requireArmViewable(const planner::ArmPlanningProblem& problem, const std::string& where);

}  // namespace adsd::app
