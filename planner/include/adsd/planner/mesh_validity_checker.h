#pragma once
/// \file
/// \brief The checker built on adsd::distance: the product's reason to exist (issue 4).

#include "adsd/distance.h"
#include "adsd/planner/rigid_body_validity_checker.h"

namespace adsd::planner {

/// \brief State validity and clearance from the adaptive-surface-decomposition distance query.
///
/// Validity runs the threshold query (QueryMode::threshold), which stops as soon as the distance is
/// proven above or below the safety margin. Clearance runs the query set by \p clearanceOptions:
/// exact (the default; specs_.clearanceComputationType = EXACT), or with a tolerance or a cap, in
/// which case clearance() returns a lower bound and the type is BOUNDED_APPROXIMATE.
///
/// Thread safety: queries need scratch memory; each thread uses its own thread_local
/// DistanceScratch, shared by every checker that thread runs. That is safe with any number of
/// checker instances because a thread runs one query at a time and a scratch is only working
/// memory (distance.h: reusable across queries, never shared by concurrent queries); nothing in
/// it belongs to a particular checker or mesh pair.
class MeshValidityChecker : public RigidBodyValidityChecker {
 public:
  /// \brief Throws adsd::InputError when \p clearanceOptions asks for the threshold mode or has
  /// invalid values, or when \p safetyMargin is negative or not finite.
  MeshValidityChecker(const ompl::base::SpaceInformationPtr& si, std::shared_ptr<const RigidBodyScene> scene,
                      double safetyMargin = 0.0, const DistanceOptions& clearanceOptions = DistanceOptions::exactDistance());

  const DistanceOptions& clearanceOptions() const { return clearanceOptions_; }

 protected:
  bool pairSeparatedAbove(std::size_t r, std::size_t e, const Pose& robotPose, double margin) const override;
  PairDistance pairDistance(std::size_t r, std::size_t e, const Pose& robotPose, double cap) const override;

 private:
  DistanceOptions clearanceOptions_;
};

}  // namespace adsd::planner
