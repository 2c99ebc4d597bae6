#pragma once
/// \file
/// \brief The same checker on FCL 0.7 (OBBRSS hierarchies), for side-by-side comparisons.

#include <memory>
#include <vector>

#include "adsd/planner/rigid_body_validity_checker.h"

namespace adsd::planner {

/// \brief Validity from fcl::collide (or fcl::distance when the safety margin is positive),
/// clearance from fcl::distance with zero error tolerance (specs_: EXACT as FCL reports it).
///
/// The OBBRSS models are built once and only read afterwards; each query passes the poses
/// explicitly (FCL's geometry-level collide/distance), so no shared CollisionObject transform is
/// written and concurrent queries need no lock.
class FclValidityChecker : public RigidBodyValidityChecker {
 public:
  FclValidityChecker(const ompl::base::SpaceInformationPtr& si, std::shared_ptr<const RigidBodyScene> scene,
                     double safetyMargin = 0.0);
  ~FclValidityChecker() override;

 protected:
  bool pairSeparatedAbove(std::size_t r, std::size_t e, const Pose& robotPose, double margin) const override;
  PairDistance pairDistance(std::size_t r, std::size_t e, const Pose& robotPose, double cap) const override;

 private:
  struct Models;
  std::unique_ptr<Models> models_;
};

}  // namespace adsd::planner
