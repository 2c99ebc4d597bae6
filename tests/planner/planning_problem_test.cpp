// Problems from files: meshes loaded and re-centred, bounds inferred, errors naming the key; and
// `adsd plan` end to end (exit status 0 solved, 2 bad input, no half-written path file).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <ompl/base/spaces/SE2StateSpace.h>

#include "adsd/error.h"
#include "adsd/planner/features.h"
#include "adsd/planner/planning_problem.h"
#include "adsd/problem_scenes.h"
#include "adsd/shapes.h"
#include "scratch_dir.h"

namespace adsd::app {
int planCommand(const std::vector<std::string>& args);
}

namespace adsd::planner {
namespace {

using test::ScratchDir;

/// thin_wall.cfg with its meshes, written into \p dir; the robot is written moved off its vertex
/// mean so that the loader's re-centring is what puts it back. \p extra lines go in [problem].
std::string writeThinWall(const ScratchDir& dir, const std::string& extra = "",
                          const std::string& start = "start.x = -2.03\nstart.y = -1\nstart.theta = 0\n") {
  const shapes::ProblemScene scene = shapes::thinWallScene();
  Pose offset = Pose::Identity();
  offset.translate(Vec3(5, -7, 0.25));
  shapes::writeObj(shapes::merge({scene.robot.front()}, {offset}), dir.path("bar.obj"));
  shapes::writeObj(scene.environment, dir.path("walls.obj"));
  return dir.write("thin.cfg", "[problem]\nrobot = bar.obj\nworld = walls.obj\n" + start +
                                   "goal.x = -2.03\ngoal.y = 3\ngoal.theta = 0\n" + extra);
}

std::string errorOf(const ProblemFile& file, const CheckingOptions& options = {}) {
  try {
    PlanningProblem problem(file, options);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no error";
  return "";
}

TEST(PlanningProblem, RecentresTheRobotKeepingZForSe2AndInfersBounds) {
  ScratchDir dir;
  const ProblemFile file = readProblemFile(writeThinWall(dir));
  PlanningProblem problem(file, CheckingOptions{});
  const Mesh& robot = problem.scene().robot.front();
  Vec3 mean = Vec3::Zero();
  for (const Vec3& v : robot.vertices()) mean += v;
  mean /= static_cast<double>(robot.vertices().size());
  EXPECT_NEAR(mean.x(), 0.0, 1e-12);
  EXPECT_NEAR(mean.y(), 0.0, 1e-12);
  EXPECT_NEAR(mean.z(), 0.25, 1e-12) << "SE(2): z of the mean is kept";
  // No volume: the environment's box (the outer walls reach +-4.2). Assimp reads coordinates in
  // single precision: 4.2 comes back within 2.4e-7 (half a float ulp at 4).
  const auto* bounds = &problem.spaceInformation()->getStateSpace()->as<ompl::base::SE2StateSpace>()->getBounds();
  EXPECT_NEAR(bounds->low[0], -4.2, 2.4e-7);
  EXPECT_NEAR(bounds->high[1], 4.2, 2.4e-7);
}

TEST(PlanningProblem, RobotFileThatDoesNotExist) {
  ScratchDir dir;
  const std::string cfg = writeThinWall(dir);
  std::filesystem::remove(dir.path("bar.obj"));
  EXPECT_EQ(errorOf(readProblemFile(cfg)),
            cfg + ":2: key 'problem.robot': mesh file '" + dir.path("bar.obj") + "' does not exist");
  // In a `data` directory beside the cfg, as the shipped problems reach the fetched real models
  // (which an install leaves for the user to link): the message says where they come from.
  const std::string inData =
      dir.write("in_data.cfg", "[problem]\nrobot = data/cow.off\nworld = walls.obj\nstart.x = -2.03\nstart.y = -1\n"
                               "start.theta = 0\ngoal.x = -2.03\ngoal.y = 3\ngoal.theta = 0\n");
  const std::string message = errorOf(readProblemFile(inData));
  EXPECT_EQ(message.rfind(inData + ":2: key 'problem.robot': mesh file '" + dir.path("data/cow.off") +
                              "' does not exist (a shipped problem's real meshes are fetched by fetch_meshes.sh",
                          0),
            0u)
      << message;
  EXPECT_NE(message.find("link that directory as '" + dir.path("data") + "')"), std::string::npos) << message;
}

TEST(PlanningProblem, StartInCollisionOrOutsideTheBounds) {
  ScratchDir dir;
  const std::string inWall = writeThinWall(dir, "", "start.x = 0\nstart.y = -1\nstart.theta = 0\n");
  const std::string message = errorOf(readProblemFile(inWall));
  EXPECT_EQ(message.rfind(inWall + ":4: key 'problem.start.x': the start state is in collision", 0), 0u) << message;
  const std::string outside = writeThinWall(
      dir, "volume.min.x = -4\nvolume.min.y = -4\nvolume.max.x = 4\nvolume.max.y = 4\n",
      "start.x = -5\nstart.y = -1\nstart.theta = 0\n");
  EXPECT_EQ(errorOf(readProblemFile(outside)),
            outside + ":4: key 'problem.start.x': the start state is outside the bounds (x = -5, the bounds [-4, 4])");
}

// A start valid by a hair, nearer the wall than distances are trusted (1e-10 of the scene): with
// certified motions no path can leave it, and planning from it used to run out of time without a
// word (an outside review). It is warned of, naming its line; with discrete motions it is not.
TEST(PlanningProblem, StartFlushAgainstAWallIsWarnedOfForCertifiedMotions) {
  ScratchDir dir;
  // The bar's face touches the wall's at x = -0.02 (CheckerSettings.SafetyMarginMakesNearStatesInvalid).
  const std::string flush = writeThinWall(dir, "", "start.x = -0.02000000001\nstart.y = -1\nstart.theta = 0\n");
  CheckingOptions certified;
  certified.motion = MotionKind::certified;
  PlanningProblem problem(readProblemFile(flush), certified);
  ASSERT_GT(problem.checker()->clearance(problem.setup().getProblemDefinition()->getStartState(0)), 0.0);
  ASSERT_EQ(problem.warnings().size(), 1u);
  EXPECT_EQ(problem.warnings()[0].rfind(flush + ":4: key 'problem.start.x': the start state is ", 0), 0u)
      << problem.warnings()[0];
  EXPECT_NE(problem.warnings()[0].find("no certified motion can be proven to or from it"), std::string::npos);
  EXPECT_TRUE(PlanningProblem(readProblemFile(flush), CheckingOptions{}).warnings().empty());
}

TEST(PlanningProblem, SpaceParametersAreAppliedOrReported) {
  ScratchDir dir;
  PlanningProblem problem(readProblemFile(writeThinWall(dir, "longest_valid_segment_fraction = 0.002\nfoo = 1\n")),
                          CheckingOptions{});
  EXPECT_DOUBLE_EQ(problem.spaceInformation()->getStateSpace()->getLongestValidSegmentFraction(), 0.002);
  ASSERT_EQ(problem.warnings().size(), 1u);
  EXPECT_NE(problem.warnings()[0].find(":11: key 'problem.foo'"), std::string::npos) << problem.warnings()[0];
  const std::string badSampler = writeThinWall(dir, "sampler = clever\n");
  EXPECT_EQ(errorOf(readProblemFile(badSampler)),
            badSampler + ":10: key 'problem.sampler': unknown sampler 'clever' (expected uniform, gaussian, "
                         "obstacle_based, max_clearance or bridge_test)");
}

TEST(PlanCommand, SolvesWritesThePathAndExitsZero) {
  ScratchDir dir;
  const std::string cfg = writeThinWall(dir);
  const std::string out = dir.path("out.path");
  EXPECT_EQ(app::planCommand({cfg, "--time", "5", "--motion", "certified", "--path", out}), 0);
  std::ifstream in(out);
  std::string line;
  int lines = 0;
  while (std::getline(in, line)) {
    ++lines;
    std::istringstream values(line);
    double x, y, yaw;
    EXPECT_TRUE(values >> x >> y >> yaw) << line;  // SE(2): x y yaw
  }
  EXPECT_GE(lines, 2);
  // RRTConnect stops at its first solution: the time is only a cap (sanitizer builds are slower).
#if ADSD_PLANNER_HAS_FCL
  EXPECT_EQ(app::planCommand({cfg, "--checker", "fcl", "--objective", "clearance", "--planner", "rrtconnect",
                              "--time", "30"}),
            0);
#else
  EXPECT_EQ(app::planCommand({cfg, "--checker", "fcl", "--planner", "rrtconnect"}), 2);  // refused, one line
#endif
}

// OMPL's simplifier shortens a path towards the obstacles: with the clearance objective the path
// is kept as planned, and the summary says why (`adsd plan maze.cfg`, its own objective, had
// minimum clearance 0.0033 simplified and 0.218 as planned).
TEST(PlanCommand, PathPlannedForClearanceIsNotSimplified) {
  ScratchDir dir;
  const std::string cfg = writeThinWall(dir);
  auto summary = [&](const std::vector<std::string>& args) {
    testing::internal::CaptureStdout();
    const int status = app::planCommand(args);
    const std::string out = testing::internal::GetCapturedStdout();
    EXPECT_EQ(status, 0) << out;
    return out;
  };
  const std::string clearance =
      summary({cfg, "--objective", "clearance", "--planner", "rrtconnect", "--time", "30", "--motion", "certified"});
  EXPECT_NE(clearance.find(", 0.000 s simplifying"), std::string::npos) << clearance;
  EXPECT_NE(clearance.find("simplify    not done: the objective is clearance"), std::string::npos) << clearance;
  const std::string length = summary({cfg, "--planner", "rrtconnect", "--time", "30", "--motion", "certified"});
  EXPECT_EQ(length.find("simplify    not done"), std::string::npos) << length;
  const std::string asked = summary({cfg, "--objective", "clearance", "--planner", "rrtconnect", "--time", "30",
                                     "--motion", "certified", "--no-simplify"});
  EXPECT_EQ(asked.find("simplify    not done"), std::string::npos) << asked;  // nothing to explain
}

TEST(PlanCommand, BadInputExitsTwoAndWritesNothing) {
  ScratchDir dir;
  const std::string cfg = writeThinWall(dir);
  const std::string out = dir.path("out.path");
  EXPECT_EQ(app::planCommand({cfg, "--planner", "teleport", "--path", out}), 2);
  EXPECT_EQ(app::planCommand({dir.path("missing.cfg"), "--path", out}), 2);
  EXPECT_EQ(app::planCommand({cfg, "--time", "-1"}), 2);
  EXPECT_EQ(app::planCommand({cfg, "--checker", "ode"}), 2);
  EXPECT_EQ(app::planCommand({cfg, "--bogus"}), 2);
  const std::string inWall = writeThinWall(dir, "", "start.x = 0\nstart.y = -1\nstart.theta = 0\n");
  EXPECT_EQ(app::planCommand({inWall, "--path", out}), 2);
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_FALSE(std::filesystem::exists(out + ".partial"));
}

}  // namespace
}  // namespace adsd::planner
