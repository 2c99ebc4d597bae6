#include "adsd/planner/arm_state_space.h"

#include <cmath>

#include <ompl/base/spaces/RealVectorStateSpace.h>

#include "adsd/error.h"

namespace adsd::planner {

namespace ob = ompl::base;

ArmStateSpace::ArmStateSpace(const ArmModel& model) {
  if (model.dof() == 0) throw InputError(model.sourceFile + ": the robot has no movable joint to plan for");
  setName("arm:" + model.name);
  for (std::size_t i = 0; i < model.dof(); ++i) {
    const ArmJoint& joint = model.joints[model.activeJoints[i]];
    ob::StateSpacePtr sub;
    if (joint.type == ArmJointType::continuous) {
      sub = std::make_shared<ob::SO2StateSpace>();
      continuous_.push_back(true);
    } else {
      auto real = std::make_shared<ob::RealVectorStateSpace>(1);
      real->setBounds(joint.lower, joint.upper);
      sub = real;
      continuous_.push_back(false);
    }
    sub->setName(joint.name);
    addSubspace(sub, 1.0);
  }
  lock();
}

void ArmStateSpace::toJoints(const ob::State* state, double* q) const {
  const auto* s = state->as<ob::CompoundState>();
  for (std::size_t i = 0; i < continuous_.size(); ++i) {
    q[i] = continuous_[i] ? s->as<ob::SO2StateSpace::StateType>(static_cast<unsigned>(i))->value
                          : s->as<ob::RealVectorStateSpace::StateType>(static_cast<unsigned>(i))->values[0];
  }
}

void ArmStateSpace::fromJoints(const double* q, ob::State* state) const {
  auto* s = state->as<ob::CompoundState>();
  for (std::size_t i = 0; i < continuous_.size(); ++i) {
    if (continuous_[i]) {
      auto* angle = s->as<ob::SO2StateSpace::StateType>(static_cast<unsigned>(i));
      angle->value = q[i];
      getSubspace(static_cast<unsigned>(i))->enforceBounds(angle);  // wraps into [-pi, pi)
    } else {
      s->as<ob::RealVectorStateSpace::StateType>(static_cast<unsigned>(i))->values[0] = q[i];
    }
  }
}

void ArmStateSpace::jointSteps(const ob::State* from, const ob::State* to, double* dq) const {
  const double pi = std::acos(-1.0);
  const auto* a = from->as<ob::CompoundState>();
  const auto* b = to->as<ob::CompoundState>();
  for (std::size_t i = 0; i < continuous_.size(); ++i) {
    const auto k = static_cast<unsigned>(i);
    if (continuous_[i]) {
      // SO2StateSpace::interpolate goes the shorter way: the difference wrapped into [-pi, pi].
      double d = b->as<ob::SO2StateSpace::StateType>(k)->value - a->as<ob::SO2StateSpace::StateType>(k)->value;
      if (d > pi) d -= 2.0 * pi;
      if (d < -pi) d += 2.0 * pi;
      dq[i] = d;
    } else {
      dq[i] = b->as<ob::RealVectorStateSpace::StateType>(k)->values[0] -
              a->as<ob::RealVectorStateSpace::StateType>(k)->values[0];
    }
  }
}

}  // namespace adsd::planner
