// The shipped arm problems (problems/arm/NAME/{problem.cfg, scene.yaml, request.yaml}, written by
// problems/arm/make_arm_problems.py): every one reads without error, names its robot in the robot
// cache, has obstacles, and a start and goal over the same joints. (Whether start and goal are
// collision-free needs the arm checker: problems/arm/README.md.)
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <set>
#include <string>

#include "adsd/planner/motion_bench_maker_problem.h"
#include "adsd/planner/motion_plan_request_yaml.h"
#include "adsd/planner/planning_scene_yaml.h"
#include "scratch_dir.h"

namespace adsd::planner {
namespace {

TEST(ShippedArmProblems, EveryProblemReads) {
  namespace fs = std::filesystem;
  std::set<std::string> robots;
  int count = 0;
  for (const auto& entry : fs::directory_iterator(ADSD_ARM_PROBLEMS_DIR)) {
    // Problem directories only (not Python's __pycache__ beside the generator).
    if (!entry.is_directory() || entry.path().filename().string().rfind("_", 0) == 0) continue;
    const std::string cfg = (entry.path() / "problem.cfg").string();
    SCOPED_TRACE(cfg);
    ASSERT_TRUE(fs::exists(cfg));
    const MotionBenchMakerProblem p = readMotionBenchMakerProblem(cfg);
    EXPECT_TRUE(p.warnings.empty());
    EXPECT_EQ(p.name, entry.path().filename().string());
    EXPECT_EQ(p.robotPath.rfind(defaultRobotsDirectory(), 0), 0u) << p.robotPath;
    robots.insert(fs::path(p.robotPath).filename().string());
    const PlanningSceneYaml scene = readPlanningSceneYaml(p.scenePath);
    EXPECT_GE(scene.objects.size(), 2u);
    const MotionPlanRequestYaml request = readMotionPlanRequestYaml(p.requestPath);
    EXPECT_GE(request.start.size(), 6u);
    ASSERT_EQ(request.goal.size(), request.start.size());
    for (const auto& [joint, value] : request.start) EXPECT_EQ(request.goal.count(joint), 1u) << joint;
    ++count;
  }
  EXPECT_GE(count, 10);
  EXPECT_EQ(robots.size(), 2u);
}

std::string contents(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(ShippedArmProblems, GeneratorWritesTheCommittedFiles) {
  namespace fs = std::filesystem;
  test::ScratchDir dir;
  const std::string command = "/usr/bin/python3 " + std::string(ADSD_ARM_PROBLEMS_DIR) +
                              "/make_arm_problems.py --out " + dir.root().string() + " > /dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  int compared = 0;
  for (const auto& problem : fs::directory_iterator(dir.root())) {
    for (const char* file : {"problem.cfg", "scene.yaml", "request.yaml"}) {
      const fs::path committed = fs::path(ADSD_ARM_PROBLEMS_DIR) / problem.path().filename() / file;
      EXPECT_EQ(contents(problem.path() / file), contents(committed))
          << committed << " differs from the generator's output: run problems/arm/make_arm_problems.py";
      ++compared;
    }
  }
  EXPECT_GE(compared, 30);
}

}  // namespace
}  // namespace adsd::planner
