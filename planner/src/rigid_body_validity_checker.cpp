#include "adsd/planner/rigid_body_validity_checker.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "adsd/error.h"
#include "adsd/planner/state_pose.h"

namespace adsd::planner {

RigidBodyValidityChecker::RigidBodyValidityChecker(const ompl::base::SpaceInformationPtr& si,
                                                   std::shared_ptr<const RigidBodyScene> scene, double safetyMargin)
    : ompl::base::StateValidityChecker(si), scene_(std::move(scene)), safetyMargin_(safetyMargin) {
  if (!scene_ || scene_->robot.empty() || scene_->environment.empty()) {
    throw InputError("validity checker: the scene needs at least one robot mesh and one environment mesh");
  }
  if (!std::isfinite(safetyMargin_) || safetyMargin_ < 0.0) {
    throw InputError("validity checker: the safety margin must be finite and >= 0, got " +
                     std::to_string(safetyMargin_));
  }
  robotRadius_ = planner::robotRadius(*scene_);
  scale_ = sceneScale(*scene_);
  for (const Mesh& part : scene_->robot) {
    const Vec3 centre = part.bounds().center();
    double radius = 0.0;
    for (const TriangleIndices& t : part.triangles()) {
      for (std::uint32_t v : t) radius = std::max(radius, (part.vertices()[v] - centre).norm());
    }
    robotBallCentres_.push_back(centre);
    robotBoxes_.push_back(part.bounds());
    robotBallRadii_.push_back(radius);
  }
  for (const Mesh& part : scene_->environment) environmentBoxes_.push_back(part.bounds());
}

void RigidBodyValidityChecker::broadPhase(const Pose& robotPose, std::vector<PairBound>& pairs) const {
  pairs.clear();
  for (std::size_t r = 0; r < robotBallCentres_.size(); ++r) {
    const Vec3 centre = robotPose * robotBallCentres_[r];
    // World box around the posed body-frame box: centre moved, half extents through |R|.
    const Vec3 boxCentre = robotPose * robotBoxes_[r].center();
    const Vec3 boxHalf = robotPose.linear().cwiseAbs() * (0.5 * robotBoxes_[r].sizes());
    for (std::size_t e = 0; e < environmentBoxes_.size(); ++e) {
      // Both are distances between sets that contain the two meshes, so neither exceeds the
      // meshes' distance.
      const double ballBound = environmentBoxes_[e].exteriorDistance(centre) - robotBallRadii_[r];
      const Vec3 gap = ((environmentBoxes_[e].center() - boxCentre).cwiseAbs() - boxHalf -
                        0.5 * environmentBoxes_[e].sizes())
                           .cwiseMax(0.0);
      const double lower = std::max({0.0, ballBound, gap.norm()});
      pairs.push_back({lower, r, e});
    }
  }
  if (pairs.size() > 1) {
    std::sort(pairs.begin(), pairs.end(), [](const PairBound& a, const PairBound& b) { return a.lower < b.lower; });
  }
}

bool RigidBodyValidityChecker::separatedAbove(const Pose& robotPose, double margin) const {
  thread_local std::vector<PairBound> pairs;
  broadPhase(robotPose, pairs);
  for (const PairBound& pair : pairs) {
    if (pair.lower > margin) break;  // this pair and all after it are proven farther than the margin
    if (!pairSeparatedAbove(pair.robot, pair.environment, robotPose, margin)) return false;
  }
  return true;
}

double RigidBodyValidityChecker::distanceUpTo(const Pose& robotPose, double cap) const {
  thread_local std::vector<PairBound> pairs;
  broadPhase(robotPose, pairs);
  double best = cap;  // a lower bound on the distance, valid for every pair visited or skipped
  for (const PairBound& pair : pairs) {
    if (pair.lower >= best) break;  // cannot bring the minimum below `best`
    const PairDistance d = pairDistance(pair.robot, pair.environment, robotPose, best);
    if (!d.reachedCap) best = std::min(best, d.lower);
    if (best <= 0.0) break;  // in contact: nothing is nearer
  }
  return best;
}

bool RigidBodyValidityChecker::isValid(const ompl::base::State* state) const {
  ScopedQueryTimer timer(counters_, ScopedQueryTimer::Kind::validity);
  if (!si_->satisfiesBounds(state)) return false;
  return separatedAbove(poseFromState(state, scene_->space), safetyMargin_);
}

bool RigidBodyValidityChecker::isValid(const ompl::base::State* state, double& dist) const {
  ScopedQueryTimer timer(counters_, ScopedQueryTimer::Kind::clearance);
  dist = distanceUpTo(poseFromState(state, scene_->space), std::numeric_limits<double>::infinity());
  return si_->satisfiesBounds(state) && dist > safetyMargin_;
}

double RigidBodyValidityChecker::clearance(const ompl::base::State* state) const {
  ScopedQueryTimer timer(counters_, ScopedQueryTimer::Kind::clearance);
  return distanceUpTo(poseFromState(state, scene_->space), std::numeric_limits<double>::infinity());
}

double RigidBodyValidityChecker::clearanceUpTo(const ompl::base::State* state, double cap) const {
  ScopedQueryTimer timer(counters_, ScopedQueryTimer::Kind::clearance);
  return distanceUpTo(poseFromState(state, scene_->space), cap);
}

}  // namespace adsd::planner
