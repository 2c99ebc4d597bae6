#include "adsd/planner/fcl_arm_validity_checker.h"

#include <algorithm>
#include <limits>

#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>

#include "adsd/error.h"
#include "fcl_model.h"

namespace adsd::planner {

using detail::FclModel;
using detail::buildFclModel;

struct FclArmValidityChecker::Models {
  std::vector<std::shared_ptr<FclModel>> bodies;  ///< by body index (links, then obstacle parts)
};

FclArmValidityChecker::FclArmValidityChecker(const ompl::base::SpaceInformationPtr& si, const ArmScene& scene,
                                             double safetyMargin)
    : ArmValidityCheckerBase(si, std::make_shared<ArmScene>(scene), safetyMargin), models_(std::make_unique<Models>()) {
  for (std::size_t b = 0; b < linkBodies() + scene_->environment.size(); ++b) {
    models_->bodies.push_back(buildFclModel(bodyMesh(b)));
  }
  specs_.clearanceComputationType = ompl::base::StateValidityCheckerSpecs::EXACT;
}

FclArmValidityChecker::~FclArmValidityChecker() = default;

bool FclArmValidityChecker::pairSeparatedAbove(std::size_t a, const Pose& poseA, std::size_t b, const Pose& poseB,
                                               double margin) const {
  if (margin > 0.0) return pairDistance(a, poseA, b, poseB, std::numeric_limits<double>::infinity()).lower > margin;
  fcl::CollisionRequestd request;  // one contact decides
  fcl::CollisionResultd result;
  fcl::collide(models_->bodies[a].get(), poseA, models_->bodies[b].get(), poseB, request, result);
  return !result.isCollision();
}

ArmValidityCheckerBase::PairDistance FclArmValidityChecker::pairDistance(std::size_t a, const Pose& poseA,
                                                                         std::size_t b, const Pose& poseB,
                                                                         double) const {
  fcl::DistanceRequestd request;
  request.enable_nearest_points = false;
  request.rel_err = 0.0;
  request.abs_err = 0.0;
  fcl::DistanceResultd result;
  const double d =
      fcl::distance(models_->bodies[a].get(), poseA, models_->bodies[b].get(), poseB, request, result);
  PairDistance out;
  out.lower = std::max(0.0, d);  // FCL reports intersecting meshes with a negative distance
  return out;
}

}  // namespace adsd::planner
