#include "adsd/planner/arm_planning_problem.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <filesystem>
#include <functional>
#include <limits>
#include <map>
#include <sstream>

#include <ompl/base/goals/GoalState.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>

#include "adsd/error.h"
#include "adsd/planner/arm_state_space.h"
#include "adsd/planner/arm_validity_checker.h"
#include "adsd/planner/features.h"
#include "adsd/planner/motion_plan_request_yaml.h"
#include "adsd/planner/planning_scene_yaml.h"
#include "adsd/planner/srdf_groups.h"
#if ADSD_PLANNER_HAS_FCL
#include "adsd/planner/fcl_arm_validity_checker.h"
#endif
#include "input_file.h"

namespace adsd::planner {

namespace ob = ompl::base;
namespace og = ompl::geometric;

bool isArmProblemFile(const std::string& path) {
  // A file it cannot read (missing, or a device such as /dev/zero, one line without end) is no arm
  // problem: the rigid-body reader then refuses it by name.
  std::string text;
  try {
    text = readInputFile(path, "problem file");  // whole, its byte-order mark dropped
  } catch (const InputError&) {
    return false;
  }
  takeLoneCarriageReturnsAsLineEnds(text);
  std::istringstream in(text);
  std::string line, section;
  while (std::getline(in, line)) {
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#' || line[first] == ';') continue;
    const std::string s = line.substr(first);
    if (s[0] == '[') {
      const auto close = s.find(']');
      section = s.substr(1, close == std::string::npos ? std::string::npos : close - 1);
      continue;
    }
    const auto eq = s.find('=');
    if (section != "problem" || eq == std::string::npos) continue;
    std::string key = s.substr(0, eq);
    key.erase(key.find_last_not_of(" \t") + 1);
    // `request`, or what only an arm problem has (an OMPL.app cfg names its obstacles `world`):
    // an arm cfg without its request line was read as a rigid one, and refused for a missing
    // `start.x` (an outside review), where the arm reader names the missing `request`.
    if (key == "request" || key == "scene" || key == "srdf" || key == "package_path") return true;
    if (key == "robot") {
      std::string value = s.substr(eq + 1);
      value.erase(value.find_last_not_of(" \t\r") + 1);
      std::transform(value.begin(), value.end(), value.begin(), [](unsigned char c) { return std::tolower(c); });
      if (value.size() >= 5 && value.compare(value.size() - 5, 5, ".urdf") == 0) return true;
    }
  }
  return false;
}

namespace {

/// "FILE:LINE" of \p line in \p file (just FILE when the line is unknown).
std::string at(const std::string& file, int line) {
  return line > 0 ? file + ":" + std::to_string(line) : file;
}

/// The smallest line of the map's values (the first joint as written), 0 when empty.
template <class Map, class LineOf>
int firstLine(const Map& map, LineOf lineOf) {
  int best = 0;
  for (const auto& entry : map) {
    const int line = lineOf(entry.second);
    if (line > 0 && (best == 0 || line < best)) best = line;
  }
  return best;
}

/// Throws when a non-continuous joint of \p q lies outside its limits.
/// Throws when a coordinate of \p q lies outside its joint's limits, the message beginning with
/// whereOf(that joint's name): the line that gives its position.
void checkLimits(const ArmModel& model, const std::vector<double>& q,
                 const std::function<std::string(const std::string&)>& whereOf, const char* which) {
  for (std::size_t i = 0; i < model.dof(); ++i) {
    const ArmJoint& joint = model.joints[model.activeJoints[i]];
    if (joint.type == ArmJointType::continuous) continue;  // wraps: every angle is a position
    if (q[i] < joint.lower || q[i] > joint.upper) {
      // The shortest text of each double that reads back as it: at 6 digits a value one ulp
      // outside read as its limit.
      const auto text = [](double x) {
        char digits[32];
        return std::string(digits, std::to_chars(digits, digits + sizeof digits, x).ptr);
      };
      std::ostringstream why;
      why << whereOf(joint.name) << ": " << which << " is outside the joint limits (joint " << joint.name << " = " << text(q[i])
          << ", limits [" << text(joint.lower) << ", " << text(joint.upper) << "])";
      throw InputError(why.str());
    }
  }
}

/// A file the cfg names must exist: otherwise the error names the cfg's line (the reader's own
/// message would name only the missing file).
void requireFile(const std::string& path, const SourceLocation& where, const char* what) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw InputError(where.describe() + ": " + what + " '" + path + "' is a directory");
  }
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec)) {
    throw InputError(where.describe() + ": " + what + " '" + path + "' is a device, a pipe or a socket, not a file");
  }
  if (!std::filesystem::is_regular_file(path, ec)) {
    // A file under the robots' cache is one the shipped problems expect fetch_robots.sh to have
    // fetched: the message says where that script is.
    const std::string robots = defaultRobotsDirectory() + "/";
    const std::string hint = path.compare(0, robots.size(), robots) == 0
                                 ? " (the shipped arm problems' robots are fetched by fetch_robots.sh: problems/data/ "
                                   "of the source, PREFIX/share/adsd/ of an install)"
                                 : "";
    throw InputError(where.describe() + ": " + what + " '" + path + "' does not exist" + hint);
  }
}

}  // namespace

ArmPlanningProblem::ArmPlanningProblem(const MotionBenchMakerProblem& file, const CheckingOptions& options)
    : name_(file.name), options_(options), objective_(options.objective.value_or(ObjectiveKind::length)) {
  warnings_ = file.warnings;
  requireFile(file.robotPath, file.robotLocation, "URDF file");
  if (file.srdfPath) requireFile(*file.srdfPath, file.srdfLocation, "SRDF file");
  requireFile(file.scenePath, file.sceneLocation, "scene file");
  requireFile(file.requestPath, file.requestLocation, "request file");
  auto model = std::make_shared<ArmModel>(readUrdf(file.robotPath, file.packagePath));
  model_ = model;
  // A URDF with <visual> geometry only (dart-doc's test robots, a description stripped for a
  // viewer) plans as if nothing could collide; say so rather than report a path that is
  // "collision-free" by default.
  const auto hasCollision = [](const ArmLink& l) { return l.collision.has_value(); };
  if (std::none_of(model_->links.begin(), model_->links.end(), hasCollision)) {
    warnings_.push_back(file.robotPath + ": robot '" + model_->name +
                        "' has no <collision> geometry on any link (its <visual> geometry is not checked, as in "
                        "MoveIt): no state is in collision");
  }
  // A mimic joint follows its leader past its own limits, as in MoveIt (which checks the limits of
  // the joints it plans for only): said, since the robot's description then disagrees with itself.
  for (const ArmJoint& j : model_->joints) {
    if (j.mimicCoordinate < 0 || j.type == ArmJointType::continuous) continue;
    const auto [low, high] = model_->positionRange(j);
    if (low < j.lower || high > j.upper) {
      std::ostringstream why;
      why << file.robotPath << ": joint '" << j.name << "' mimics joint '" << j.mimics << "' and reaches [" << low
          << ", " << high << "] over that joint's limits, beyond its own [" << j.lower << ", " << j.upper
          << "] (it follows its leader there, as in MoveIt)";
      warnings_.push_back(why.str());
    }
  }
  const PlanningSceneYaml sceneFile = readPlanningSceneYaml(file.scenePath);
  warnings_.insert(warnings_.end(), sceneFile.warnings.begin(), sceneFile.warnings.end());
  const MotionPlanRequestYaml request = readMotionPlanRequestYaml(file.requestPath);
  allowedPlanningTime_ = request.allowedPlanningTime;
  scene_ = std::make_shared<const ArmScene>(
      makeArmScene(model_, sceneFile.objects, file.srdfPath.value_or(""), sceneFile.primitives));
  warnings_.insert(warnings_.end(), scene_->warnings.begin(), scene_->warnings.end());

  // The joint vectors, in the model's order.
  std::size_t dof = model_->dof();  // fewer once the planning group is known
  start_.assign(dof, 0.0);
  goal_.assign(dof, 0.0);
  // A joint neither the request's start_state nor the scene's robot_state gives starts where
  // MoveIt's default state puts it: 0 where its limits allow, else their midpoint (a
  // MotionPlanRequest's start is a difference from that state, and hand-written ones list only the
  // group's joints: Atlas's 27 joints all had to be written into the scene, an outside review).
  // Unless the start names a joint the robot lacks: a misspelling, refused at its line.
  std::string unknown;
  int unknownLine = 0;
  for (const auto& [given, position] : request.start) {
    const std::string& name = given;  // a structured binding: clang 14 captures none
    const auto named = [&name](const ArmJoint& j) { return j.name == name; };
    if (std::any_of(model_->joints.begin(), model_->joints.end(), named)) continue;
    unknown += (unknown.empty() ? "'" : ", '") + given + "'";
    if (const auto l = request.startLines.find(given); l != request.startLines.end() && unknownLine == 0) {
      unknownLine = l->second;
    }
  }
  std::string defaulted;
  for (std::size_t i = 0; i < dof; ++i) {
    const ArmJoint& joint = model_->joints[model_->activeJoints[i]];
    if (const auto s = request.start.find(joint.name); s != request.start.end()) {
      start_[i] = s->second;
    } else if (const auto d = sceneFile.defaultJointValues.find(joint.name); d != sceneFile.defaultJointValues.end()) {
      start_[i] = d->second;
    } else if (!unknown.empty()) {
      throw InputError(at(file.requestPath, unknownLine) + ": the start state has no position for joint '" +
                       joint.name + "' of robot '" + model_->name + "' (neither the request's start_state nor the " +
                       "scene's robot_state gives one; the start_state names " + unknown + ", which the robot lacks)");
    } else {
      start_[i] = defaultPosition(joint);
      std::ostringstream value;
      value << start_[i];
      defaulted += (defaulted.empty() ? "" : ", ") + joint.name + " = " + value.str();
    }
  }
  if (!defaulted.empty()) {
    warnings_.push_back(at(file.requestPath, firstLine(request.startLines, [](int l) { return l; })) +
                        ": the start_state and the scene's robot_state leave out joints, started at MoveIt's "
                        "default (0 where the limits allow, else their midpoint): " + defaulted);
  }
  // The planning group, request.groupName: as the SRDF defines it, or else the joints the goal
  // constrains (MotionBenchMaker's requests name every joint of the group). The robot's other
  // joints are held at the start state, as MoveIt plans: planning every joint, a humanoid's request
  // for one arm moved its legs, its torso and its other arm too (Atlas: 27 joints for 2).
  std::vector<std::string> planned;
  bool fromSrdf = false;
  if (file.srdfPath) {
    if (std::optional<std::vector<std::string>> group = srdfGroupJoints(*model, *file.srdfPath, request.groupName)) {
      planned = std::move(*group);
      fromSrdf = true;
    }
  }
  if (!fromSrdf) {
    for (const auto& [joint, constraint] : request.goal) planned.push_back(joint);
  }
  std::size_t plannedCoordinates = 0;
  for (std::size_t i = 0; i < dof; ++i) {
    const std::string& name = model->joints[model->activeJoints[i]].name;
    if (std::find(planned.begin(), planned.end(), name) != planned.end()) ++plannedCoordinates;
  }
  if (plannedCoordinates > 0 && plannedCoordinates < dof) {
    // A held joint stands where the start state puts it, limits or not: they bound the planned
    // joints (checkLimits, below). One outside them was taken in silence (an outside review).
    for (std::size_t i = 0; i < dof; ++i) {
      const ArmJoint& joint = model->joints[model->activeJoints[i]];
      if (std::find(planned.begin(), planned.end(), joint.name) != planned.end()) continue;
      if (joint.type == ArmJointType::continuous || (joint.lower <= start_[i] && start_[i] <= joint.upper)) continue;
      const auto line = request.startLines.find(joint.name);
      std::ostringstream why;
      why << (line != request.startLines.end() ? at(file.requestPath, line->second) : file.scenePath) << ": joint '"
          << joint.name << "', held outside planning group '" << request.groupName << "', stands at " << start_[i]
          << ", outside its limits [" << joint.lower << ", " << joint.upper << "]: held there as given";
      warnings_.push_back(why.str());
    }
    std::map<std::string, double> startOf;
    for (std::size_t i = 0; i < dof; ++i) startOf[model->joints[model->activeJoints[i]].name] = start_[i];
    holdJointsOutside(*model, planned, start_);
    start_.clear();
    for (const std::size_t j : model->activeJoints) start_.push_back(startOf.at(model->joints[j].name));
    if (!fromSrdf) {
      const int line = firstLine(request.goal, [](const JointGoal& g) { return g.line; });
      warnings_.push_back(at(file.requestPath, line) + ": group '" + request.groupName +
                          "' is defined by no SRDF: planning the " + std::to_string(plannedCoordinates) +
                          " joints the goal constrains, the robot's other " + std::to_string(dof - plannedCoordinates) +
                          " held at the start state");
    }
    dof = model_->dof();
    goal_.assign(dof, 0.0);
  }
  // A mimic joint follows its leader, as in MoveIt, and a locked joint (equal limits) stands at its
  // limit: a start position given for either is not used, and one that disagrees is said to be
  // replaced.
  const auto dependentJoint = [&](const std::string& name) -> const ArmJoint* {
    for (const ArmJoint& j : model_->joints) {
      if (j.name == name && (j.mimicCoordinate >= 0 || j.locked)) return &j;
    }
    return nullptr;
  };
  // Why a joint that is no coordinate stands where it does: its equal limits, the start state
  // outside the group, or its leader, which may itself be held there.
  const std::string held = "the start state, outside planning group '" + request.groupName + "'";
  const auto standsBy = [&](const ArmJoint& j) {
    if (j.mimics.empty()) return j.lower == j.upper ? std::string("its limits, which are equal") : held;
    const std::string follows = "joint '" + j.mimics + "', which it mimics";
    if (!j.locked) return follows;
    const auto leader = std::find_if(model_->joints.begin(), model_->joints.end(),
                                     [&j](const ArmJoint& l) { return l.name == j.mimics; });
    const bool leaderHeld = leader != model_->joints.end() && leader->lower != leader->upper;
    return leaderHeld ? follows + ", held at " + held : "joint '" + j.mimics + "', which is locked";
  };
  for (const auto& [joint, value] : request.start) {
    bool known = false;
    for (std::size_t i = 0; i < dof && !known; ++i) known = model_->joints[model_->activeJoints[i]].name == joint;
    if (const ArmJoint* dependent = dependentJoint(joint)) {
      const double position = ArmModel::jointPosition(*dependent, start_.data());
      if (std::abs(position - value) > kArmGoalThresholdFloor) {
        const auto line = request.startLines.find(joint);
        std::ostringstream why;
        why << at(file.requestPath, line != request.startLines.end() ? line->second : 0) << ": start joint '" << joint
            << "' stands at " << position << " by " << standsBy(*dependent) << ", not at " << value << " as given";
        warnings_.push_back(why.str());
      }
    } else if (!known) {
      const auto line = request.startLines.find(joint);
      warnings_.push_back(at(file.requestPath, line != request.startLines.end() ? line->second : 0) +
                          ": start joint '" + joint + "' is not a movable joint of robot '" + model_->name +
                          "', ignored");
    }
  }
  goal_ = start_;
  double smallestTolerance = std::numeric_limits<double>::infinity();
  for (const auto& [joint, constraint] : request.goal) {
    std::size_t index = dof;
    for (std::size_t i = 0; i < dof; ++i) {
      if (model_->joints[model_->activeJoints[i]].name == joint) index = i;
    }
    if (const ArmJoint* dependent = dependentJoint(joint); index == dof && dependent) {
      if (dependent->mimicCoordinate >= 0) {
        throw InputError(at(file.requestPath, constraint.line) + ": goal joint '" + joint + "' mimics joint '" +
                         dependent->mimics + "' of robot '" + model_->name + "': constrain the joint it follows");
      }
      // A locked joint: the goal may name it where it stands.
      if (constraint.position - constraint.toleranceBelow <= dependent->lockedPosition &&
          dependent->lockedPosition <= constraint.position + constraint.toleranceAbove) {
        continue;
      }
      std::ostringstream why;
      why << at(file.requestPath, constraint.line) << ": goal joint '" << joint << "' stands at "
          << dependent->lockedPosition << " by " << standsBy(*dependent) << ": the goal's " << constraint.position
          << " cannot be reached";
      throw InputError(why.str());
    }
    if (index == dof) {
      throw InputError(at(file.requestPath, constraint.line) + ": goal joint '" + joint +
                       "' is not a movable joint of robot '" + model_->name + "'");
    }
    goal_[index] = constraint.position;
    // MoveIt samples a joint goal within its tolerance and the joint's limits: a position just
    // outside a limit (a value rounded on its way into the request) is reached at the limit when
    // the tolerance reaches it (an outside review: 0.0002 beyond, tolerance 0.001, refused).
    const ArmJoint& moved = model_->joints[model_->activeJoints[index]];
    if (moved.type != ArmJointType::continuous) {
      const double limit = std::clamp(constraint.position, moved.lower, moved.upper);
      if (limit != constraint.position && constraint.position - constraint.toleranceBelow <= limit &&
          limit <= constraint.position + constraint.toleranceAbove) {
        goal_[index] = limit;
        std::ostringstream why;
        why << at(file.requestPath, constraint.line) << ": goal joint '" << joint << "' at "
            << constraint.position << " lies outside its limits [" << moved.lower << ", " << moved.upper
            << "], within its tolerance of " << limit << ": the goal is taken there";
        warnings_.push_back(why.str());
      }
    }
    smallestTolerance = std::min({smallestTolerance, constraint.toleranceAbove, constraint.toleranceBelow});
  }
  goalThreshold_ = std::max(smallestTolerance, kArmGoalThresholdFloor);

  auto space = std::make_shared<ArmStateSpace>(*model_);
  setup_ = std::make_shared<og::SimpleSetup>(space);
  const ob::SpaceInformationPtr& si = setup_->getSpaceInformation();
  if (options_.checker == CheckerKind::fcl) {
#if ADSD_PLANNER_HAS_FCL
    checker_ = std::make_shared<FclArmValidityChecker>(si, *scene_, options_.safetyMargin);
#else
    throw InputError("checker 'fcl': this build of adsd has no FCL (libfcl-dev was not found when it was configured)");
#endif
  } else {
    checker_ = std::make_shared<ArmValidityChecker>(si, *scene_, options_.safetyMargin, options_.clearance);
  }
  setup_->setStateValidityChecker(checker_);
  if (options_.motion == MotionKind::certified) {
    certified_ = std::make_shared<ArmMotionValidator>(si, checker_);
    si->setMotionValidator(certified_);
  }
  if (objective_ == ObjectiveKind::maxMinClearance) {
    // The certified smallest clearance to the obstacles along each motion (arm_clearance_objective.h).
    objectiveClearance_ = std::make_shared<const ArmMotionClearance>(checker_, ArmClearanceScope::obstacles);
    setup_->setOptimizationObjective(std::make_shared<ArmClearanceObjective>(si, objectiveClearance_));
  } else {
    setup_->setOptimizationObjective(std::make_shared<ob::PathLengthOptimizationObjective>(si));
  }

  // Start and goal: within the limits and valid, or an error naming the request's first joint line.
  const std::string startAt =
      at(file.requestPath, firstLine(request.startLines, [](int line) { return line; }));
  const std::string goalAt =
      at(file.requestPath, firstLine(request.goal, [](const JointGoal& g) { return g.line; }));
  ob::ScopedState<> startState(space), goalState(space);
  space->fromJoints(start_.data(), startState.get());
  space->fromJoints(goal_.data(), goalState.get());
  for (const bool isStart : {true, false}) {
    const std::string& where = isStart ? startAt : goalAt;
    const char* which = isStart ? "the start state" : "the goal state";
    // Named at the line of the joint outside its limits (it was the first joint's line).
    const auto whereOf = [&](const std::string& joint) {
      if (isStart) {
        const auto line = request.startLines.find(joint);
        return line != request.startLines.end() ? at(file.requestPath, line->second) : startAt;
      }
      const auto goal = request.goal.find(joint);
      return goal != request.goal.end() ? at(file.requestPath, goal->second.line) : goalAt;
    };
    checkLimits(*model_, isStart ? start_ : goal_, whereOf, which);
    const ob::State* s = isStart ? startState.get() : goalState.get();
    if (!checker_->isValid(s)) {
      std::ostringstream why;
      why << where << ": " << which << " is in collision (clearance " << checker_->clearance(s) << ", safety margin "
          << options_.safetyMargin << ")";
      // Which pairs: with a robot new to the program, often two links that touch in the URDF's
      // own pose, which an SRDF's <disable_collisions> (the cfg's srdf key) leaves unchecked.
      const std::vector<std::string> pairs = checker_->pairsInContact(s);
      bool selfContact = false;
      for (std::size_t k = 0; k < pairs.size(); ++k) {
        why << (k == 0 ? ": " : ", ") << pairs[k];
        selfContact = selfContact || pairs[k].rfind("links ", 0) == 0;
      }
      if (selfContact) why << " (an SRDF's <disable_collisions> leaves a pair of links unchecked)";
      if (!options_.keepEndpointsInCollision) throw InputError(why.str());
      warnings_.push_back(why.str());
    }
  }
  setup_->setStartState(startState);
  auto goal = std::make_shared<ob::GoalState>(si);
  goal->setState(goalState);
  goal->setThreshold(goalThreshold_);
  setup_->setGoal(goal);
  checker_->resetCounts();
}

}  // namespace adsd::planner
