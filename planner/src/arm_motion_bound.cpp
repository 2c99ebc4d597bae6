#include "adsd/planner/arm_motion_bound.h"

#include <algorithm>
#include <cmath>

namespace adsd::planner {

ArmMotionBound::ArmMotionBound(const ArmModel& model) : links_(model.links.size()), dof_(model.dof()) {
  // The joints that move: every joint of the joint vector, and every mimic joint, which moves
  // |multiplier| times as fast as the coordinate it follows.
  for (std::size_t j = 0; j < model.joints.size(); ++j) {
    const ArmJoint& joint = model.joints[j];
    if (joint.active >= 0) movers_.push_back({j, static_cast<std::size_t>(joint.active), 1.0});
    if (joint.mimicCoordinate >= 0) {
      movers_.push_back({j, static_cast<std::size_t>(joint.mimicCoordinate), std::abs(joint.mimicMultiplier)});
    }
  }
  k_.assign(links_ * movers_.size(), 0.0);
  beyond_.assign(links_ * movers_.size(), 0);
  coefficients_.assign(links_ * dof_, 0.0);
  // r_L: the farthest vertex of each link from its frame origin.
  std::vector<double> radius(links_, 0.0);
  for (std::size_t l = 0; l < links_; ++l) {
    if (!model.links[l].collision) continue;
    for (const Vec3& v : model.links[l].collision->vertices()) radius[l] = std::max(radius[l], v.norm());
  }
  // step_M: how far link M's frame origin can be from its parent's, in any configuration.
  std::vector<double> step(links_, 0.0);
  for (std::size_t l = 1; l < links_; ++l) {
    const ArmJoint& j = model.joints[static_cast<std::size_t>(model.links[l].parentJoint)];
    const auto [lower, upper] = model.positionRange(j);
    step[l] = j.origin.translation().norm() +
              (j.type == ArmJointType::prismatic ? std::max(std::abs(lower), std::abs(upper)) : 0.0);
  }
  const std::size_t movers = movers_.size();
  for (std::size_t m = 0; m < movers; ++m) {
    const ArmJoint& joint = model.joints[movers_[m].joint];
    const std::size_t c = joint.childLink;
    // Links beyond the joint: C and its descendants, which follow C contiguously in depth-first
    // order; chain[l] = sum of the steps from C (exclusive) to l (inclusive).
    std::vector<double> chain(links_, -1.0);
    chain[c] = 0.0;
    for (std::size_t l = c + 1; l < links_; ++l) {
      const std::size_t parent = model.joints[static_cast<std::size_t>(model.links[l].parentJoint)].parentLink;
      if (chain[parent] < 0.0) break;  // left C's subtree: depth-first order keeps it contiguous
      chain[l] = chain[parent] + step[l];
    }
    for (std::size_t l = c; l < links_ && chain[l] >= 0.0; ++l) {
      double k = 1.0;  // prismatic: every point moves as fast as the joint
      if (joint.type != ArmJointType::prismatic) {
        k = chain[l] + radius[l];
        if (l == c && model.links[c].collision) {
          // C turns about its own frame's axis: its vertices' distance from that line.
          double fromAxis = 0.0;
          for (const Vec3& v : model.links[c].collision->vertices()) {
            fromAxis = std::max(fromAxis, (v - v.dot(joint.axis) * joint.axis).norm());
          }
          k = fromAxis;
        }
      }
      k_[l * movers + m] = k * movers_[m].rate;
      beyond_[l * movers + m] = 1;
      coefficients_[l * dof_ + movers_[m].coordinate] += k * movers_[m].rate;
    }
  }
}

void ArmMotionBound::linkDisplacements(const double* dq, double* out) const {
  const std::size_t movers = movers_.size();
  for (std::size_t l = 0; l < links_; ++l) {
    double b = 0.0;
    for (std::size_t m = 0; m < movers; ++m) b += k_[l * movers + m] * std::abs(dq[movers_[m].coordinate]);
    out[l] = b;
  }
}

double ArmMotionBound::pairDisplacement(std::size_t a, std::size_t b, const double* dq) const {
  const std::size_t movers = movers_.size();
  double d = 0.0;
  for (std::size_t m = 0; m < movers; ++m) {
    if (beyond_[a * movers + m] != beyond_[b * movers + m]) {
      d += (k_[a * movers + m] + k_[b * movers + m]) * std::abs(dq[movers_[m].coordinate]);
    }
  }
  return d;
}

}  // namespace adsd::planner
