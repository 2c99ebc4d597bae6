#pragma once
/// \file
/// \brief Where an arm path's clearance is measured: `adsd plan`'s summary and the arm viewer page
/// (arm_viewer_html.h) take the same states, so the page's minimum is the printed one.

#include <algorithm>
#include <cmath>

#include <ompl/geometric/PathGeometric.h>

#include "adsd/planner/path_report.h"

namespace adsd::app {

/// \brief Spacing of the states at which an arm path's clearance is measured: joint-space distance
/// (the sum of the joints' absolute changes, radians for turning joints), 0.01 rad, where a link
/// 1 m from its joint's axis moves at most 1 cm. Finer than the validity-checking resolution (1 %
/// of the joint space's extent, tenths of a radian).
constexpr double kArmClearanceStep = 0.01;

/// \brief At most this many states are measured along a path: a joint of wide limits (a turntable
/// of +-1e9 rad) can make a path millions of steps long, whose measure would outlast any time
/// limit and fill the memory with states. About a second of clearance queries on the shipped arms.
constexpr double kMaxArmClearanceStates = 20000;

/// \brief The spacing actually used along \p path: kArmClearanceStep, or wider on a path so long
/// that it would need more than kMaxArmClearanceStates states.
inline double armClearanceStep(const ompl::geometric::PathGeometric& path) {
  return std::max(kArmClearanceStep, path.length() / (kMaxArmClearanceStates - 1));
}

/// \brief A copy of \p path interpolated to states at most armClearanceStep() apart, and then at
/// most the space's validity-checking resolution apart (finer on a joint space of small ranges,
/// a gripper's) unless that would pass planner::kMaxMeasuredStates (planner::measuredStates: the
/// resolution's pass had undone this cap, 3 GB for a path file of 50 000 states).
/// adsd::planner::measurePath() measures the clearance at measuredStates() of these states, which
/// the arm viewer shows, and measureArmPathClearance() at these.
inline ompl::geometric::PathGeometric armClearanceSamples(const ompl::geometric::PathGeometric& path) {
  ompl::geometric::PathGeometric dense(path);
  dense.interpolate(static_cast<unsigned>(std::ceil(path.length() / armClearanceStep(path))) + 1);
  return planner::measuredStates(dense);
}

/// \brief The largest distance between consecutive states of \p samples.
inline double largestStep(const ompl::geometric::PathGeometric& samples) {
  double largest = 0.0;
  for (std::size_t i = 0; i + 1 < samples.getStateCount(); ++i) {
    largest = std::max(largest, samples.getSpaceInformation()->distance(samples.getState(i), samples.getState(i + 1)));
  }
  return largest;
}

}  // namespace adsd::app
