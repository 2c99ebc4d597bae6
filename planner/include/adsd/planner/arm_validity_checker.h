#pragma once
/// \file
/// \brief The arm checker built on adsd::distance (issue 17).

#include "adsd/distance.h"
#include "adsd/planner/arm_validity_checker_base.h"

namespace adsd::planner {

/// \brief State validity and clearance of an arm from the adaptive-surface-decomposition distance
/// query, link by link (MeshValidityChecker's query modes, per pair).
///
/// Validity runs the threshold query on each pair the broad phase keeps, stopping at the first
/// pair within the margin. Clearance runs the query \p clearanceOptions sets: exact (default;
/// specs_.clearanceComputationType = EXACT), or with a tolerance or a cap, when clearance() is a
/// lower bound (BOUNDED_APPROXIMATE). Every link mesh and obstacle part gets its sub-mesh tree
/// (Mesh::buildHierarchy) on construction: the checker keeps its own copy of the scene.
///
/// Thread safety: each thread uses its own thread_local DistanceScratch (as MeshValidityChecker).
class ArmValidityChecker : public ArmValidityCheckerBase {
 public:
  /// \brief Throws adsd::InputError when \p clearanceOptions asks for the threshold mode or has
  /// invalid values, or for the base class's reasons.
  ArmValidityChecker(const ompl::base::SpaceInformationPtr& si, const ArmScene& scene, double safetyMargin = 0.0,
                     const DistanceOptions& clearanceOptions = DistanceOptions::exactDistance());

  const DistanceOptions& clearanceOptions() const { return clearanceOptions_; }

 protected:
  bool pairSeparatedAbove(std::size_t a, const Pose& poseA, std::size_t b, const Pose& poseB,
                          double margin) const override;
  PairDistance pairDistance(std::size_t a, const Pose& poseA, std::size_t b, const Pose& poseB,
                            double cap) const override;

 private:
  DistanceOptions clearanceOptions_;
};

}  // namespace adsd::planner
