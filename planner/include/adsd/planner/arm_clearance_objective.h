#pragma once
/// \file
/// \brief Clearance-optimal planning for arms (issue 17): the certified smallest clearance along a
/// joint-space motion, and an OMPL objective that maximizes a path's smallest clearance with it.
///
/// OMPL's MaximizeMinClearanceObjective costs a motion by the clearance at its states a
/// validity-checking resolution apart (MinimaxObjective::motionCost), which is only an upper
/// bound of the motion's smallest clearance: a motion that grazes an obstacle between two of those
/// states costs as if it kept clear. ArmClearanceObjective costs it by a lower bound proven from
/// the clearances at a few states and the bound on how far the links move (arm_motion_bound.h),
/// refined until it is within a tolerance of the smallest clearance found.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include <ompl/base/OptimizationObjective.h>

#include "adsd/planner/arm_motion_bound.h"
#include "adsd/planner/arm_validity_checker_base.h"

namespace adsd::planner {

/// \brief What clearance the objective measures. The checker checks every enabled link pair either
/// way: this changes what is optimized, never what is valid.
///
/// Obstacles by default, as MoveIt's PlanningScene::distanceToCollision (which ignores
/// self-collision): on both shipped arms some enabled link pairs stay within millimetres to a few
/// centimetres of each other in nearly every configuration (the KR5's forearm and palm 0-6 mm,
/// its base and upper arm at most 37.5 mm; the WAM's /wam5 and /wam7 a median 8 mm:
/// ArmClearanceObjective.SomeLinkPairsStayCloseOnTheShippedArms), and with them a path's least
/// clearance is that gap whatever the path takes.
enum class ArmClearanceScope {
  obstacles,         ///< every link against every obstacle (ArmValidityCheckerBase::obstacleClearanceUpTo)
  obstaclesAndLinks  ///< and the enabled link pairs (the checker's clearance())
};

/// \brief How closely ArmMotionClearance::along() brackets a motion's smallest clearance.
struct MotionClearanceOptions {
  /// Stop when the certified lower bound is within max(absoluteTolerance, relativeTolerance x the
  /// smallest clearance found) of the smallest clearance found (metres, and dimensionless).
  double absoluteTolerance = 1e-3;
  double relativeTolerance = 0.05;
  /// States queried per motion at most, both ends included; past it the lower bound is returned
  /// as it stands (still certified, less tight).
  std::size_t maxStates = 64;
};

/// \brief What along() established about the motion's smallest clearance m (over the scope's
/// pairs, for t in [0, 1]).
struct MotionClearance {
  double lower = 0.0;  ///< certified: lower <= m (less the distance trust allowance)
  double upper = 0.0;  ///< the smallest clearance found at a queried state: m <= upper
  std::size_t states = 0;  ///< distinct states queried, both ends included
  bool converged = false;  ///< upper - lower within the tolerance (else the budget or the step floor ended it)
};

/// \brief The smallest clearance along a straight joint-space motion, bracketed with a certified
/// lower bound: the motion validator's bisection (ArmMotionValidator; Schwarzer, Saha and Latombe
/// 2002), run at a level lambda just below the least clearance found instead of at the margin.
///
/// The bound. Along the motion q(t) = q1 + t dq, pair P's distance d_P changes by at most
/// w_P |t - t'| between t and t' (ArmMotionBound: w_P = B_L(dq) for link L against an obstacle,
/// B_{L1,L2}(dq) for two links). On a segment [a, b], d_P(t) >= max(d_P(a) - w_P (t - a),
/// d_P(b) - w_P (b - t)), so P stays at or above lambda there when d_P(a), d_P(b) >= lambda and
/// w_P (b - a) <= (d_P(a) - lambda) + (d_P(b) - lambda). With
/// tau(s) = min over the scope's pairs of (d_P(s) - lambda) / w_P (ArmValidityCheckerBase::
/// weightedClearanceUpTo, with lambda for the margin), every pair of the scope is proven at or above
/// lambda on [a, b] when tau(a), tau(b) >= 0 and b - a <= tau(a) + tau(b).
///
/// The search. U, the least clearance found, starts as the smaller end clearance (exact), and
/// lambda = U - tolerance. Segments not proven are split at their middle, the one its ends leave
/// least proven (largest b - a - tau(a) - tau(b)) first, where the least clearance most likely
/// lies. A middle with tau < 0 has a pair below lambda: its exact clearance lowers U and lambda,
/// and the search goes on (tau only grows as lambda falls, so the ends already measured stay
/// usable). When every segment is proven, lambda is the answer: lower = lambda <= m <= U = upper,
/// with U - lambda = the tolerance; once U is within the tolerance of 0, 0 is (no distance is
/// negative: a motion through an obstacle costs little). A segment still unproven at the step
/// floor (kMinimumStepFraction) or past the budget is settled with what its ends prove: every pair
/// stays above lambda - w_max (b - a - tau(a) - tau(b)) / 2 (and 0), and the result is not
/// converged. Distances are trusted to kDistanceTrustFraction of the scene's scale, which the
/// proof gives away.
///
/// Cost: a motion far from the obstacles is proven from its ends; one that passes close needs
/// states about 2 tolerance / w_P apart where its clearance is within a few tolerances of its
/// least (a grazing swing of the small test arm: about 60 states at 1 mm), each a
/// weightedClearanceUpTo query.
///
/// Pairs the motion does not move (w_P = 0) keep their distance, which the start's clearance
/// counts. Thread-safe: each call allocates its own buffers; counters are atomic.
class ArmMotionClearance {
 public:
  ArmMotionClearance(std::shared_ptr<const ArmValidityCheckerBase> checker,
                     ArmClearanceScope scope = ArmClearanceScope::obstacles, MotionClearanceOptions options = {});

  /// \brief The exact clearance at \p state over the scope's pairs (infinity when it has none).
  double at(const ompl::base::State* state) const;
  /// \brief The smallest clearance along the straight motion \p s1 -> \p s2, both ends included.
  MotionClearance along(const ompl::base::State* s1, const ompl::base::State* s2) const;

  ArmClearanceScope scope() const { return scope_; }
  const ArmValidityCheckerBase& checker() const { return *checker_; }
  const MotionClearanceOptions& options() const { return options_; }

  /// \brief along() calls and the states they queried, since construction or resetCounts().
  std::uint64_t motions() const { return motions_.load(std::memory_order_relaxed); }
  std::uint64_t statesQueried() const { return states_.load(std::memory_order_relaxed); }
  void resetCounts();

 private:
  std::shared_ptr<const ArmValidityCheckerBase> checker_;
  ArmClearanceScope scope_;
  MotionClearanceOptions options_;
  ArmMotionBound bound_;
  mutable std::atomic<std::uint64_t> motions_{0};
  mutable std::atomic<std::uint64_t> states_{0};
};

/// \brief Maximize a path's smallest clearance, each motion costed by its certified smallest
/// clearance (ArmMotionClearance::along's lower bound).
///
/// Costs are clearances (metres); larger is better; a path's cost is the least of its motions'
/// (a minimax objective, as OMPL's MaximizeMinClearanceObjective): identity +infinity, infinite
/// cost -infinity, and the cost threshold +infinity (never satisfied: an optimizing planner uses
/// its whole time). A path's cost is never above the smallest clearance along it.
class ArmClearanceObjective : public ompl::base::OptimizationObjective {
 public:
  ArmClearanceObjective(const ompl::base::SpaceInformationPtr& si, std::shared_ptr<const ArmMotionClearance> clearance);

  /// \brief The clearance at \p s over the scope's pairs.
  ompl::base::Cost stateCost(const ompl::base::State* s) const override;
  /// \brief The certified smallest clearance along the motion.
  ompl::base::Cost motionCost(const ompl::base::State* s1, const ompl::base::State* s2) const override;
  /// \brief c1 is better when it is the larger clearance.
  bool isCostBetterThan(ompl::base::Cost c1, ompl::base::Cost c2) const override;
  /// \brief The smaller clearance.
  ompl::base::Cost combineCosts(ompl::base::Cost c1, ompl::base::Cost c2) const override;
  ompl::base::Cost identityCost() const override;
  ompl::base::Cost infiniteCost() const override;

  const ArmMotionClearance& clearance() const { return *clearance_; }

 private:
  std::shared_ptr<const ArmMotionClearance> clearance_;
};

}  // namespace adsd::planner
