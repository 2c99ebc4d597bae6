#include "adsd/planner/arm_kinematics.h"

#include <cassert>

namespace adsd::planner {

Pose jointMotion(const ArmJoint& joint, double q) {
  Pose motion = Pose::Identity();
  switch (joint.type) {
    case ArmJointType::revolute:
    case ArmJointType::continuous:
      motion.linear() = Eigen::AngleAxisd(q, joint.axis).toRotationMatrix();
      break;
    case ArmJointType::prismatic:
      motion.translation() = q * joint.axis;
      break;
    case ArmJointType::fixed:
      break;
  }
  return motion;
}

void forwardKinematics(const ArmModel& model, const double* q, std::vector<Pose>& linkPoses, const Pose& rootPose) {
  linkPoses.resize(model.links.size());
  linkPoses[0] = rootPose;
  // joints[k] carries links[k + 1], whose parent comes earlier (ArmModel's order).
  for (std::size_t k = 0; k < model.joints.size(); ++k) {
    const ArmJoint& joint = model.joints[k];
    assert(joint.parentLink < joint.childLink);
    const double position = ArmModel::jointPosition(joint, q);
    linkPoses[joint.childLink] = linkPoses[joint.parentLink] * joint.origin * jointMotion(joint, position);
  }
}

}  // namespace adsd::planner
