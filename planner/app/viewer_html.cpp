#include "viewer_html.h"

#include <vector>

#include <ompl/base/ScopedState.h>

#include "adsd/planner/path_report.h"
#include "adsd/planner/state_pose.h"
#include "viewer_page.h"

namespace adsd::app {

ViewerSummary writeViewerHtml(const std::string& file, const planner::ProblemFile& problemFile,
                              const planner::PlanningProblem& problem, const ompl::geometric::PathGeometric* path,
                              const std::string& source) {
  const planner::RigidBodyScene& scene = problem.scene();
  const ompl::base::SpaceInformationPtr& si = problem.spaceInformation();

  // The states shown: the path as measurePath() samples it, or the start and the goal.
  ompl::geometric::PathGeometric states(si);
  bool coarser = false;
  if (path != nullptr) {
    states = planner::measuredStates(*path, &coarser);
  } else {
    ompl::base::ScopedState<> start(si->getStateSpace()), goal(si->getStateSpace());
    planner::poseToState(problemFile.start.toPose(), scene.space, start.get());
    planner::poseToState(problemFile.goal.toPose(), scene.space, goal.get());
    states.append(start.get());
    states.append(goal.get());
  }

  // Each part gets its sub-mesh tree once, as the checker's own copy does (mesh_validity_checker.cpp).
  planner::RigidBodyScene prepared = scene;
  for (Mesh& m : prepared.robot) m.buildHierarchy();
  for (Mesh& m : prepared.environment) m.buildHierarchy();

  // The robot is one body: its meshes move together.
  ViewerPage page;
  page.name = problemFile.name;
  page.space = scene.space == planner::RigidBodySpace::se2 ? "SE(2)" : "SE(3)";
  page.source = source;
  page.environment = &scene.environment;
  page.bodies.push_back({"robot", {}});
  for (const Mesh& m : scene.robot) page.bodies.front().parts.push_back(&m);
  page.start = {problemFile.start.toPose()};
  page.goal = {problemFile.goal.toPose()};

  const auto describe = [&](std::size_t i, ViewerState& shown, std::vector<CandidatePair>& pairs) {
    const ompl::base::State* s = states.getState(i);
    shown.bodyPoses = {planner::poseFromState(s, scene.space)};
    shown.clearance = problem.checker()->clearance(s);
    for (const Mesh& r : prepared.robot) {
      for (const Mesh& e : prepared.environment) {
        pairs.push_back({&r, shown.bodyPoses.front(), &e, Pose::Identity(), 0, ClosestPoints::kEnvironment});
      }
    }
  };
  ViewerSummary summary = writeViewerPage(file, page, states.getStateCount(), describe,
                                          kWitnessSlackPerScale * planner::sceneScale(scene));
  summary.coarserThanResolution = coarser;
  return summary;
}

}  // namespace adsd::app
