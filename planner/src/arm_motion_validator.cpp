#include "adsd/planner/arm_motion_validator.h"

#include <algorithm>
#include <vector>

#include "adsd/error.h"
#include "adsd/planner/certified_motion_validator.h"

namespace adsd::planner {

namespace ob = ompl::base;

ArmMotionValidator::ArmMotionValidator(const ob::SpaceInformationPtr& si,
                                       std::shared_ptr<const ArmValidityCheckerBase> checker)
    : ob::MotionValidator(si), checker_(std::move(checker)), bound_(checker_->model()) {
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
  for (const auto& [l1, l2] : selfPairs_) m = std::max(m, b[l1] + b[l2]);
  return m;
}

bool ArmMotionValidator::certify(const ob::State* s1, const ob::State* s2, double& lastValidT) const {
  lastValidT = 0.0;
  if (!si_->satisfiesBounds(s2)) return false;
  const double total = motionBound(s1, s2);
  // Distances are trusted up to kDistanceTrustFraction of the scene's scale; each clearance gives
  // that away, and the margin, so that rounding never certifies a touching motion.
  const double giveAway = checker_->safetyMargin() + kDistanceTrustFraction * checker_->scale();
  // A state's clearance is needed only up to the bound of the segments it ends: above
  // M x (their length), one end alone proves them. Asking for no more lets the distance queries
  // stop early (clearanceUpTo's cap), which matters most deep in the bisection.
  const double allowance = kDistanceTrustFraction * checker_->scale();
  ob::State* state = si_->allocState();
  const auto effective = [&](const ob::State* s, double segmentLength) {
    clearanceQueries_.fetch_add(1, std::memory_order_relaxed);
    return checker_->clearanceUpTo(s, giveAway + total * segmentLength + allowance) - giveAway;
  };
  struct Segment {
    double ta, ca, tb, cb;
  };
  std::vector<Segment> stack;
  const double c0 = effective(s1, 1.0);
  const double c1 = effective(s2, 1.0);
  bool ok = c0 > 0.0;
  if (ok) stack.push_back({0.0, c0, 1.0, c1});
  while (ok && !stack.empty()) {
    const Segment s = stack.back();
    stack.pop_back();
    const double length = s.tb - s.ta;
    // The end's clearance counts only when the end is valid (c > 0); an invalid end is never
    // proven, and its segments shrink to the floor below.
    if (s.cb > 0.0 && total * length < s.ca + s.cb) {
      lastValidT = s.tb;  // left first: everything up to tb is proven
      continue;
    }
    if (length < kMinimumStepFraction) {
      ok = false;
      break;
    }
    const double tm = 0.5 * (s.ta + s.tb);
    si_->getStateSpace()->interpolate(s1, s2, tm, state);
    const double cm = effective(state, 0.5 * length);
    if (!(cm > 0.0)) {
      ok = false;
      break;
    }
    stack.push_back({tm, cm, s.tb, s.cb});  // right half after the left one
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
