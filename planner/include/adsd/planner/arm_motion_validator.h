#pragma once
/// \file
/// \brief A certified joint-space motion validator for arms: a straight motion is proven
/// collision-free from the clearances at a few states and a bound on how far the links move,
/// instead of being sampled at a fixed resolution (which can step over a thin obstacle).

#include <atomic>
#include <cstdint>
#include <memory>
#include <utility>

#include <ompl/base/MotionValidator.h>
#include <ompl/base/SpaceInformation.h>

#include "adsd/planner/arm_motion_bound.h"
#include "adsd/planner/arm_validity_checker_base.h"

namespace adsd::planner {

/// \brief What an ArmMotionValidator has done, for reports that compare it with OMPL's
/// DiscreteMotionValidator.
struct ArmMotionCounts {
  std::uint64_t motions = 0;           ///< checkMotion calls
  std::uint64_t rejected = 0;          ///< motions found (or not proven) invalid
  std::uint64_t clearanceQueries = 0;  ///< states a motion check queried (the start's validity, weighted clearances)
};

/// \brief Certified motion checking for an arm (issue 17), by the bisection of Schwarzer, Saha and
/// Latombe, "Exact collision checking of robot paths" (WAFR 2002), sec. 3.
///
/// For a segment [a, b] of the motion, let c(a), c(b) be the clearances at its ends (less the
/// safety margin and a roundoff allowance) and M the most any checked pair's distance can change
/// over the segment: for a link against an obstacle, the link's displacement bound B_L
/// (ArmMotionBound); for two links, B_{L1,L2}, the joints between them (both move). A contact at s in [a, b] needs
/// M (s - a)/(b - a) >= c(a) and M (b - s)/(b - a) >= c(b), hence M >= c(a) + c(b). So when
/// M < c(a) + c(b) the segment is free (the paper's eq. (1)); otherwise the segment is split at its
/// middle, whose clearance is measured, and both halves are checked, left first. A motion is
/// rejected when a midpoint (or the end) is not valid, or when a segment shorter than
/// kMinimumStepFraction of the motion would still need splitting (conservative: a valid motion
/// grazing an obstacle may be rejected, an invalid one is never accepted), unless steps from its
/// start, each as long as tau there proves alone, cross it with tau growing by kEscapeGrowth per
/// step: a motion leaving an obstacle its start is flush against.
///
/// Pair by pair: with w_P the pair's bound for the whole motion (B_L, or B_{L1,L2}) and
/// tau(s) = min over pairs of c_P(s) / w_P (ArmValidityCheckerBase::weightedClearanceUpTo), a
/// segment of parameter length len is free when len < tau(a) + tau(b), since then
/// w_P len < c_P(a) + c_P(b) for every pair. A pair near contact that barely moves no longer
/// forces short segments on a fast link elsewhere, as the robot-wide minimum would. The bound
/// scales with the segment's length, as the motion is linear in joint space (continuous joints
/// along the shorter arc, ArmStateSpace).
///
/// Thread-safe: each call allocates its own state; counters are atomic. The base class's
/// valid_/invalid_ counters are not written; use counts().
class ArmMotionValidator : public ompl::base::MotionValidator {
 public:
  ArmMotionValidator(const ompl::base::SpaceInformationPtr& si, std::shared_ptr<const ArmValidityCheckerBase> checker);

  /// \brief True only when the whole motion is proven valid (s1 is assumed valid, as in OMPL;
  /// a motion from a state within the margin is rejected).
  bool checkMotion(const ompl::base::State* s1, const ompl::base::State* s2) const override;
  /// \brief As above; when rejected, \p lastValid receives the last state proven valid (when its
  /// pointer is not null) and its parameter in [0, 1).
  bool checkMotion(const ompl::base::State* s1, const ompl::base::State* s2,
                   std::pair<ompl::base::State*, double>& lastValid) const override;

  /// \brief The bound M over the whole motion s1 -> s2 (metres): the most any checked pair's
  /// distance can change along it.
  double motionBound(const ompl::base::State* s1, const ompl::base::State* s2) const;

  ArmMotionCounts counts() const;
  void resetCounts();

 private:
  bool certify(const ompl::base::State* s1, const ompl::base::State* s2, double& lastValidT) const;

  std::shared_ptr<const ArmValidityCheckerBase> checker_;
  ArmMotionBound bound_;
  std::vector<std::size_t> obstacleLinks_;  ///< links with geometry, when there are obstacles
  std::vector<std::pair<std::size_t, std::size_t>> selfPairs_;  ///< enabled link pairs
  mutable std::atomic<std::uint64_t> motions_{0};
  mutable std::atomic<std::uint64_t> rejected_{0};
  mutable std::atomic<std::uint64_t> clearanceQueries_{0};
};

}  // namespace adsd::planner
