#include "adsd/planner/state_pose.h"

#include <cmath>
#include <limits>

#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/base/spaces/SE3StateSpace.h>

namespace adsd::planner {

namespace ob = ompl::base;

namespace {

Eigen::Quaterniond quaternionOf(const ob::SE3StateSpace::StateType& s) {
  const auto& r = s.rotation();
  return Eigen::Quaterniond(r.w, r.x, r.y, r.z);
}

}  // namespace

Pose poseFromState(const ob::State* state, RigidBodySpace space) {
  Pose pose = Pose::Identity();
  if (space == RigidBodySpace::se2) {
    const auto* s = state->as<ob::SE2StateSpace::StateType>();
    pose.translate(Vec3(s->getX(), s->getY(), 0.0));
    pose.rotate(Eigen::AngleAxisd(s->getYaw(), Vec3::UnitZ()));
  } else {
    const auto* s = state->as<ob::SE3StateSpace::StateType>();
    pose.translate(Vec3(s->getX(), s->getY(), s->getZ()));
    // OMPL keeps its quaternions normalized; normalizing again guards against drift in states a
    // user wrote by hand, so the pose stays a rigid motion. A quaternion of no length names no
    // rotation (Eigen would leave it be and answer the identity): the pose is then not finite,
    // which checkers take as invalid, at clearance 0, as they take a NaN.
    const Eigen::Quaterniond q = quaternionOf(*s);
    const double norm = q.norm();
    if (!(norm > 0.0) || !std::isfinite(norm)) {
      pose.matrix().setConstant(std::numeric_limits<double>::quiet_NaN());
      return pose;
    }
    pose.rotate(Eigen::Quaterniond(q.coeffs() / norm).toRotationMatrix());
  }
  return pose;
}

void poseToState(const Pose& pose, RigidBodySpace space, ob::State* state) {
  const Vec3 t = pose.translation();
  if (space == RigidBodySpace::se2) {
    auto* s = state->as<ob::SE2StateSpace::StateType>();
    const Eigen::Matrix3d r = pose.rotation();
    s->setXY(t.x(), t.y());
    s->setYaw(std::atan2(r(1, 0), r(0, 0)));
  } else {
    auto* s = state->as<ob::SE3StateSpace::StateType>();
    s->setXYZ(t.x(), t.y(), t.z());
    const Eigen::Quaterniond q(pose.rotation());
    auto& r = s->rotation();
    r.x = q.x();
    r.y = q.y();
    r.z = q.z();
    r.w = q.w();
  }
}

const ob::RealVectorBounds& positionBounds(const ob::SpaceInformation& si, RigidBodySpace space) {
  return space == RigidBodySpace::se2 ? si.getStateSpace()->as<ob::SE2StateSpace>()->getBounds()
                                      : si.getStateSpace()->as<ob::SE3StateSpace>()->getBounds();
}

double translationDistance(const ob::State* a, const ob::State* b, RigidBodySpace space) {
  return (poseFromState(a, space).translation() - poseFromState(b, space).translation()).norm();
}

double rotationAngle(const ob::State* a, const ob::State* b, RigidBodySpace space) {
  if (space == RigidBodySpace::se2) {
    const double yawA = a->as<ob::SE2StateSpace::StateType>()->getYaw();
    const double yawB = b->as<ob::SE2StateSpace::StateType>()->getYaw();
    // OMPL's SO2 interpolation turns the short way round: |difference| wrapped into [0, pi].
    double d = std::fabs(std::remainder(yawB - yawA, 2.0 * M_PI));
    return std::min(d, M_PI);
  }
  const Eigen::Quaterniond qa = quaternionOf(*a->as<ob::SE3StateSpace::StateType>()).normalized();
  const Eigen::Quaterniond qb = quaternionOf(*b->as<ob::SE3StateSpace::StateType>()).normalized();
  // angularDistance is the angle of qa^-1 qb on the short arc (q and -q are one rotation), the
  // arc OMPL's SO3 interpolation follows.
  return qa.angularDistance(qb);
}

}  // namespace adsd::planner
