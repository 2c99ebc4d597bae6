#include "adsd/planner/rigid_body_validity_checker.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/base/spaces/SE3StateSpace.h>

#include "adsd/error.h"
#include "adsd/tolerances.h"
#include "adsd/planner/state_pose.h"

namespace adsd::planner {

namespace {

/// Environment parts whose box bounds the broad phase works out together (count): a block's
/// bounds live on the stack, and a planning problem's parts (tens to a few hundred) fill a few.
constexpr std::size_t kBroadPhaseBlock = 64;

/// Whether the distance query takes \p pose: finite, and no translation beyond the coordinates it
/// accepts (adsd/tolerances.h). A state past them (x = 1e300 in bounds as wide) is invalid, at
/// clearance 0, instead of an exception thrown into the planner (an outside review).
bool queryablePose(const Pose& pose) {
  return pose.matrix().allFinite() && pose.translation().cwiseAbs().maxCoeff() <= tolerance::kMaxCoordinate;
}

}  // namespace

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
  // States are read as the scene's space says: an SE(3) scene over an SE(2) space read past each
  // state's memory, and an SE(2) scene over an SE(3) space ignored z (outside review).
  const ompl::base::StateSpace* space = si->getStateSpace().get();
  const bool planar = scene_->space == RigidBodySpace::se2;
  const bool matches = planar ? dynamic_cast<const ompl::base::SE2StateSpace*>(space) != nullptr
                              : dynamic_cast<const ompl::base::SE3StateSpace*>(space) != nullptr;
  if (!matches) {
    throw InputError(std::string("validity checker: the scene is ") + (planar ? "SE(2)" : "SE(3)") +
                     " but the space is '" + space->getName() + "', not an " +
                     (planar ? "SE2StateSpace" : "SE3StateSpace"));
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
  for (const Mesh& part : scene_->environment) {
    for (int k = 0; k < 3; ++k) {
      environmentCentres_[k].push_back(part.bounds().center()[k]);
      environmentHalves_[k].push_back(0.5 * part.bounds().sizes()[k]);
    }
  }
}

double RigidBodyValidityChecker::broadPhase(const Pose& robotPose, double limit, std::vector<PairBound>& pairs) const {
  pairs.clear();
  // Coordinates of size M carry errors of a few eps M into every bound below (the core's own
  // allowance, adsd/tolerances.h); a pair is skipped only when its bound exceeds the limit by more.
  const double slack = tolerance::kBoundSafetyUlps * tolerance::kEpsilon *
                       (scale_ + robotPose.translation().cwiseAbs().maxCoeff());
  const double reach = limit + slack;  // infinite for a clearance query without a cap
  const double reach2 = reach * reach;
  const std::size_t environmentParts = environmentCentres_[0].size();
  for (std::size_t r = 0; r < robotBallCentres_.size(); ++r) {
    const Vec3 ballCentre = robotPose * robotBallCentres_[r];
    // World box around the posed body-frame box: centre moved, half extents through |R|.
    const Vec3 boxCentre = robotPose * robotBoxes_[r].center();
    const Vec3 boxHalf = robotPose.linear().cwiseAbs() * (0.5 * robotBoxes_[r].sizes());
    const double radius = robotBallRadii_[r];
    const double ballReach2 = (reach + radius) * (reach + radius);
    // Both bounds are distances between sets that contain the two meshes, so neither exceeds the
    // meshes' distance; compared squared, so that the parts skipped (most of them) cost no root.
    // The box bound first, for a block of parts at a time in a loop without branches (which the
    // compiler vectorizes); the ball bound only for the parts it keeps.
    for (std::size_t first = 0; first < environmentParts; first += kBroadPhaseBlock) {
      const std::size_t count = std::min(kBroadPhaseBlock, environmentParts - first);
      double box2[kBroadPhaseBlock];
      for (std::size_t i = 0; i < count; ++i) box2[i] = 0.0;
      for (int k = 0; k < 3; ++k) {
        const double* centres = environmentCentres_[k].data() + first;
        const double* halves = environmentHalves_[k].data() + first;
        for (std::size_t i = 0; i < count; ++i) {
          const double gap = std::max(0.0, std::abs(centres[i] - boxCentre[k]) - halves[i] - boxHalf[k]);
          box2[i] += gap * gap;
        }
      }
      for (std::size_t i = 0; i < count; ++i) {
        if (box2[i] > reach2) continue;
        const std::size_t e = first + i;
        double ball2 = 0.0;
        for (int k = 0; k < 3; ++k) {
          const double gap = std::max(0.0, std::abs(environmentCentres_[k][e] - ballCentre[k]) - environmentHalves_[k][e]);
          ball2 += gap * gap;
        }
        if (ball2 > ballReach2) continue;
        pairs.push_back({std::max({0.0, std::sqrt(ball2) - radius, std::sqrt(box2[i])}), r, e});
      }
    }
  }
  return slack;
}

bool RigidBodyValidityChecker::separatedAbove(const Pose& robotPose, double margin) const {
  thread_local std::vector<PairBound> pairs;
  broadPhase(robotPose, margin, pairs);
  // Nearest first: when the robot collides, it is most likely with the nearest part. The broad
  // phase leaves few pairs (most checks: none or one), so sorting them costs little.
  if (pairs.size() > 1) {
    std::sort(pairs.begin(), pairs.end(), [](const PairBound& a, const PairBound& b) { return a.lower < b.lower; });
  }
  for (const PairBound& pair : pairs) {
    if (!pairSeparatedAbove(pair.robot, pair.environment, robotPose, margin)) return false;
  }
  return true;
}

double RigidBodyValidityChecker::distanceUpTo(const Pose& robotPose, double cap) const {
  // Nothing asked for: 0 is a lower bound of every distance. (A cap of 0 reached the distance
  // query as a cap, which it refuses: an InputError thrown into the caller for every state whose
  // broad phase kept a pair, an outside review.)
  if (!(cap > 0.0)) return 0.0;
  thread_local std::vector<PairBound> pairs;
  const double slack = broadPhase(robotPose, cap, pairs);
  // Nearest first, from a heap: the bound usually passes the remaining pairs' bounds after a few.
  const auto fartherFirst = [](const PairBound& a, const PairBound& b) { return a.lower > b.lower; };
  std::make_heap(pairs.begin(), pairs.end(), fartherFirst);
  double best = cap;  // a lower bound on the distance, valid for every pair visited or skipped
  while (!pairs.empty()) {
    std::pop_heap(pairs.begin(), pairs.end(), fartherFirst);
    const PairBound pair = pairs.back();
    pairs.pop_back();
    if (pair.lower > best + slack) break;  // this pair and all left are proven no nearer than `best`
    const PairDistance d = pairDistance(pair.robot, pair.environment, robotPose, best);
    if (!d.reachedCap) best = std::min(best, d.lower);
    if (best <= 0.0) break;  // in contact: nothing is nearer
  }
  return best;
}

bool RigidBodyValidityChecker::isValid(const ompl::base::State* state) const {
  ScopedQueryTimer timer(counters_, ScopedQueryTimer::Kind::validity);
  if (!si_->satisfiesBounds(state)) return false;
  const Pose pose = poseFromState(state, scene_->space);
  return queryablePose(pose) && separatedAbove(pose, safetyMargin_);
}

bool RigidBodyValidityChecker::isValid(const ompl::base::State* state, double& dist) const {
  ScopedQueryTimer timer(counters_, ScopedQueryTimer::Kind::clearance);
  dist = clearanceOf(state, std::numeric_limits<double>::infinity());
  if (!si_->satisfiesBounds(state)) return false;
  if (dist > safetyMargin_) return true;
  // An exact clearance at or below the margin decides. A lower bound (a tolerance's interval, a
  // cap) may lie there for a state clear of the margin, which isValid(state) calls valid: the
  // threshold query decides then, so that both calls agree (an outside review: with a tolerance of
  // 1e-3 + 1 %, 890 of 2000 states near the office's walls were valid to one and not the other).
  if (specs_.clearanceComputationType == ompl::base::StateValidityCheckerSpecs::EXACT) return false;
  const Pose pose = poseFromState(state, scene_->space);
  return queryablePose(pose) && separatedAbove(pose, safetyMargin_);
}

double RigidBodyValidityChecker::clearance(const ompl::base::State* state) const {
  ScopedQueryTimer timer(counters_, ScopedQueryTimer::Kind::clearance);
  return clearanceOf(state, std::numeric_limits<double>::infinity());
}

double RigidBodyValidityChecker::clearanceUpTo(const ompl::base::State* state, double cap) const {
  if (!(cap >= 0.0)) {
    throw InputError("clearanceUpTo: the cap must be >= 0 (infinity for none), got " + std::to_string(cap));
  }
  ScopedQueryTimer timer(counters_, ScopedQueryTimer::Kind::clearance);
  return clearanceOf(state, cap);
}

double RigidBodyValidityChecker::clearanceOf(const ompl::base::State* state, double cap) const {
  // A NaN position passes OMPL's bounds test (its comparisons are false), and the distance query
  // refuses the pose it makes with an exception thrown into the planner: such a state is invalid,
  // at clearance 0, as one with a NaN yaw already was (SO(2)'s bounds test fails for it).
  const Pose pose = poseFromState(state, scene_->space);
  if (!queryablePose(pose)) return 0.0;
  return distanceUpTo(pose, cap);
}

}  // namespace adsd::planner
