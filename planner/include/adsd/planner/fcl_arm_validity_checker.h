#pragma once
/// \file
/// \brief The arm checker on FCL 0.7 (an OBBRSS hierarchy per link and per obstacle part), behind
/// the same broad phase and the same disabled pairs as ArmValidityChecker: the baseline that
/// compares the narrow phases alone.

#include <memory>

#include "adsd/planner/arm_validity_checker_base.h"

namespace adsd::planner {

/// \brief Validity from fcl::collide (fcl::distance when the safety margin is positive),
/// clearance from fcl::distance with zero error tolerance (EXACT as FCL reports it). The models are
/// built once and only read; poses are passed per query, so concurrent queries need no lock.
class FclArmValidityChecker : public ArmValidityCheckerBase {
 public:
  FclArmValidityChecker(const ompl::base::SpaceInformationPtr& si, const ArmScene& scene, double safetyMargin = 0.0);
  ~FclArmValidityChecker() override;

 protected:
  bool pairSeparatedAbove(std::size_t a, const Pose& poseA, std::size_t b, const Pose& poseB,
                          double margin) const override;
  PairDistance pairDistance(std::size_t a, const Pose& poseA, std::size_t b, const Pose& poseB,
                            double cap) const override;

 private:
  struct Models;
  std::unique_ptr<Models> models_;
};

}  // namespace adsd::planner
