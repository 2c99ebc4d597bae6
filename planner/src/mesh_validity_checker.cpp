#include "adsd/planner/mesh_validity_checker.h"

#include <cmath>
#include <limits>

#include "adsd/error.h"
#include "clearance_queries.h"
#include "non_null.h"

namespace adsd::planner {

using detail::requireClearanceOptions;
using detail::threadScratch;

namespace {

/// Robot and environment are rigid here: every part gets its sub-mesh tree once, and every query
/// reuses it (adsd/mesh_hierarchy.h, issue 6). The meshes are copied so that the caller's scene
/// (which FCL's checker may share) is left as it was.
std::shared_ptr<const RigidBodyScene> withHierarchies(const std::shared_ptr<const RigidBodyScene>& scene) {
  auto prepared = std::make_shared<RigidBodyScene>(*scene);
  for (Mesh& part : prepared->robot) part.buildHierarchy();
  for (Mesh& part : prepared->environment) part.buildHierarchy();
  return prepared;
}

}  // namespace

MeshValidityChecker::MeshValidityChecker(const ompl::base::SpaceInformationPtr& si,
                                         std::shared_ptr<const RigidBodyScene> scene, double safetyMargin,
                                         const DistanceOptions& clearanceOptions)
    : RigidBodyValidityChecker(si, withHierarchies(detail::nonNull(std::move(scene), "validity checker: the scene")),
                               safetyMargin),
      clearanceOptions_(clearanceOptions) {
  requireClearanceOptions(clearanceOptions_);
  // Honest about what clearance() returns: exact, or a lower bound (tolerance: the interval's lower
  // end; cap: min(distance, cap)).
  specs_.clearanceComputationType = clearanceOptions_.mode == QueryMode::exact
                                        ? ompl::base::StateValidityCheckerSpecs::EXACT
                                        : ompl::base::StateValidityCheckerSpecs::BOUNDED_APPROXIMATE;
}

bool MeshValidityChecker::pairSeparatedAbove(std::size_t r, std::size_t e, const Pose& robotPose,
                                             double margin) const {
  const DistanceResult result = distance(scene_->robot[r], robotPose, scene_->environment[e], Pose::Identity(),
                                         DistanceOptions::aboveThreshold(margin), threadScratch());
  return result.status == DistanceStatus::aboveThreshold;
}

RigidBodyValidityChecker::PairDistance MeshValidityChecker::pairDistance(std::size_t r, std::size_t e,
                                                                         const Pose& robotPose, double cap) const {
  DistanceOptions options = clearanceOptions_;
  if (options.mode == QueryMode::exact || options.mode == QueryMode::cap) {
    // Exact below the smaller cap: the caller needs nothing above `cap`, the settings nothing
    // above their own.
    const double needed = std::min(cap, options.cap);
    if (std::isfinite(needed)) {
      options = DistanceOptions::cappedAt(needed);
    }
  }
  const DistanceResult result =
      distance(scene_->robot[r], robotPose, scene_->environment[e], Pose::Identity(), options, threadScratch());
  PairDistance d;
  switch (result.status) {
    case DistanceStatus::beyondCap:
      d.lower = result.lower;
      d.reachedCap = result.lower >= cap;
      break;
    case DistanceStatus::withinTolerance:
      d.lower = result.lower;
      break;
    default:
      d.lower = result.distance;
      break;
  }
  return d;
}

}  // namespace adsd::planner
