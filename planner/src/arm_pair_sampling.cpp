#include "adsd/planner/arm_pair_sampling.h"

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "adsd/distance.h"
#include "adsd/error.h"
#include "adsd/planner/arm_kinematics.h"

namespace adsd::planner {

PairSamplingResult disablePairsBySampling(const ArmModel& model, ArmCollisionPairs& pairs, std::size_t states,
                                          std::uint64_t seed, NeverInContact never) {
  if (states == 0) throw InputError("pair sampling: the number of states must be > 0");
  // The links are queried many times: a copy with sub-mesh trees.
  ArmModel prepared = model;
  prepared.buildHierarchies();
  const std::vector<std::pair<std::size_t, std::size_t>> tested = pairs.enabledPairs();
  std::vector<std::size_t> contacts(tested.size(), 0);
  std::mt19937_64 rng(seed);
  std::vector<double> q(model.dof());
  std::vector<Pose> poses;
  DistanceScratch scratch;
  for (std::size_t s = 0; s < states; ++s) {
    for (std::size_t i = 0; i < q.size(); ++i) {
      const ArmJoint& joint = model.joints[model.activeJoints[i]];
      q[i] = std::uniform_real_distribution<double>(joint.lower, joint.upper)(rng);
    }
    forwardKinematics(prepared, q.data(), poses);
    for (std::size_t k = 0; k < tested.size(); ++k) {
      const auto [a, b] = tested[k];
      const DistanceResult r = distance(*prepared.links[a].collision, poses[a], *prepared.links[b].collision, poses[b],
                                        DistanceOptions::aboveThreshold(0.0), scratch);
      if (r.status != DistanceStatus::aboveThreshold) ++contacts[k];
    }
  }
  PairSamplingResult result;
  result.states = states;
  result.pairsTested = tested.size();
  for (std::size_t k = 0; k < tested.size(); ++k) {
    if (contacts[k] == states) {
      pairs.disable(tested[k].first, tested[k].second, "Always");
      ++result.alwaysInContact;
    } else if (contacts[k] == 0) {
      if (never == NeverInContact::disable) pairs.disable(tested[k].first, tested[k].second, "Never");
      ++result.neverInContact;
    }
  }
  return result;
}

std::vector<double> defaultJointVector(const ArmModel& model) {
  std::vector<double> q(model.dof());
  for (std::size_t i = 0; i < q.size(); ++i) {
    q[i] = defaultPosition(model.joints[model.activeJoints[i]]);
  }
  return q;
}

std::size_t disablePairsInContactAt(const ArmModel& model, ArmCollisionPairs& pairs, const std::vector<double>& q) {
  if (q.size() != model.dof()) {
    throw InputError(model.sourceFile + ": a joint vector of " + std::to_string(q.size()) + " values for " +
                     std::to_string(model.dof()) + " joints");
  }
  std::vector<Pose> poses;
  forwardKinematics(model, q.data(), poses);
  DistanceScratch scratch;
  std::size_t count = 0;
  for (const auto& [a, b] : pairs.enabledPairs()) {
    const DistanceResult r = distance(*model.links[a].collision, poses[a], *model.links[b].collision, poses[b],
                                      DistanceOptions::aboveThreshold(0.0), scratch);
    if (r.status == DistanceStatus::aboveThreshold) continue;
    pairs.disable(a, b, "Default");
    ++count;
  }
  return count;
}

}  // namespace adsd::planner
