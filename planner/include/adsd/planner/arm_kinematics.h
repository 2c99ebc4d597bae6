#pragma once
/// \file
/// \brief Forward kinematics of an ArmModel: a joint vector to the world pose of every link.

#include <vector>

#include "adsd/planner/arm_model.h"

namespace adsd::planner {

/// \brief The motion of one joint at position \p q: a turn of q radians about the joint's axis
/// (revolute, continuous), a move of q metres along it (prismatic), the identity (fixed). Maps
/// child-link coordinates to joint-frame coordinates.
Pose jointMotion(const ArmJoint& joint, double q);

/// \brief World pose of every link for the joint vector \p q (model.dof() values, in the model's
/// joint order), with the root link at \p rootPose (default: the root's frame is the world frame):
///   linkPoses[child] = linkPoses[parent] * joint.origin * jointMotion(joint, position),
/// with each joint's position from ArmModel::jointPosition (a mimic joint follows its leader).
/// \p linkPoses is resized to model.links.size(); once it has that size a call allocates nothing,
/// so a caller (or a thread_local) keeps it between calls. Links come parents first, so one pass
/// over the joints suffices.
void forwardKinematics(const ArmModel& model, const double* q, std::vector<Pose>& linkPoses,
                       const Pose& rootPose = Pose::Identity());

}  // namespace adsd::planner
