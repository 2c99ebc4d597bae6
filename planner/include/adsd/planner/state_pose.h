#pragma once
/// \file
/// \brief The OMPL boundary: SE(2)/SE(3) states to and from adsd::Pose (STYLE habit 9).

#include <ompl/base/SpaceInformation.h>
#include <ompl/base/State.h>
#include <ompl/base/StateSpace.h>
#include <ompl/base/spaces/RealVectorBounds.h>

#include "adsd/mesh.h"
#include "adsd/planner/rigid_body_scene.h"

namespace adsd::planner {

/// \brief The robot's pose for \p state: SE(3) is translation then the state's quaternion;
/// SE(2) is translation (x, y, 0) then a rotation by yaw about z. A quaternion of zero or
/// non-finite length gives a pose whose entries are NaN.
Pose poseFromState(const ompl::base::State* state, RigidBodySpace space);

/// \brief Writes \p pose into \p state. For SE(2) only x, y and the yaw about z are kept.
void poseToState(const Pose& pose, RigidBodySpace space, ompl::base::State* state);

/// \brief The position bounds (the volume) of \p si's rigid-body state space.
const ompl::base::RealVectorBounds& positionBounds(const ompl::base::SpaceInformation& si, RigidBodySpace space);

/// \brief Translation between two states (world frame length units).
double translationDistance(const ompl::base::State* a, const ompl::base::State* b, RigidBodySpace space);

/// \brief Angle (radians, in [0, pi]) of the rotation that OMPL's interpolation turns through
/// between \p a and \p b: |yaw difference| wrapped for SE(2); the shortest-arc quaternion angle
/// 2 acos|qa . qb| for SE(3) (OMPL's SO3 distance is half of that: not used here).
double rotationAngle(const ompl::base::State* a, const ompl::base::State* b, RigidBodySpace space);

}  // namespace adsd::planner
