#include "arm_viewer_html.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include <ompl/base/ScopedState.h>

#include "adsd/error.h"
#include "adsd/planner/arm_kinematics.h"
#include "adsd/planner/arm_state_space.h"
#include "arm_path_samples.h"

namespace adsd::app {

namespace {

using planner::ArmModel;
using planner::ArmValidityCheckerBase;

/// Each body's world pose (bodies are the checker's link bodies) for the joint vector \p q.
std::vector<Pose> bodyPoses(const ArmValidityCheckerBase& checker, const std::vector<double>& q,
                            std::vector<Pose>& linkPoses) {
  planner::forwardKinematics(checker.model(), q.data(), linkPoses);
  std::vector<Pose> poses;
  for (std::size_t b = 0; b < checker.linkBodies(); ++b) poses.push_back(linkPoses[checker.linkOfBody(b)]);
  return poses;
}

/// An arm's base joint: the robot's movable joint that carries every other one, and per joint
/// whether it is carried (the base itself included).
struct BaseJoint {
  std::size_t joint;
  std::vector<bool> carried;
};

/// The robot's base joint, if it has one. All of the description's movable joints count, not only
/// those planned: one arm of a humanoid has such a joint, the humanoid has none. Linear in the
/// joints: each joint's answer is found once, by a path up that stops at a joint already answered
/// (a URDF may hold a chain of thousands of joints).
std::optional<BaseJoint> baseJoint(const ArmModel& model) {
  const std::size_t count = model.joints.size();
  const auto movable = [&](std::size_t j) { return model.joints[j].type != planner::ArmJointType::fixed; };
  const auto parentOf = [&](std::size_t j) { return model.links[model.joints[j].parentLink].parentJoint; };
  // The only candidate: the topmost movable joint above (or at) any one movable joint.
  std::optional<std::size_t> base;
  for (std::size_t j = 0; j < count && !base; ++j) {
    if (!movable(j)) continue;
    for (int k = static_cast<int>(j); k >= 0; k = parentOf(static_cast<std::size_t>(k))) {
      if (movable(static_cast<std::size_t>(k))) base = static_cast<std::size_t>(k);
    }
  }
  if (!base) return std::nullopt;
  enum class Answer : std::uint8_t { unknown, carried, notCarried };
  std::vector<Answer> answers(count, Answer::unknown);
  answers[*base] = Answer::carried;
  std::vector<std::size_t> path;
  for (std::size_t j = 0; j < count; ++j) {
    path.clear();
    int k = static_cast<int>(j);
    while (k >= 0 && answers[static_cast<std::size_t>(k)] == Answer::unknown) {
      path.push_back(static_cast<std::size_t>(k));
      k = parentOf(static_cast<std::size_t>(k));
    }
    const Answer answer = k >= 0 ? answers[static_cast<std::size_t>(k)] : Answer::notCarried;
    for (const std::size_t p : path) answers[p] = answer;
    if (movable(j) && answers[j] != Answer::carried) return std::nullopt;
  }
  BaseJoint found{*base, std::vector<bool>(count)};
  for (std::size_t j = 0; j < count; ++j) found.carried[j] = answers[j] == Answer::carried;
  return found;
}

/// The page's "up", a heuristic for drawing only:
/// - A robot whose movable joints branch before any of them (a humanoid's arms and legs from its
///   pelvis, a mobile base's wheels and arm) has no base joint: the world's +z, upwards in the ROS
///   convention (REP 103) its description follows. (The first planned joint's axis, used before,
///   is a shoulder's or a hip's: Atlas and DRC-Hubo were drawn lying down or upside down.)
/// - An arm's base joint turns about the vertical, and descriptions mount arms with any axis
///   upwards (dart-doc's KR5 has +y): the base joint's axis in the world at the joint vector \p q.
///   Within 45 degrees of the world's z it is signed upwards (REP 103 again: an arm hung from a
///   ceiling hangs); otherwise so that the links it carries lie on its positive side (the arm
///   stands on its base).
Vec3 upDirection(const ArmValidityCheckerBase& checker, const std::vector<double>& q) {
  const ArmModel& model = checker.model();
  const std::optional<BaseJoint> base = baseJoint(model);
  if (!base) return Vec3::UnitZ();
  std::vector<Pose> linkPoses;
  planner::forwardKinematics(model, q.data(), linkPoses);
  const planner::ArmJoint& first = model.joints[base->joint];
  // The child's frame is the joint's frame turned about (or moved along) the axis: the axis and
  // the joint's origin read the same in it.
  const Pose& joint = linkPoses[first.childLink];
  Vec3 up = joint.linear() * first.axis;
  if (std::abs(up.z()) >= std::sqrt(0.5) * up.norm()) return (up.z() > 0.0 ? up : Vec3(-up)).normalized();
  Vec3 centre = Vec3::Zero();
  std::size_t carried = 0;
  for (std::size_t b = 0; b < checker.linkBodies(); ++b) {
    const int parent = model.links[checker.linkOfBody(b)].parentJoint;
    if (parent < 0 || !base->carried[static_cast<std::size_t>(parent)]) continue;
    centre += linkPoses[checker.linkOfBody(b)] * checker.bodyMesh(b).bounds().center();
    ++carried;
  }
  centre /= static_cast<double>(std::max<std::size_t>(1, carried));
  if (up.dot(centre - joint.translation()) < 0.0) up = -up;
  return up.normalized();
}

}  // namespace

void requireArmViewable(const planner::ArmPlanningProblem& problem, const std::string& where) {
  const ArmValidityCheckerBase& checker = *problem.checker();
  const std::string robot = "robot '" + checker.model().name + "'";
  if (checker.linkBodies() == 0) {
    throw InputError(where + ": nothing to show: no link of " + robot + " has <collision> geometry");
  }
  if (checker.scene().environment.empty() && checker.scene().selfPairs.enabledPairs().empty()) {
    throw InputError(where + ": nothing to measure a clearance to: the scene has no obstacles and every link pair "
                     "of " + robot + " is disabled");
  }
}

ViewerSummary writeArmViewerHtml(const std::string& file, const planner::ArmPlanningProblem& problem,
                                 const ompl::geometric::PathGeometric* path, const std::string& source) {
  const ompl::base::SpaceInformationPtr& si = problem.spaceInformation();
  const auto& space = static_cast<const planner::ArmStateSpace&>(*si->getStateSpace());
  const ArmValidityCheckerBase& checker = *problem.checker();
  const ArmModel& model = checker.model();

  // The states shown: those measurePath() measures in `adsd plan` (its own interpolation on the
  // samples included), or the start and the goal.
  ompl::geometric::PathGeometric states(si);
  if (path != nullptr) {
    states = planner::measuredStates(armClearanceSamples(*path));
  } else {
    ompl::base::ScopedState<> start(si->getStateSpace()), goal(si->getStateSpace());
    space.fromJoints(problem.startJoints().data(), start.get());
    space.fromJoints(problem.goalJoints().data(), goal.get());
    states.append(start.get());
    states.append(goal.get());
  }

  ViewerPage page;
  page.name = problem.name();
  page.space = "arm " + model.name + ", " + std::to_string(model.dof()) + " joints";
  page.source = source;
  page.environment = &checker.scene().environment;
  const std::size_t links = checker.linkBodies();
  for (std::size_t b = 0; b < links; ++b) {
    page.bodies.push_back({model.links[checker.linkOfBody(b)].name, {&checker.bodyMesh(b)}});
  }
  for (const std::size_t j : model.activeJoints) page.jointNames.push_back(model.joints[j].name);
  std::vector<Pose> linkPoses;
  page.start = bodyPoses(checker, problem.startJoints(), linkPoses);
  page.goal = bodyPoses(checker, problem.goalJoints(), linkPoses);
  page.up = upDirection(checker, problem.startJoints());

  // The pairs the checker checks: every link against every obstacle part, and the enabled link
  // pairs (as link bodies).
  std::vector<int> bodyOfLink(model.links.size(), -1);
  for (std::size_t b = 0; b < links; ++b) bodyOfLink[checker.linkOfBody(b)] = static_cast<int>(b);
  std::vector<std::pair<int, int>> selfPairs;
  for (const auto& [a, b] : checker.scene().selfPairs.enabledPairs()) selfPairs.emplace_back(bodyOfLink[a], bodyOfLink[b]);
  requireArmViewable(problem, problem.name());

  const auto describe = [&](std::size_t i, ViewerState& shown, std::vector<CandidatePair>& pairs) {
    const ompl::base::State* s = states.getState(i);
    shown.joints.resize(model.dof());
    space.toJoints(s, shown.joints.data());
    shown.bodyPoses = bodyPoses(checker, shown.joints, linkPoses);
    shown.clearance = checker.clearance(s);
    // A link wholly inside a primitive (a solid: clearance 0) meets none of its surfaces: its
    // first vertex inside is what the page marks, if no pair of surfaces touches.
    if (shown.clearance <= 0.0) {
      const double slack = kWitnessSlackPerScale * checker.scale();
      for (std::size_t b = 0; b < links && !shown.inside; ++b) {
        for (const planner::ConvexSolid& solid : checker.scene().solids) {
          for (const Vec3& v : checker.bodyMesh(b).vertices()) {
            const Vec3 p = shown.bodyPoses[b] * v;
            if (!solid.containsStrictly(p, slack)) continue;
            shown.inside = ClosestPoints{static_cast<int>(b), ClosestPoints::kEnvironment, p, p,
                                         planner::nameBeforeSplit(solid.name)};
            break;
          }
          if (shown.inside) break;
        }
      }
    }
    for (std::size_t b = 0; b < links; ++b) {
      for (std::size_t e = 0; e < checker.scene().environment.size(); ++e) {
        pairs.push_back({&checker.bodyMesh(b), shown.bodyPoses[b], &checker.bodyMesh(links + e), Pose::Identity(),
                         static_cast<int>(b), ClosestPoints::kEnvironment});
      }
    }
    for (const auto& [a, b] : selfPairs) {
      pairs.push_back({&checker.bodyMesh(a), shown.bodyPoses[a], &checker.bodyMesh(b), shown.bodyPoses[b], a, b});
    }
  };
  return writeViewerPage(file, page, states.getStateCount(), describe, kWitnessSlackPerScale * checker.scale());
}

}  // namespace adsd::app
