// An outside OMPL program, as a user writes one against the installed package: it plans the
// shipped office problem on an ompl::geometric::SimpleSetup with adsd's state validity checker and
// certified motion validator. Exit 0 only when the solution is exact, every state and motion of it
// is valid, and the checker's clearance at each of its states equals the distance the library
// computes from scratch between the robot and the whole (unsplit) environment mesh.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include <ompl/base/ScopedState.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/geometric/SimpleSetup.h>

#include <adsd/distance.h>
#include <adsd/io/load_mesh.h>
#include <adsd/planner/certified_motion_validator.h>
#include <adsd/planner/mesh_validity_checker.h>
#include <adsd/planner/problem_file.h>
#include <adsd/planner/state_pose.h>

#ifndef ADSD_PROBLEMS_DIR
#error "ADSD_PROBLEMS_DIR: the installed problems (adsd_PROBLEMS_DIR from find_package(adsd))"
#endif

namespace ap = adsd::planner;
namespace ob = ompl::base;
namespace og = ompl::geometric;

int main() {
  const std::string problemsDir = ADSD_PROBLEMS_DIR;
  // README: the OMPL example (from here to "end of the README example").
  const ap::ProblemFile cfg = ap::readProblemFile(problemsDir + "/office.cfg");  // an SE(2) problem
  auto scene = std::make_shared<ap::RigidBodyScene>();
  scene->space = cfg.space;
  scene->robot = {ap::recentreRobot(adsd::io::loadMesh(cfg.robotPath), cfg.space)};
  scene->environment = ap::splitForRobot(adsd::io::loadMesh(cfg.worldPath), scene->robot);
  auto space = std::make_shared<ob::SE2StateSpace>();  // as cfg.space says: SE(3) takes SE3StateSpace, 3 bounds
  ob::RealVectorBounds bounds(2);
  const Eigen::AlignedBox3d volume = cfg.volume.value();  // the cfg's volume.* keys (optional in a cfg)
  for (int i = 0; i < 2; ++i) bounds.setLow(i, volume.min()[i]), bounds.setHigh(i, volume.max()[i]);
  space->setBounds(bounds);
  og::SimpleSetup ss(space);
  auto checker = std::make_shared<ap::MeshValidityChecker>(ss.getSpaceInformation(), scene);
  ss.setStateValidityChecker(checker);
  ss.getSpaceInformation()->setMotionValidator(
      std::make_shared<ap::CertifiedMotionValidator>(ss.getSpaceInformation(), checker));
  ob::ScopedState<> start(space), goal(space);
  ap::poseToState(cfg.start.toPose(), cfg.space, start.get());
  ap::poseToState(cfg.goal.toPose(), cfg.space, goal.get());
  ss.setStartAndGoalStates(start, goal);
  const ob::PlannerStatus solved = ss.solve(30.0);  // checker->clearance(state): exact distance to the obstacles
  // end of the README example

  if (solved != ob::PlannerStatus::EXACT_SOLUTION || !ss.haveExactSolutionPath()) {
    std::printf("no exact solution: %s\n", solved.asString().c_str());
    return 1;
  }
  og::PathGeometric path = ss.getSolutionPath();
  // Every state valid and every motion proven collision-free, forward as OMPL checks a path. A
  // planner that grows a tree from the goal (the default here) proved its motions from their far
  // end; the validator accepts a motion in either direction alike (14 of 20 such paths failed
  // check() when a walk toward a state flush against a wall stalled: an outside review).
  if (!path.check()) {
    std::printf("PathGeometric::check() fails on the solution\n");
    return 1;
  }
  path.interpolate(40);  // more states along the same motions, each checked below
  const adsd::Mesh world = adsd::io::loadMesh(cfg.worldPath);
  const double tolerance = 1e-9 * checker->scale();  // scene diagonal: clearances agree to rounding
  double worst = 0.0, smallest = INFINITY;
  for (std::size_t i = 0; i < path.getStateCount(); ++i) {
    const ob::State* s = path.getState(i);
    const double clearance = checker->clearance(s);
    const adsd::DistanceResult truth =
        adsd::distance(scene->robot[0], ap::poseFromState(s, cfg.space), world, adsd::Pose::Identity());
    worst = std::max(worst, std::fabs(clearance - truth.distance));
    smallest = std::min(smallest, clearance);
    if (!(std::fabs(clearance - truth.distance) <= tolerance) || !checker->isValid(s)) {
      std::printf("state %zu: clearance %.17g, library distance %.17g, valid %d\n", i, clearance, truth.distance,
                  checker->isValid(s));
      return 1;
    }
  }
  std::printf("office: %zu states on the solution, smallest clearance %.6g, max |clearance - distance| %.3g\n",
              path.getStateCount(), smallest, worst);
  return 0;
}
