#include "adsd/planner/planning_problem.h"

#include <filesystem>
#include <sstream>

#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/samplers/BridgeTestValidStateSampler.h>
#include <ompl/base/samplers/GaussianValidStateSampler.h>
#include <ompl/base/samplers/MaximizeClearanceValidStateSampler.h>
#include <ompl/base/samplers/ObstacleBasedValidStateSampler.h>
#include <ompl/base/samplers/UniformValidStateSampler.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/base/spaces/SE3StateSpace.h>

#include "adsd/error.h"
#include "adsd/io/load_mesh.h"
#include "adsd/planner/features.h"
#include "adsd/planner/mesh_validity_checker.h"
#if ADSD_PLANNER_HAS_FCL
#include "adsd/planner/fcl_validity_checker.h"
#endif
#include "adsd/planner/rigid_body_clearance_objective.h"
#include "adsd/planner/state_pose.h"

namespace adsd::planner {

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace {

Mesh loadProblemMesh(const std::string& path, const SourceLocation& where) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    // The shipped problems reach the fetched real models through a `data` directory beside them
    // (cow_doorway.cfg's cow), which an install leaves for the user to link: the message says how.
    const std::filesystem::path missing(path);
    const std::string hint =
        missing.parent_path().filename() == "data"
            ? " (a shipped problem's real meshes are fetched by fetch_meshes.sh, in problems/data/ of the source or "
              "PREFIX/share/adsd/ of an install, into ~/.cache/adsd/meshes; link that directory as '" +
                  missing.parent_path().string() + "')"
            : "";
    throw InputError(where.describe() + ": mesh file '" + path + "' does not exist" + hint);
  }
  try {
    return io::loadMesh(path);
  } catch (const InputError& e) {
    throw InputError(where.describe() + ": " + e.what());
  }
}

std::shared_ptr<const RigidBodyScene> loadScene(const ProblemFile& file) {
  auto scene = std::make_shared<RigidBodyScene>();
  scene->space = file.space;
  scene->robot.push_back(recentreRobot(loadProblemMesh(file.robotPath, file.robotLocation), file.space));
  // One world file, many parts of about the robot's size: the broad phase then skips the parts far
  // from the robot, and none of them surrounds it.
  scene->environment = splitForRobot(loadProblemMesh(file.worldPath, file.worldLocation), scene->robot);
  return scene;
}

/// OMPL.app's `sampler` values.
ob::ValidStateSamplerAllocator samplerAllocator(const Setting& s) {
  if (s.value == "uniform") {
    return [](const ob::SpaceInformation* si) { return std::make_shared<ob::UniformValidStateSampler>(si); };
  }
  if (s.value == "gaussian") {
    return [](const ob::SpaceInformation* si) { return std::make_shared<ob::GaussianValidStateSampler>(si); };
  }
  if (s.value == "obstacle_based") {
    return [](const ob::SpaceInformation* si) { return std::make_shared<ob::ObstacleBasedValidStateSampler>(si); };
  }
  if (s.value == "max_clearance") {
    return [](const ob::SpaceInformation* si) { return std::make_shared<ob::MaximizeClearanceValidStateSampler>(si); };
  }
  if (s.value == "bridge_test") {
    return [](const ob::SpaceInformation* si) { return std::make_shared<ob::BridgeTestValidStateSampler>(si); };
  }
  throw InputError(s.location.describe() + ": unknown sampler '" + s.value +
                   "' (expected uniform, gaussian, obstacle_based, max_clearance or bridge_test)");
}

std::string describeOr(const ProblemFile* file, bool start) {
  if (file == nullptr) return start ? "start" : "goal";
  return (start ? file->start : file->goal).location.describe();
}

}  // namespace

PlanningProblem::PlanningProblem(const ProblemFile& file, const CheckingOptions& options)
    : scene_(loadScene(file)), options_(options), objective_(options.objective.value_or(file.objective)) {
  build(file.start.toPose(), file.goal.toPose(), file.volume, &file);
}

PlanningProblem::PlanningProblem(std::shared_ptr<const RigidBodyScene> scene, const Pose& start, const Pose& goal,
                                 const std::optional<Eigen::AlignedBox3d>& volume, const CheckingOptions& options,
                                 ObjectiveKind objective)
    : scene_(std::move(scene)), options_(options), objective_(options.objective.value_or(objective)) {
  if (!scene_) throw InputError("planning problem: no scene");
  build(start, goal, volume, nullptr);
}

void PlanningProblem::build(const Pose& start, const Pose& goal, const std::optional<Eigen::AlignedBox3d>& volume,
                            const ProblemFile* file) {
  const RigidBodySpace space = scene_->space;

  // Bounds: the file's volume, or the environment's box grown to contain start and goal
  // (OMPL.app's inference, shared/OMPLAPP-CFG.md).
  Eigen::AlignedBox3d box;
  if (volume) {
    box = *volume;
  } else {
    box = environmentBounds(*scene_);
    box.extend(start.translation());
    box.extend(goal.translation());
    // A flat environment (a wall, a floor) leaves an axis without extent; the robot may still
    // move along it by its own size.
    const double reach = std::max(robotRadius(*scene_), 1e-9);
    for (int i = 0; i < 3; ++i) {
      if (box.max()[i] - box.min()[i] <= 0.0) {
        box.min()[i] -= reach;
        box.max()[i] += reach;
      }
    }
  }
  const int dims = space == RigidBodySpace::se2 ? 2 : 3;
  ob::RealVectorBounds bounds(dims);
  for (int i = 0; i < dims; ++i) {
    bounds.setLow(i, box.min()[i]);
    bounds.setHigh(i, box.max()[i]);
  }
  ob::StateSpacePtr stateSpace;
  if (space == RigidBodySpace::se2) {
    auto se2 = std::make_shared<ob::SE2StateSpace>();
    se2->setBounds(bounds);
    stateSpace = se2;
  } else {
    auto se3 = std::make_shared<ob::SE3StateSpace>();
    se3->setBounds(bounds);
    stateSpace = se3;
  }
  setup_ = std::make_shared<og::SimpleSetup>(stateSpace);
  const ob::SpaceInformationPtr& si = setup_->getSpaceInformation();

  if (options_.checker == CheckerKind::fcl) {
#if ADSD_PLANNER_HAS_FCL
    checker_ = std::make_shared<FclValidityChecker>(si, scene_, options_.safetyMargin);
#else
    throw InputError("checker 'fcl': this build of adsd has no FCL (libfcl-dev was not found when it was configured)");
#endif
  } else {
    checker_ = std::make_shared<MeshValidityChecker>(si, scene_, options_.safetyMargin, options_.clearance);
  }
  setup_->setStateValidityChecker(checker_);
  if (options_.motion == MotionKind::certified) {
    certified_ = std::make_shared<CertifiedMotionValidator>(si, checker_);
    si->setMotionValidator(certified_);
  }

  if (file != nullptr) {
    for (const Setting& s : file->spaceParameters) {
      if (s.key == "sampler") {
        si->setValidStateSamplerAllocator(samplerAllocator(s));
      } else if (!si->params().hasParam(s.key)) {
        warnings_.push_back(s.location.describe() + ": not a parameter of the space information, ignored");
      } else if (!si->params().setParam(s.key, s.value)) {
        throw InputError(s.location.describe() + ": OMPL rejected the value '" + s.value + "'");
      }
    }
  }

  ob::OptimizationObjectivePtr objective;
  if (objective_ == ObjectiveKind::maxMinClearance) {
    objective = std::make_shared<RigidBodyClearanceObjective>(si);
  } else {
    objective = std::make_shared<ob::PathLengthOptimizationObjective>(si);
  }
  if (file != nullptr && file->objectiveThreshold) objective->setCostThreshold(ob::Cost(*file->objectiveThreshold));
  setup_->setOptimizationObjective(objective);

  ob::ScopedState<> startState(stateSpace), goalState(stateSpace);
  poseToState(start, space, startState.get());
  poseToState(goal, space, goalState.get());
  for (const bool isStart : {true, false}) {
    const ob::State* s = isStart ? startState.get() : goalState.get();
    const std::string which = isStart ? "the start state" : "the goal state";
    if (!si->satisfiesBounds(s)) {
      // Name the coordinate outside, its line and the bounds it is outside of.
      const Vec3 position = (isStart ? start : goal).translation();
      const ob::RealVectorBounds& bounds = positionBounds(*si, space);
      std::string where = describeOr(file, isStart);
      std::ostringstream why;
      for (std::size_t axis = 0; axis < bounds.low.size(); ++axis) {
        const double x = position[static_cast<Eigen::Index>(axis)];
        if (bounds.low[axis] <= x && x <= bounds.high[axis]) continue;
        if (file != nullptr) where = (isStart ? file->start : file->goal).positionLocations[axis].describe();
        why << " (" << "xyz"[axis] << " = " << x << ", the bounds [" << bounds.low[axis] << ", " << bounds.high[axis]
            << "])";
        break;
      }
      throw InputError(where + ": " + which + " is outside the bounds" + why.str());
    }
    if (!checker_->isValid(s)) {
      std::ostringstream why;
      why << describeOr(file, isStart) << ": " << which << " is in collision (clearance " << checker_->clearance(s)
          << ", safety margin " << options_.safetyMargin << ")";
      if (!options_.keepEndpointsInCollision) throw InputError(why.str());
      warnings_.push_back(why.str());
    } else if (certified_ != nullptr) {
      // Valid, but nearer the margin than distances are trusted (kDistanceTrustFraction): no
      // certified motion can leave or reach it, and the planner would only run out of time
      // without a word (an outside review: from starts within 1e-12 of the scene of a wall, none
      // of 38 motions away from it was certified).
      const double trusted = kDistanceTrustFraction * checker_->scale();
      const double clearance = checker_->clearance(s);
      if (clearance - options_.safetyMargin <= trusted) {
        std::ostringstream why;
        why << describeOr(file, isStart) << ": " << which << " is " << clearance - options_.safetyMargin
            << " from the safety margin, within the " << trusted
            << " that distances are trusted to (1e-10 of the scene): no certified motion can be proven to or from it";
        warnings_.push_back(why.str());
      }
    }
  }
  setup_->setStartAndGoalStates(startState, goalState, file != nullptr ? file->goalThreshold : 1e-6);
  checker_->resetCounts();
}

}  // namespace adsd::planner
