#include "adsd/planner/certified_motion_validator.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "adsd/planner/rigid_body_scene.h"
#include "adsd/planner/state_pose.h"
#include "adsd/tolerances.h"
#include "non_null.h"

namespace adsd::planner {

namespace ob = ompl::base;

namespace {

/// Ulps of the magnitudes involved given away per step: the query's roundoff allowance, twice
/// (adsd/distance.h: its M adds both meshes' coordinates to the poses' offset), and four for the
/// interpolated state's own rounding.
constexpr double kRoundingUlps = 2.0 * tolerance::kBoundSafetyUlps + 4.0;

}  // namespace

CertifiedMotionValidator::CertifiedMotionValidator(const ob::SpaceInformationPtr& si,
                                                   std::shared_ptr<const RigidBodyValidityChecker> checker)
    : ob::MotionValidator(si),
      checker_(detail::nonNull(std::move(checker), "certified motion validator: the checker")) {
  // The largest coordinate of the environment and the robot: the farthest corner of the
  // environment's box from the origin, and the robot's reach.
  const Eigen::AlignedBox3d box = environmentBounds(checker_->scene());
  if (!box.isEmpty()) sceneMagnitude_ = std::max(box.min().norm(), box.max().norm());
  sceneMagnitude_ += checker_->robotRadius();
}

bool CertifiedMotionValidator::certify(const ob::State* s1, const ob::State* s2, double& lastValidT) const {
  lastValidT = 0.0;
  const RigidBodySpace space = checker_->space();
  const double margin = checker_->safetyMargin();
  // Rounding allowance given away by every step (see kDistanceTrustFraction), and what rounding
  // costs far from the origin: an interpolated state lies off the straight motion by a few eps of
  // the ends' magnitude, and a distance is trusted only to kBoundSafetyUlps eps of the magnitudes
  // the query works with (adsd/distance.h). Both are negligible in a scene near its origin; a
  // start 1e20 away made states near the walls land metres off the motion, and a motion through
  // them was certified.
  const double magnitude = poseFromState(s1, space).translation().norm() +
                           poseFromState(s2, space).translation().norm() + sceneMagnitude_;
  const double trust = kDistanceTrustFraction * checker_->scale() +
                       kRoundingUlps * tolerance::kEpsilon * magnitude;
  // Bound on how far any robot point moves per unit of the motion parameter t.
  const double sweep =
      translationDistance(s1, s2, space) + rotationAngle(s1, s2, space) * checker_->robotRadius();

  // An end the distance query cannot take (a NaN coordinate): nothing along the motion is proven.
  if (!std::isfinite(sweep) || !std::isfinite(trust)) return false;
  ob::State* state = si_->allocState();
  // The spare clearance at parameter t, left when the distance needed to carry the walk over the
  // \p remaining part of the parameter is granted (one more `trust`, so that a capped answer
  // carries the step past its end despite rounding).
  auto spareAt = [&](double t, double remaining) {
    if (t == 0.0) {
      si_->copyState(state, s1);
    } else if (t == 1.0) {
      si_->copyState(state, s2);
    } else {
      si_->getStateSpace()->interpolate(s1, s2, t, state);
    }
    const double clearance = checker_->clearanceUpTo(state, margin + 2.0 * trust + sweep * remaining);
    clearanceSteps_.fetch_add(1, std::memory_order_relaxed);
    return clearance - margin - trust;
  };
  // Walks the motion's parameter from `from` towards `to` (either way), each step as long as the
  // clearance at its start proves: every state in [x, x + step] is farther than the margin, its
  // distance at least clearance - sweep * step = margin + trust. `lastProven` gets each parameter
  // whose state was proven. Ends proven at `to`, unproven at a state not proven valid, or grazing
  // (`grazedAt`, where the states up to it are proven) when a step falls below the floor.
  struct WalkEnd {
    bool proven = false;
    double grazedAt = -1.0;
  };
  auto walk = [&](double from, double to, double& lastProven) {
    const double direction = to > from ? 1.0 : -1.0;
    double x = from;
    // The spare clearance of the last step, and how many steps in a row were below the floor.
    double lastSpare = 0.0;
    int smallSteps = 0;
    while (true) {
      const double spare = spareAt(x, direction * (to - x));
      if (!(spare > 0.0)) return WalkEnd{};  // this state is not proven valid
      lastProven = x;
      // At `to`, or s1 == s2 as poses: the one query decided it.
      if (direction * (to - x) <= 0.0 || sweep <= 0.0) return WalkEnd{true};
      const double step = spare / sweep;
      const double next = x + direction * step;
      if (direction * (next - to) >= 0.0) return WalkEnd{true};
      // Grazing: not provable at this cost (see the constant). Except a motion leaving an obstacle
      // its end is flush against, whose spare grows by a factor with every step (by 1 + v / sweep,
      // v its speed away from the obstacle): a start 1.5e-8 from a wall, 1e-9 of the scene, had
      // every motion rejected, and certified planning from it never solved (an outside review).
      // Such steps are taken while the spare grows by kEscapeGrowth each, up to kEscapeSteps in a
      // row; a motion that slides along or closes in stops at once.
      if (step < kMinimumStepFraction) {
        const bool escaping = x != from && spare >= kEscapeGrowth * lastSpare && smallSteps < kEscapeSteps;
        if (x != from && !escaping) return WalkEnd{false, next};
        ++smallSteps;
      } else {
        smallSteps = 0;
      }
      lastSpare = spare;
      x = next;
    }
  };
  const WalkEnd fromS1 = walk(0.0, 1.0, lastValidT);
  bool proven = fromS1.proven;
  // A walk that grazed may be closing in on an end flush against an obstacle, which its steps,
  // shrinking with the clearance, never reach; from that end the same motion leaves the obstacle
  // and its steps grow. So the rest is walked from s2 back to where the first walk stopped, and
  // the motion is proven when the two meet: a motion reaching a flush state is accepted as the one
  // leaving it, as OMPL's PathGeometric::check asks of paths whose motions a planner growing a
  // tree from the goal checked from their far ends (an outside review: 14 of 20 paths of the
  // README's example failed check(), every rejected motion accepted in reverse).
  if (!proven && fromS1.grazedAt >= 0.0) {
    double provenFromS2 = 1.0;
    proven = walk(1.0, fromS1.grazedAt, provenFromS2).proven;
  }
  si_->freeState(state);
  return proven;
}

bool CertifiedMotionValidator::checkMotion(const ob::State* s1, const ob::State* s2) const {
  motions_.fetch_add(1, std::memory_order_relaxed);
  // The end state's bounds: positions interpolate linearly and the bounds are a box, so if both
  // ends are inside so is the whole motion (s1 is valid by OMPL's contract).
  // A cheap threshold query on s2 first: a motion into an obstacle is rejected without walking up
  // to the obstacle by ever shorter steps.
  bool valid = si_->satisfiesBounds(s2) && checker_->isValid(s2);
  double lastValidT = 0.0;
  if (valid) valid = certify(s1, s2, lastValidT);
  if (!valid) rejected_.fetch_add(1, std::memory_order_relaxed);
  return valid;
}

bool CertifiedMotionValidator::checkMotion(const ob::State* s1, const ob::State* s2,
                                           std::pair<ob::State*, double>& lastValid) const {
  motions_.fetch_add(1, std::memory_order_relaxed);
  double lastValidT = 0.0;
  bool valid = certify(s1, s2, lastValidT);
  if (valid && !si_->satisfiesBounds(s2)) {
    valid = false;
    // The last state inside the bounds is not located exactly; the start is certainly inside.
    lastValidT = 0.0;
  }
  if (!valid) {
    rejected_.fetch_add(1, std::memory_order_relaxed);
    if (lastValid.first != nullptr) si_->getStateSpace()->interpolate(s1, s2, lastValidT, lastValid.first);
    lastValid.second = lastValidT;
  }
  return valid;
}

MotionCounts CertifiedMotionValidator::counts() const {
  MotionCounts c;
  c.motions = motions_.load(std::memory_order_relaxed);
  c.rejected = rejected_.load(std::memory_order_relaxed);
  c.clearanceSteps = clearanceSteps_.load(std::memory_order_relaxed);
  return c;
}

void CertifiedMotionValidator::resetCounts() {
  motions_ = 0;
  rejected_ = 0;
  clearanceSteps_ = 0;
}

}  // namespace adsd::planner
