#include "adsd/planner/arm_state_space.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <ompl/base/ProjectionEvaluator.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>

#include "adsd/error.h"

namespace adsd::planner {

namespace ob = ompl::base;

namespace {

/// A continuous joint's angle: OMPL's SO(2), whose interpolation can land on +pi exactly (the
/// shorter arc wrapped by comparison, not by remainder), an angle its own bounds test refuses
/// ([-pi, pi)). Every checker asks that test first, so the state halfway between 3 and -3 was
/// invalid and the straight motion through it refused (an outside review). The angle is wrapped
/// into [-pi, pi) after interpolation, the same angle.
class ContinuousJointSpace : public ob::SO2StateSpace {
 public:
  void interpolate(const ob::State* from, const ob::State* to, double t, ob::State* state) const override {
    ob::SO2StateSpace::interpolate(from, to, t, state);
    enforceBounds(state);
  }
};

/// The first few coordinates of an arm's joint vector, as they are (a continuous joint's angle in
/// [-pi, pi)).
class LeadingJointsProjection : public ob::ProjectionEvaluator {
 public:
  LeadingJointsProjection(const ArmStateSpace* space, std::size_t count)
      : ob::ProjectionEvaluator(space), arm_(space), count_(count) {}

  unsigned int getDimension() const override { return static_cast<unsigned int>(count_); }

  void defaultCellSizes() override {
    // OMPL's own choice for a bounded real vector: a twentieth of each coordinate's range.
    cellSizes_.resize(count_);
    for (std::size_t i = 0; i < count_; ++i) {
      cellSizes_[i] = arm_->getSubspace(static_cast<unsigned>(i))->getMaximumExtent() / 20.0;
      if (!(cellSizes_[i] > 0.0)) cellSizes_[i] = 1.0;  // a locked joint: one cell
    }
  }

  void project(const ob::State* state, Eigen::Ref<Eigen::VectorXd> projection) const override {
    for (std::size_t i = 0; i < count_; ++i) projection(static_cast<Eigen::Index>(i)) = arm_->coordinate(state, i);
  }

 private:
  const ArmStateSpace* arm_;
  std::size_t count_;
};

}  // namespace

ArmStateSpace::ArmStateSpace(const ArmModel& model) {
  if (model.dof() == 0) throw InputError(model.sourceFile + ": the robot has no movable joint to plan for");
  setName("arm:" + model.name);
  for (std::size_t i = 0; i < model.dof(); ++i) {
    const ArmJoint& joint = model.joints[model.activeJoints[i]];
    ob::StateSpacePtr sub;
    if (joint.type == ArmJointType::continuous) {
      sub = std::make_shared<ContinuousJointSpace>();
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

double ArmStateSpace::coordinate(const ob::State* state, std::size_t i) const {
  const auto* s = state->as<ob::CompoundState>();
  return continuous_[i] ? s->as<ob::SO2StateSpace::StateType>(static_cast<unsigned>(i))->value
                        : s->as<ob::RealVectorStateSpace::StateType>(static_cast<unsigned>(i))->values[0];
}

void ArmStateSpace::toJoints(const ob::State* state, double* q) const {
  for (std::size_t i = 0; i < continuous_.size(); ++i) q[i] = coordinate(state, i);
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

void ArmStateSpace::registerProjections() {
  registerDefaultProjection(
      std::make_shared<LeadingJointsProjection>(this, std::min<std::size_t>(kProjectedJoints, dof())));
}

}  // namespace adsd::planner
