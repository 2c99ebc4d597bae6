// Solution paths of the certified motion validator against the independent oracle (tests/oracle):
// every motion of a path the certified validator accepted is walked with the oracle's own
// distances, and no state on the walk may collide (issue 4: "the certified validator never
// accepts a colliding motion"). Paths come from planning the small shipped problems here, and
// from the path files that problems/compare_checkers.py writes (ADSD_VERIFY_PATHS).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <utility>
#include <sstream>
#include <string>
#include <vector>

#include <ompl/base/ScopedState.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/base/spaces/SE3StateSpace.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/Console.h>

#include "adsd/planner/features.h"
#include "adsd/planner/planning_problem.h"
#include "adsd/planner/problem_file.h"
#include "adsd/planner/shipped_problems.h"
#include "adsd/planner/state_pose.h"
#include "oracle.h"

namespace adsd::planner {
namespace {

namespace ob = ompl::base;
namespace og = ompl::geometric;

/// Where the oracle's clearance is too small to step by, the walk still advances by this fraction
/// of the scene's length scale (dimensionless): such states are dense samples, checked but not
/// proven to cover the stretch between them. 2e-4 of the diagonal is 2.7 mm on the thin wall's
/// 13.5 m scene, a seventh of its 2 cm wall.
constexpr double kSampleSpacingFraction = 2e-4;

/// What walking one path established.
struct PathWalk {
  std::size_t motions = 0;
  std::size_t states = 0;         ///< oracle evaluations
  std::size_t sampledSteps = 0;   ///< steps taken at the sample spacing (oracle clearance too small)
  double minClearance = std::numeric_limits<double>::infinity();  ///< the oracle's, over the walk
};

/// The environment's parts joined into one mesh again: the oracle places the robot's triangles
/// once per call, so one call over the whole world is much cheaper than one per part.
Mesh joined(const std::vector<Mesh>& parts) {
  std::vector<Vec3> vertices;
  std::vector<TriangleIndices> triangles;
  for (const Mesh& part : parts) {
    const auto base = static_cast<std::uint32_t>(vertices.size());
    vertices.insert(vertices.end(), part.vertices().begin(), part.vertices().end());
    for (const TriangleIndices& t : part.triangles()) triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  }
  return Mesh(std::move(vertices), std::move(triangles), "environment");
}

/// The oracle's distance from the robot at \p pose to the environment, and whether they meet.
std::pair<double, bool> oracleAt(const RigidBodyScene& scene, const Mesh& environment, const Pose& pose) {
  double distance = std::numeric_limits<double>::infinity();
  bool intersecting = false;
  for (const Mesh& r : scene.robot) {
    distance = std::min(distance, oracle::meshDistance(r, pose, environment, Pose::Identity()).value);
    intersecting = intersecting || oracle::meshesIntersect(r, pose, environment, Pose::Identity());
  }
  return {distance, intersecting};
}

/// Walks every motion of \p path: at each state the oracle's distance d must be positive and no
/// triangle pair may meet; the next state is d / L further along (L bounds the displacement of any
/// robot point per unit of the motion, as in the certified validator), so where the oracle's
/// distance allows it the walk proves the stretch free on its own; where d is below the sample
/// spacing, it advances by the spacing instead.
PathWalk walkWithOracle(const PlanningProblem& problem, const og::PathGeometric& path, const std::string& what) {
  const RigidBodyScene& scene = problem.scene();
  const ob::SpaceInformationPtr& si = problem.spaceInformation();
  const double spacing = kSampleSpacingFraction * sceneScale(scene);
  const double radius = robotRadius(scene);
  const Mesh environment = joined(scene.environment);
  PathWalk walk;
  ob::ScopedState<> state(si);
  for (std::size_t i = 0; i + 1 < path.getStateCount(); ++i) {
    const ob::State* a = path.getState(i);
    const ob::State* b = path.getState(i + 1);
    ++walk.motions;
    const double sweep = translationDistance(a, b, scene.space) + rotationAngle(a, b, scene.space) * radius;
    double t = 0.0;
    while (true) {
      si->getStateSpace()->interpolate(a, b, t, state.get());
      const auto [distance, intersecting] = oracleAt(scene, environment, poseFromState(state.get(), scene.space));
      ++walk.states;
      walk.minClearance = std::min(walk.minClearance, distance);
      EXPECT_FALSE(intersecting) << what << ": motion " << i << " collides at t = " << t;
      EXPECT_GT(distance, 0.0) << what << ": motion " << i << " touches at t = " << t;
      if (intersecting || !(distance > 0.0)) return walk;
      if (t >= 1.0 || sweep <= 0.0) break;
      const bool sampled = distance < spacing;
      walk.sampledSteps += sampled;
      t = std::min(1.0, t + std::max(distance, spacing) / sweep);
    }
  }
  return walk;
}

void report(const std::string& what, const PathWalk& w) {
  std::printf("[%s] %zu motions, %zu oracle states (%zu steps at the sample spacing), min oracle clearance %.6g\n",
              what.c_str(), w.motions, w.states, w.sampledSteps, w.minClearance);
}

/// Plans \p cfg with RRTConnect and the certified validator, then walks the path as found and as
/// simplified (the simplifier's shortcuts are motions the validator accepted too).
void planAndWalk(const std::string& cfg, CheckerKind checker) {
  ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
  const ProblemFile file = readProblemFile(shippedProblemsDirectory() + "/" + cfg);
  CheckingOptions options;
  options.checker = checker;
  options.motion = MotionKind::certified;
  PlanningProblem problem(file, options);
  og::SimpleSetup& ss = problem.setup();
  ss.setPlanner(std::make_shared<og::RRTConnect>(problem.spaceInformation()));
  // RRTConnect stops at its first solution: the time is only a cap (sanitizer builds are slower).
  ASSERT_EQ(ss.solve(60.0), ob::PlannerStatus::EXACT_SOLUTION) << cfg;
  const std::string what = file.name + (checker == CheckerKind::adsd ? " adsd" : " fcl");
  PathWalk raw = walkWithOracle(problem, ss.getSolutionPath(), what + " as found");
  report(what + " as found", raw);
  ss.simplifySolution(5.0);
  PathWalk simplified = walkWithOracle(problem, ss.getSolutionPath(), what + " simplified");
  report(what + " simplified", simplified);
}

TEST(SolutionPathsVersusOracle, CertifiedPathsThroughTheThinWallScene) {
  planAndWalk("thin_wall.cfg", CheckerKind::adsd);
#if ADSD_PLANNER_HAS_FCL
  planAndWalk("thin_wall.cfg", CheckerKind::fcl);
#endif
}
TEST(SolutionPathsVersusOracle, CertifiedPathsInTheOffice) { planAndWalk("office.cfg", CheckerKind::adsd); }
TEST(SolutionPathsVersusOracle, CertifiedPathsInTheMaze) { planAndWalk("maze.cfg", CheckerKind::adsd); }

/// Reads an OMPL.app .path file as `adsd plan --path` writes it (SE(2): x y yaw; SE(3): x y z qx
/// qy qz qw per line).
og::PathGeometric readPath(const std::string& pathFile, const PlanningProblem& problem) {
  og::PathGeometric path(problem.spaceInformation());
  std::ifstream in(pathFile);
  EXPECT_TRUE(in.good()) << pathFile << ": cannot read";
  ob::ScopedState<> state(problem.spaceInformation());
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream values(line);
    if (problem.scene().space == RigidBodySpace::se2) {
      double x, y, yaw;
      if (!(values >> x >> y >> yaw)) continue;
      auto* s = state->as<ob::SE2StateSpace::StateType>();
      s->setXY(x, y);
      s->setYaw(yaw);
    } else {
      double x, y, z, qx, qy, qz, qw;
      if (!(values >> x >> y >> z >> qx >> qy >> qz >> qw)) continue;
      auto* s = state->as<ob::SE3StateSpace::StateType>();
      s->setXYZ(x, y, z);
      s->rotation().x = qx;
      s->rotation().y = qy;
      s->rotation().z = qz;
      s->rotation().w = qw;
    }
    path.append(state.get());
  }
  return path;
}

TEST(SolutionPathsVersusOracle, PathFilesNamedInTheEnvironment) {
  // ADSD_VERIFY_PATHS = "CFG PATH CFG PATH ...": paths that `adsd plan --motion certified` wrote
  // (problems/compare_checkers.py --verify sets it for every certified run it made).
  const char* list = std::getenv("ADSD_VERIFY_PATHS");
  if (list == nullptr || *list == '\0') GTEST_SKIP() << "ADSD_VERIFY_PATHS not set";
  std::istringstream words(list);
  std::string cfg, pathFile;
  int walked = 0;
  while (words >> cfg >> pathFile) {
    const ProblemFile file = readProblemFile(cfg);
    CheckingOptions options;
    options.motion = MotionKind::certified;
    PlanningProblem problem(file, options);
    const og::PathGeometric path = readPath(pathFile, problem);
    ASSERT_GE(path.getStateCount(), 2u) << pathFile;
    report(pathFile, walkWithOracle(problem, path, pathFile));
    ++walked;
  }
  EXPECT_GT(walked, 0) << "ADSD_VERIFY_PATHS holds no CFG PATH pair";
}

}  // namespace
}  // namespace adsd::planner
