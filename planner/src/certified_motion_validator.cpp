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
  double t = 0.0;
  bool proven = false;
  // Where the walk from s1 stopped below the step floor, with every state before it proven (-1:
  // it did not stop so).
  double grazedAt = -1.0;
  // The spare clearance of the last step, and how many steps in a row were below the floor.
  double lastSpare = 0.0;
  int smallSteps = 0;
  while (true) {
    const double spare = spareAt(t, 1.0 - t);
    if (!(spare > 0.0)) break;  // this state is not proven valid
    lastValidT = t;
    if (t >= 1.0 || sweep <= 0.0) {  // at s2, or s1 == s2 as poses: the one query decided it
      proven = true;
      break;
    }
    // Every state in [t, t + step] is farther than the margin: its distance is at least
    // clearance - sweep * step = margin + trust.
    const double step = spare / sweep;
    if (t + step >= 1.0) {
      proven = true;
      break;
    }
    // Grazing: not provable at this cost (see the constant). Except a motion leaving an obstacle
    // it starts flush against, whose spare grows by a factor with every step (by 1 + v / sweep,
    // v its speed away from the obstacle): a start 1.5e-8 from a wall, 1e-9 of the scene, had
    // every motion rejected, and certified planning from it never solved (an outside review).
    // Such steps are taken while the spare grows by kEscapeGrowth each, up to kEscapeSteps in a
    // row; a motion that slides along or closes in stops at once, as before.
    if (step < kMinimumStepFraction) {
      const bool escaping = t > 0.0 && spare >= kEscapeGrowth * lastSpare && smallSteps < kEscapeSteps;
      if (t > 0.0 && !escaping) {
        grazedAt = t + step;
        break;
      }
      ++smallSteps;
    } else {
      smallSteps = 0;
    }
    lastSpare = spare;
    t += step;
  }
  // A walk that grazed may be closing in on an end flush against an obstacle, which its steps,
  // shrinking with the clearance, never reach; from that end the same motion leaves the obstacle
  // and its steps grow. So the rest is walked from s2 back to where the first walk stopped, with
  // the same rules, and the motion is proven when the two meet: it is then accepted in either
  // direction, as OMPL's PathGeometric::check asks of paths whose motions a planner growing a
  // tree from the goal checked from their far ends (an outside review: 14 of 20 paths of the
  // README's example failed check(), every rejected motion accepted in reverse).
  if (grazedAt >= 0.0) {
    double u = 1.0;
    lastSpare = 0.0;
    smallSteps = 0;
    while (true) {
      const double spare = spareAt(u, u - grazedAt);
      if (!(spare > 0.0)) break;
      const double step = spare / sweep;
      if (u - step <= grazedAt) {
        proven = true;
        break;
      }
      if (step < kMinimumStepFraction) {
        const bool escaping = u < 1.0 && spare >= kEscapeGrowth * lastSpare && smallSteps < kEscapeSteps;
        if (u < 1.0 && !escaping) break;
        ++smallSteps;
      } else {
        smallSteps = 0;
      }
      lastSpare = spare;
      u -= step;
    }
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
