#include "adsd/planner/arm_motion_bound.h"

#include <algorithm>
#include <cmath>

namespace adsd::planner {

ArmMotionBound::ArmMotionBound(const ArmModel& model)
    : links_(model.links.size()), dof_(model.dof()), k_(links_ * dof_, 0.0), beyond_(links_ * dof_, 0) {
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
    step[l] = j.origin.translation().norm() +
              (j.type == ArmJointType::prismatic ? std::max(std::abs(j.lower), std::abs(j.upper)) : 0.0);
  }
  for (std::size_t i = 0; i < dof_; ++i) {
    const ArmJoint& joint = model.joints[model.activeJoints[i]];
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
      k_[l * dof_ + i] = k;
      beyond_[l * dof_ + i] = 1;
    }
  }
}

void ArmMotionBound::linkDisplacements(const double* dq, double* out) const {
  for (std::size_t l = 0; l < links_; ++l) {
    double b = 0.0;
    for (std::size_t i = 0; i < dof_; ++i) b += k_[l * dof_ + i] * std::abs(dq[i]);
    out[l] = b;
  }
}

double ArmMotionBound::pairDisplacement(std::size_t a, std::size_t b, const double* dq) const {
  double d = 0.0;
  for (std::size_t i = 0; i < dof_; ++i) {
    if (beyond_[a * dof_ + i] != beyond_[b * dof_ + i]) d += (k_[a * dof_ + i] + k_[b * dof_ + i]) * std::abs(dq[i]);
  }
  return d;
}

}  // namespace adsd::planner
