#pragma once
/// \file
/// \brief Where an arm path's clearance is measured: `adsd plan`'s summary and the arm viewer page
/// (arm_viewer_html.h) take the same states, so the page's minimum is the printed one.

#include <cmath>

#include <ompl/geometric/PathGeometric.h>

namespace adsd::app {

/// \brief Spacing of the states at which an arm path's clearance is measured: joint-space distance
/// (the sum of the joints' absolute changes, radians for turning joints), 0.01 rad, where a link
/// 1 m from its joint's axis moves at most 1 cm. Finer than the validity-checking resolution (1 %
/// of the joint space's extent, tenths of a radian).
constexpr double kArmClearanceStep = 0.01;

/// \brief A copy of \p path interpolated to states at most kArmClearanceStep apart. What
/// adsd::planner::measurePath() measures on it is then the clearance at these states (its own
/// interpolation to the validity-checking resolution adds none).
inline ompl::geometric::PathGeometric armClearanceSamples(const ompl::geometric::PathGeometric& path) {
  ompl::geometric::PathGeometric dense(path);
  dense.interpolate(static_cast<unsigned>(std::ceil(path.length() / kArmClearanceStep)) + 1);
  return dense;
}

}  // namespace adsd::app
