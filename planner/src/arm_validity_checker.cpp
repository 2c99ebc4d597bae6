#include "adsd/planner/arm_validity_checker.h"

#include <cmath>

#include "adsd/error.h"
#include "clearance_queries.h"

namespace adsd::planner {

using detail::requireClearanceOptions;
using detail::threadScratch;

namespace {

/// The links and obstacles are rigid: every mesh keeps a tree, built once on a copy of the scene
/// (so the caller's scene, which FCL's checker may share, is left as it was).
std::shared_ptr<const ArmScene> withHierarchies(const ArmScene& scene) {
  auto model = std::make_shared<ArmModel>(*scene.model);
  model->buildHierarchies();
  auto prepared = std::make_shared<ArmScene>(scene);
  prepared->model = model;
  for (Mesh& part : prepared->environment) part.buildHierarchy();
  return prepared;
}

}  // namespace

ArmValidityChecker::ArmValidityChecker(const ompl::base::SpaceInformationPtr& si, const ArmScene& scene,
                                       double safetyMargin, const DistanceOptions& clearanceOptions)
    : ArmValidityCheckerBase(si, withHierarchies(scene), safetyMargin), clearanceOptions_(clearanceOptions) {
  requireClearanceOptions(clearanceOptions_);
  specs_.clearanceComputationType = clearanceOptions_.mode == QueryMode::exact
                                        ? ompl::base::StateValidityCheckerSpecs::EXACT
                                        : ompl::base::StateValidityCheckerSpecs::BOUNDED_APPROXIMATE;
}

bool ArmValidityChecker::pairSeparatedAbove(std::size_t a, const Pose& poseA, std::size_t b, const Pose& poseB,
                                            double margin) const {
  const DistanceResult r =
      distance(bodyMesh(a), poseA, bodyMesh(b), poseB, DistanceOptions::aboveThreshold(margin), threadScratch());
  return r.status == DistanceStatus::aboveThreshold;
}

ArmValidityCheckerBase::PairDistance ArmValidityChecker::pairDistance(std::size_t a, const Pose& poseA, std::size_t b,
                                                                      const Pose& poseB, double cap) const {
  DistanceOptions options = clearanceOptions_;
  if (options.mode == QueryMode::exact || options.mode == QueryMode::cap) {
    // Exact below the smaller cap: the caller needs nothing above `cap`, the settings nothing above theirs.
    const double needed = std::min(cap, options.cap);
    if (std::isfinite(needed)) options = DistanceOptions::cappedAt(needed);
  }
  const DistanceResult r = distance(bodyMesh(a), poseA, bodyMesh(b), poseB, options, threadScratch());
  PairDistance d;
  switch (r.status) {
    case DistanceStatus::beyondCap:
      d.lower = r.lower;
      d.reachedCap = r.lower >= cap;
      break;
    case DistanceStatus::withinTolerance:
      d.lower = r.lower;
      break;
    default:
      d.lower = r.distance;
      break;
  }
  return d;
}

}  // namespace adsd::planner
