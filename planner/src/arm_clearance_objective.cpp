#include "adsd/planner/arm_clearance_objective.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include "adsd/planner/certified_motion_validator.h"
#include "non_null.h"

namespace adsd::planner {

namespace ob = ompl::base;

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

}  // namespace

ArmMotionClearance::ArmMotionClearance(std::shared_ptr<const ArmValidityCheckerBase> checker, ArmClearanceScope scope,
                                       MotionClearanceOptions options)
    : checker_(std::move(checker)), scope_(scope), options_(options), bound_(checker_->model()) {}

double ArmMotionClearance::at(const ob::State* state) const {
  return scope_ == ArmClearanceScope::obstacles ? checker_->obstacleClearanceUpTo(state, kInfinity)
                                                : checker_->clearance(state);
}

MotionClearance ArmMotionClearance::along(const ob::State* s1, const ob::State* s2) const {
  const ArmValidityCheckerBase& checker = *checker_;
  const ArmStateSpace& space = checker.armSpace();
  MotionClearance result;
  // The ends' exact clearances: U, the least found, an upper bound of the motion's least.
  const double c1 = at(s1), c2 = at(s2);
  double found = std::min(c1, c2);
  result.states = 2;
  const auto finish = [&](MotionClearance r) {
    motions_.fetch_add(1, std::memory_order_relaxed);
    states_.fetch_add(r.states, std::memory_order_relaxed);
    return r;
  };
  if (!(found < kInfinity)) {  // the scope has no pair: nothing bounds the clearance
    result.lower = result.upper = kInfinity;
    result.converged = true;
    return finish(result);
  }

  // w_P per unit of the motion's parameter: B_L(dq) for link L against the obstacles, B_{L1,L2}(dq)
  // for a link pair in the scope, 0 for one outside it (weightedClearanceUpTo skips weightless
  // pairs; a pair the motion does not move keeps its distance, which c1 counts).
  std::vector<double> dq(space.dof()), linkWeights(checker.model().links.size());
  space.jointSteps(s1, s2, dq.data());
  bound_.linkDisplacements(dq.data(), linkWeights.data());
  const auto selfPairs = checker.scene().selfPairs.enabledPairs();
  std::vector<double> pairWeights(selfPairs.size(), 0.0);
  double heaviest = 0.0;  // the largest w_P
  if (!checker.scene().environment.empty()) {
    for (std::size_t b = 0; b < checker.linkBodies(); ++b) {
      heaviest = std::max(heaviest, linkWeights[checker.linkOfBody(b)]);
    }
  }
  if (scope_ == ArmClearanceScope::obstaclesAndLinks) {
    for (std::size_t k = 0; k < selfPairs.size(); ++k) {
      pairWeights[k] = bound_.pairDisplacement(selfPairs[k].first, selfPairs[k].second, dq.data());
      heaviest = std::max(heaviest, pairWeights[k]);
    }
  }

  const double giveAway = kDistanceTrustFraction * checker.scale();
  const auto levelFor = [&](double least) {
    return least - std::max(options_.absoluteTolerance, options_.relativeTolerance * std::max(least, 0.0));
  };
  double level = levelFor(found);  // lambda: what the bisection proves every pair of the scope stays above
  // A distance is never negative: once U is within the tolerance of 0, 0 is the answer.
  const auto nearZero = [&] {
    if (level > 0.0) return false;
    result.lower = 0.0;
    result.upper = found;
    result.converged = true;
    return true;
  };
  if (nearZero()) return finish(result);
  // tau(s) = min over weighted pairs of (d_P(s) - lambda) / w_P, needed up to the segment length.
  const auto tau = [&](const ob::State* s, double segmentLength) {
    return checker.weightedClearanceUpTo(s, linkWeights.data(), pairWeights.data(), level + giveAway, segmentLength);
  };
  struct Segment {
    double ta, ca, tb, cb;  // parameters and tau at the ends (tau for a lambda at least the current one)
    /// What the ends leave unproven, len - tau_a - tau_b: the segment that may dip lowest first.
    bool operator<(const Segment& o) const { return (tb - ta) - ca - cb < (o.tb - o.ta) - o.ca - o.cb; }
  };
  std::priority_queue<Segment> open;
  open.push({0.0, tau(s1, 1.0), 1.0, tau(s2, 1.0)});
  double settled = kInfinity;  // bounds of segments left unproven (step floor, budget)
  // An unproven segment still bounds every pair: d_P >= lambda + w_P (tau_a + tau_b - len) / 2
  // (the cones from both ends meet there), >= lambda - w_max (len - tau_a - tau_b) / 2.
  const auto settle = [&](const Segment& s) {
    settled = std::min(settled, std::max(0.0, level - 0.5 * heaviest * std::max(0.0, (s.tb - s.ta) - s.ca - s.cb)));
    result.converged = false;
  };
  result.converged = true;
  ob::State* middle = space.allocState();
  while (!open.empty()) {
    const Segment s = open.top();
    open.pop();
    const double len = s.tb - s.ta;
    // Both ends at least lambda for every pair, and their cones cannot meet below it.
    if (s.ca >= 0.0 && s.cb >= 0.0 && len <= s.ca + s.cb) continue;
    if (len < kMinimumStepFraction || result.states >= options_.maxStates) {
      settle(s);
      continue;
    }
    const double tm = 0.5 * (s.ta + s.tb);
    space.interpolate(s1, s2, tm, middle);
    ++result.states;
    double cm = tau(middle, 0.5 * len);
    if (cm < 0.0) {
      // A pair below lambda: the least clearance is lower than U. Measure the middle exactly,
      // lower U and lambda, and go on (the taus already found only grow as lambda falls).
      found = std::min(found, at(middle));
      level = levelFor(found);
      if (nearZero()) break;
      cm = tau(middle, 0.5 * len);
    }
    open.push({s.ta, s.ca, tm, cm});
    open.push({tm, cm, s.tb, s.cb});
  }
  space.freeState(middle);
  if (level > 0.0) {
    result.lower = std::min(level, settled);
    result.upper = found;
  }
  return finish(result);
}

void ArmMotionClearance::resetCounts() {
  motions_ = 0;
  states_ = 0;
}

ArmClearanceObjective::ArmClearanceObjective(const ob::SpaceInformationPtr& si,
                                             std::shared_ptr<const ArmMotionClearance> clearance)
    : ob::OptimizationObjective(si),
      clearance_(detail::nonNull(std::move(clearance), "clearance objective: the clearance")) {
  description_ = "Certified minimum clearance";
  // Never satisfied: there is no clearance good enough to stop at.
  setCostThreshold(ob::Cost(kInfinity));
}

ob::Cost ArmClearanceObjective::stateCost(const ob::State* s) const { return ob::Cost(clearance_->at(s)); }

ob::Cost ArmClearanceObjective::motionCost(const ob::State* s1, const ob::State* s2) const {
  return ob::Cost(clearance_->along(s1, s2).lower);
}

bool ArmClearanceObjective::isCostBetterThan(ob::Cost c1, ob::Cost c2) const { return c1.value() > c2.value(); }

ob::Cost ArmClearanceObjective::combineCosts(ob::Cost c1, ob::Cost c2) const {
  return ob::Cost(std::min(c1.value(), c2.value()));
}

ob::Cost ArmClearanceObjective::identityCost() const { return ob::Cost(kInfinity); }

ob::Cost ArmClearanceObjective::infiniteCost() const { return ob::Cost(-kInfinity); }

}  // namespace adsd::planner
