#include "arm_viewer_html.h"

#include <algorithm>
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

/// The page's "up": the axis of the first movable joint in the world at the joint vector \p q,
/// signed so that the links' centres lie on its positive side of the joint (the arm stands on
/// its base). A heuristic for drawing only: an arm's base joint turns about the vertical.
Vec3 upDirection(const ArmValidityCheckerBase& checker, const std::vector<double>& q) {
  const ArmModel& model = checker.model();
  std::vector<Pose> linkPoses;
  planner::forwardKinematics(model, q.data(), linkPoses);
  const planner::ArmJoint& first = model.joints[model.activeJoints.front()];
  // The child's frame is the joint's frame turned about (or moved along) the axis: the axis and
  // the joint's origin read the same in it.
  const Pose& joint = linkPoses[first.childLink];
  Vec3 up = joint.linear() * first.axis;
  Vec3 centre = Vec3::Zero();
  for (std::size_t b = 0; b < checker.linkBodies(); ++b) {
    centre += linkPoses[checker.linkOfBody(b)] * checker.bodyMesh(b).bounds().center();
  }
  centre /= static_cast<double>(std::max<std::size_t>(1, checker.linkBodies()));
  if (up.dot(centre - joint.translation()) < 0.0) up = -up;
  return up.normalized();
}

}  // namespace

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
  if (checker.scene().environment.empty() && selfPairs.empty()) {
    throw InputError(problem.name() + ": nothing to measure a clearance to: the scene has no obstacles and every "
                     "link pair of robot '" + model.name + "' is disabled");
  }

  const auto describe = [&](std::size_t i, ViewerState& shown, std::vector<CandidatePair>& pairs) {
    const ompl::base::State* s = states.getState(i);
    shown.joints.resize(model.dof());
    space.toJoints(s, shown.joints.data());
    shown.bodyPoses = bodyPoses(checker, shown.joints, linkPoses);
    shown.clearance = checker.clearance(s);
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
