#include "adsd/planner/arm_motion_validator.h"

#include <algorithm>
#include <vector>

#include "adsd/error.h"
#include "adsd/planner/certified_motion_validator.h"
#include "non_null.h"

namespace adsd::planner {

namespace ob = ompl::base;

ArmMotionValidator::ArmMotionValidator(const ob::SpaceInformationPtr& si,
                                       std::shared_ptr<const ArmValidityCheckerBase> checker)
    : ob::MotionValidator(si),
      checker_(detail::nonNull(std::move(checker), "arm motion validator: the checker")),
      bound_(checker_->model()) {
  const ArmModel& model = checker_->model();
  if (!checker_->scene().environment.empty()) {
    for (std::size_t l = 0; l < model.links.size(); ++l) {
      if (model.links[l].collision) obstacleLinks_.push_back(l);
    }
  }
  selfPairs_ = checker_->scene().selfPairs.enabledPairs();
}

double ArmMotionValidator::motionBound(const ob::State* s1, const ob::State* s2) const {
  const std::size_t dof = checker_->armSpace().dof();
  const std::size_t links = checker_->model().links.size();
  thread_local std::vector<double> dq, b;
  dq.resize(dof);
  b.resize(links);
  checker_->armSpace().jointSteps(s1, s2, dq.data());
  bound_.linkDisplacements(dq.data(), b.data());
  double m = 0.0;
  for (std::size_t l : obstacleLinks_) m = std::max(m, b[l]);
  for (const auto& [l1, l2] : selfPairs_) m = std::max(m, bound_.pairDisplacement(l1, l2, dq.data()));
  return m;
}

bool ArmMotionValidator::certify(const ob::State* s1, const ob::State* s2, double& lastValidT) const {
  lastValidT = 0.0;
  if (!si_->satisfiesBounds(s2)) return false;
  // Per-link weights: B_L of the whole motion, so that a segment of parameter length len moves
  // link L by at most w_L len, and changes pair P's distance by at most w_P len.
  const std::size_t dof = checker_->armSpace().dof();
  std::vector<double> dq(dof), weights(checker_->model().links.size()), pairWeights(selfPairs_.size());
  checker_->armSpace().jointSteps(s1, s2, dq.data());
  bound_.linkDisplacements(dq.data(), weights.data());
  for (std::size_t k = 0; k < selfPairs_.size(); ++k) {
    pairWeights[k] = bound_.pairDisplacement(selfPairs_[k].first, selfPairs_[k].second, dq.data());
  }
  // Distances are trusted up to kDistanceTrustFraction of the scene's scale; each clearance gives
  // that away, and the margin, so that rounding never certifies a touching motion.
  const double giveAway = checker_->safetyMargin() + kDistanceTrustFraction * checker_->scale();
  // tau(s) = min over pairs of (d_P(s) - giveAway) / w_P, in units of the motion's parameter: a
  // segment [a, b] is free when b - a < tau(a) + tau(b) (for every pair P, w_P (b - a) <
  // c_P(a) + c_P(b): the class comment's condition, pair by pair). A state's tau is needed only
  // up to the length of the segments it ends (one end alone then proves them): the cap.
  const auto tau = [&](const ob::State* s, double segmentLength) {
    clearanceQueries_.fetch_add(1, std::memory_order_relaxed);
    return checker_->weightedClearanceUpTo(s, weights.data(), pairWeights.data(), giveAway, segmentLength);
  };
  // Pairs with w_P = 0 keep their distance along the motion: the start's validity covers them
  // (OMPL assumes it; checked, as the start may come from elsewhere).
  clearanceQueries_.fetch_add(1, std::memory_order_relaxed);
  if (!checker_->isValid(s1)) return false;
  struct Segment {
    double ta, ca, tb, cb;
  };
  std::vector<Segment> stack;
  ob::State* state = si_->allocState();
  // Below the floor, a segment [ta, tb] (ta is where the proven part ends: left halves come
  // first) is crossed by steps from ta, each as long as its start's tau proves alone, while tau
  // grows by kEscapeGrowth per step (kEscapeSteps per motion at most). The bisection alone never
  // proves a motion leaving an obstacle its start is flush against: moving away at a speed r < 1
  // times the bound's, tau(t) = tau(0) + r t, and [0, x] needs x < 2 tau(0) + r x. A start 1e-9
  // from a wall had every such motion rejected (the rigid validator has the same rule).
  int escapeSteps = 0;
  const auto escape = [&](const Segment& s) {
    if (!(s.cb > 0.0)) return false;  // an invalid end is never proven
    double t = s.ta, c = s.ca;
    while (s.tb - t >= c + s.cb) {
      if (escapeSteps++ >= kEscapeSteps) return false;
      // [t, t + c] is free (tau(t) = c alone proves it); the next step starts at its end.
      t += c;
      si_->getStateSpace()->interpolate(s1, s2, t, state);
      const double next = tau(state, s.tb - t);
      if (!(next > 0.0)) return false;
      lastValidT = t;
      if (s.tb - t < next + s.cb) return true;
      if (!(next >= kEscapeGrowth * c)) return false;  // sliding along or closing in
      c = next;
    }
    return true;
  };
  const double c0 = tau(s1, 1.0);
  const double c1 = tau(s2, 1.0);
  bool ok = c0 > 0.0;
  if (ok) stack.push_back({0.0, c0, 1.0, c1});
  while (ok && !stack.empty()) {
    const Segment s = stack.back();
    stack.pop_back();
    const double length = s.tb - s.ta;
    // The end counts only when it is valid (tau > 0); an invalid end is never proven, and its
    // segments shrink to the floor below.
    if (s.cb > 0.0 && length < s.ca + s.cb) {
      lastValidT = s.tb;  // left first: everything up to tb is proven
      continue;
    }
    if (length < kMinimumStepFraction) {
      ok = escape(s);
      if (!ok) break;
      lastValidT = s.tb;
      continue;
    }
    const double tm = 0.5 * (s.ta + s.tb);
    si_->getStateSpace()->interpolate(s1, s2, tm, state);
    const double cm = tau(state, 0.5 * length);
    if (!(cm > 0.0)) {
      ok = false;
      break;
    }
    stack.push_back({tm, cm, s.tb, s.cb});  // the right half after the left one
    stack.push_back({s.ta, s.ca, tm, cm});
  }
  si_->freeState(state);
  if (ok) lastValidT = 1.0;
  return ok;
}

bool ArmMotionValidator::checkMotion(const ob::State* s1, const ob::State* s2) const {
  motions_.fetch_add(1, std::memory_order_relaxed);
  double lastValidT = 0.0;
  const bool ok = certify(s1, s2, lastValidT);
  if (!ok) rejected_.fetch_add(1, std::memory_order_relaxed);
  return ok;
}

bool ArmMotionValidator::checkMotion(const ob::State* s1, const ob::State* s2,
                                     std::pair<ob::State*, double>& lastValid) const {
  motions_.fetch_add(1, std::memory_order_relaxed);
  double lastValidT = 0.0;
  const bool ok = certify(s1, s2, lastValidT);
  if (!ok) {
    rejected_.fetch_add(1, std::memory_order_relaxed);
    if (lastValid.first) si_->getStateSpace()->interpolate(s1, s2, lastValidT, lastValid.first);
    lastValid.second = lastValidT;
  }
  return ok;
}

ArmMotionCounts ArmMotionValidator::counts() const {
  ArmMotionCounts c;
  c.motions = motions_.load(std::memory_order_relaxed);
  c.rejected = rejected_.load(std::memory_order_relaxed);
  c.clearanceQueries = clearanceQueries_.load(std::memory_order_relaxed);
  return c;
}

void ArmMotionValidator::resetCounts() {
  motions_ = 0;
  rejected_ = 0;
  clearanceQueries_ = 0;
}

}  // namespace adsd::planner
