#include "adsd/planner/fcl_validity_checker.h"

#include <algorithm>
#include <limits>

#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>

#include "adsd/error.h"
#include "fcl_model.h"

namespace adsd::planner {

using detail::FclModel;
using detail::buildFclModel;

struct FclValidityChecker::Models {
  std::vector<std::shared_ptr<FclModel>> robot;
  std::vector<std::shared_ptr<FclModel>> environment;
};

FclValidityChecker::FclValidityChecker(const ompl::base::SpaceInformationPtr& si,
                                       std::shared_ptr<const RigidBodyScene> scene, double safetyMargin)
    : RigidBodyValidityChecker(si, std::move(scene), safetyMargin), models_(std::make_unique<Models>()) {
  for (const Mesh& m : scene_->robot) models_->robot.push_back(buildFclModel(m));
  for (const Mesh& m : scene_->environment) models_->environment.push_back(buildFclModel(m));
  // fcl::distance with zero relative and absolute error is FCL's exact mode.
  specs_.clearanceComputationType = ompl::base::StateValidityCheckerSpecs::EXACT;
}

FclValidityChecker::~FclValidityChecker() = default;

bool FclValidityChecker::pairSeparatedAbove(std::size_t r, std::size_t e, const Pose& robotPose,
                                            double margin) const {
  if (margin > 0.0) return pairDistance(r, e, robotPose, std::numeric_limits<double>::infinity()).lower > margin;
  fcl::CollisionRequestd request;  // one contact is enough to decide
  fcl::CollisionResultd result;
  fcl::collide(models_->robot[r].get(), robotPose, models_->environment[e].get(), fcl::Transform3d::Identity(),
               request, result);
  return !result.isCollision();
}

RigidBodyValidityChecker::PairDistance FclValidityChecker::pairDistance(std::size_t r, std::size_t e,
                                                                        const Pose& robotPose, double) const {
  fcl::DistanceRequestd request;
  request.enable_nearest_points = false;
  request.rel_err = 0.0;
  request.abs_err = 0.0;
  fcl::DistanceResultd result;
  const double d = fcl::distance(models_->robot[r].get(), robotPose, models_->environment[e].get(),
                                 fcl::Transform3d::Identity(), request, result);
  // FCL reports intersecting meshes with a negative distance (-1) instead of 0.
  PairDistance out;
  out.lower = std::max(0.0, d);
  return out;
}

}  // namespace adsd::planner
