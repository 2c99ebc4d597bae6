#pragma once
/// \file
/// \brief A motion validator that proves a straight motion collision-free from clearances,
/// instead of sampling it at discrete states (which can step over a thin wall).

#include <atomic>
#include <cstdint>
#include <memory>
#include <utility>

#include <ompl/base/MotionValidator.h>
#include <ompl/base/SpaceInformation.h>

#include "adsd/planner/rigid_body_validity_checker.h"

namespace adsd::planner {

/// Motions whose certified step would advance less than this fraction of the motion are rejected
/// (dimensionless). Stepping by clearance converges geometrically towards an obstacle that the
/// motion touches (a Zeno sequence); this floor ends it, and bounds the queries spent on one motion
/// to about 1 / kMinimumStepFraction per end: a walk that stops at the floor is finished from the
/// motion's other end. A valid motion that keeps this close for its whole length is rejected:
/// conservative, never unsafe.
inline constexpr double kMinimumStepFraction = 1e-5;

/// Except for a motion leaving an obstacle its start is flush against: the floor's steps are taken
/// while each one's spare clearance is at least this factor times the last one's (dimensionless).
/// Moving away at speed v, the spare grows by 1 + v / (the bound's speed) per step, so the steps
/// grow geometrically; one that slides along the obstacle or closes in stops at once.
inline constexpr double kEscapeGrowth = 1.1;
/// At most this many such steps (in a row for rigid bodies, per motion for arms): they bound the
/// queries a motion spends below the floor.
inline constexpr int kEscapeSteps = 256;

/// Distances are trusted up to this fraction of the scene's length scale (dimensionless): the
/// accuracy issue 4 asks of exact clearance against the brute-force oracle (1e-10 × the scene's
/// diagonal). Each certified step gives that much of its clearance away, so rounding in a distance
/// can never certify a touching motion.
inline constexpr double kDistanceTrustFraction = 1e-10;

/// \brief What a validator has done, for the reports that compare it with the discrete one.
struct MotionCounts {
  std::uint64_t motions = 0;        ///< checkMotion calls
  std::uint64_t rejected = 0;       ///< motions found (or not proven) invalid
  std::uint64_t clearanceSteps = 0; ///< clearance queries spent stepping along motions
};

/// \brief Certified motion checking (issue 4, item 2).
///
/// OMPL interpolates a motion s1 -> s2 linearly in translation and along the shortest arc in
/// rotation. Between parameters t and t', every robot point moves at most
///   L |t' - t|,  L = |translation(s2) - translation(s1)| + angle(s1, s2) * robotRadius,
/// (a rotation by alpha moves a point at distance r from the origin by at most alpha r). If the
/// clearance at t is c, every state up to t + (c - margin) / L is farther than the margin from the
/// environment. The validator advances by exactly such steps from s1 until it passes s2, so an
/// accepted motion is proven valid everywhere, however thin the obstacles.
///
/// Thread-safe: each call allocates its own states; counters are atomic. The base class's
/// valid_/invalid_ counters are not written (they are not atomic); use counts().
class CertifiedMotionValidator : public ompl::base::MotionValidator {
 public:
  CertifiedMotionValidator(const ompl::base::SpaceInformationPtr& si,
                           std::shared_ptr<const RigidBodyValidityChecker> checker);

  /// \brief True only when the whole motion is proven valid (s1 is assumed valid, as in OMPL).
  bool checkMotion(const ompl::base::State* s1, const ompl::base::State* s2) const override;
  /// \brief As above; when the motion is rejected, \p lastValid receives the last state proven
  /// valid (when its pointer is not null) and its parameter in [0, 1).
  bool checkMotion(const ompl::base::State* s1, const ompl::base::State* s2,
                   std::pair<ompl::base::State*, double>& lastValid) const override;

  MotionCounts counts() const;
  void resetCounts();

 private:
  /// Walks from s1 towards s2; returns true when it reaches s2, otherwise the last valid
  /// parameter in \p lastValidT.
  bool certify(const ompl::base::State* s1, const ompl::base::State* s2, double& lastValidT) const;

  std::shared_ptr<const RigidBodyValidityChecker> checker_;
  /// The largest |coordinate| of the environment and the robot (rounding scales with it).
  double sceneMagnitude_ = 0.0;
  mutable std::atomic<std::uint64_t> motions_{0};
  mutable std::atomic<std::uint64_t> rejected_{0};
  mutable std::atomic<std::uint64_t> clearanceSteps_{0};
};

}  // namespace adsd::planner
