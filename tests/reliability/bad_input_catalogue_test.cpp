// Issue 7's bad-input catalogue at the library level: the entries that tests/io and tests/planner
// do not already pin. Each must raise adsd::InputError (the one documented type; any other
// exception fails the test) with one line naming the file, the line and the key.
//
// Already covered elsewhere, not repeated here: missing / empty / truncated / unparseable mesh
// files, no triangles, lines or points only, NaN and infinite coordinates, indices out of range
// (tests/io load_mesh_test.cpp); 13 and 15 numbers, non-unit quaternions (pose_file_test.cpp);
// missing keys, duplicate sections and keys, wrong types, syntax errors, binary garbage
// (tests/planner problem_file_test.cpp); a robot file that does not exist, a start outside the
// bounds or in collision, a planner name OMPL lacks (planning_problem_test.cpp).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <typeinfo>

#include "adsd/error.h"
#include "adsd/planner/planner_registry.h"
#include "adsd/planner/planning_problem.h"
#include "adsd/planner/problem_file.h"

namespace adsd::planner {
namespace {

/// A directory of the test's own (parallel ctest runs share nothing), removed afterwards.
class Scratch {
 public:
  Scratch() {
    std::random_device entropy;
    root_ = std::filesystem::temp_directory_path() /
            ("adsd-reliability-" + std::to_string(entropy()) + "-" + std::to_string(entropy()));
    std::filesystem::create_directories(root_);
  }
  ~Scratch() {
    std::error_code ignored;
    std::filesystem::remove_all(root_, ignored);
  }
  std::string write(const std::string& name, const std::string& text) const {
    const std::string path = (root_ / name).string();
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }

 private:
  std::filesystem::path root_;
};

const char* kBoxFaces = "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";

/// The robot (a 0.2 box) and a world of two boxes, x in [-1, -0.5] and [0.5, 1].
void writeMeshes(const Scratch& dir) {
  dir.write("robot.obj", std::string("v -0.1 -0.1 -0.1\nv 0.1 -0.1 -0.1\nv 0.1 0.1 -0.1\nv -0.1 0.1 -0.1\n"
                                     "v -0.1 -0.1 0.1\nv 0.1 -0.1 0.1\nv 0.1 0.1 0.1\nv -0.1 0.1 0.1\n") +
                             kBoxFaces);
  dir.write("world.obj", std::string("v -1 -1 -1\nv -0.5 -1 -1\nv -0.5 1 -1\nv -1 1 -1\n"
                                     "v -1 -1 1\nv -0.5 -1 1\nv -0.5 1 1\nv -1 1 1\n") +
                             kBoxFaces +
                             "v 0.5 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv 0.5 1 -1\nv 0.5 -1 1\nv 1 -1 1\nv 1 1 1\nv 0.5 1 1\n"
                             "f 9 12 11 10\nf 13 14 15 16\nf 9 10 14 13\nf 10 11 15 14\nf 11 12 16 15\nf 12 9 13 16\n");
}

/// An SE(2) problem in the gap between the world's boxes; line 1 is [problem], the goal's keys
/// are on lines 7-9.
std::string problemText(const std::string& robot, const std::string& goal) {
  return "[problem]\nrobot = " + robot + "\nworld = world.obj\nstart.x = 0\nstart.y = -0.5\nstart.theta = 0\n" + goal +
         "volume.min.x = -2\nvolume.min.y = -2\nvolume.max.x = 2\nvolume.max.y = 2\n";
}

/// Builds the problem from \p cfg and returns the InputError's message; any other outcome fails.
std::string problemError(const std::string& cfg) {
  try {
    PlanningProblem problem(readProblemFile(cfg), CheckingOptions{});
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
    EXPECT_EQ(message.rfind(cfg, 0), 0u) << "starts with the file: " << message;
    return message.substr(cfg.size());
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected adsd::InputError, got " << typeid(e).name() << ": " << e.what();
    return "";
  }
  ADD_FAILURE() << "no error for " << cfg;
  return "";
}

TEST(BadInputCatalogue, TheValidProblemBuilds) {
  Scratch dir;
  writeMeshes(dir);
  const std::string cfg = dir.write("good.cfg", problemText("robot.obj", "goal.x = 0\ngoal.y = 0.5\ngoal.theta = 0\n"));
  EXPECT_NO_THROW(PlanningProblem(readProblemFile(cfg), CheckingOptions{}));
}

TEST(BadInputCatalogue, GoalOutsideTheBounds) {
  Scratch dir;
  writeMeshes(dir);
  const std::string cfg = dir.write("t.cfg", problemText("robot.obj", "goal.x = 2.5\ngoal.y = 0\ngoal.theta = 0\n"));
  EXPECT_EQ(problemError(cfg),
            ":7: key 'problem.goal.x': the goal state is outside the bounds (x = 2.5, the bounds [-2, 2])");
}

TEST(BadInputCatalogue, GoalInCollision) {
  Scratch dir;
  writeMeshes(dir);
  const std::string cfg = dir.write("t.cfg", problemText("robot.obj", "goal.x = -0.5\ngoal.y = 0\ngoal.theta = 0.3\n"));
  const std::string message = problemError(cfg);
  EXPECT_EQ(message.rfind(":7: key 'problem.goal.x': the goal state is in collision", 0), 0u) << message;
}

TEST(BadInputCatalogue, MeshErrorsThroughAProblemFileNameTheKeyAndTheMesh) {
  Scratch dir;
  writeMeshes(dir);
  const std::string goal = "goal.x = 0\ngoal.y = 0.5\ngoal.theta = 0\n";
  const std::string inf = dir.write("inf.obj", "v 0 0 0\nv 0.1 0 0\nv inf 0.1 0\nf 1 2 3\n");
  std::string message = problemError(dir.write("inf.cfg", problemText("inf.obj", goal)));
  // The mesh file's own line too: the OBJ reader names it (issue 16).
  EXPECT_EQ(message.rfind(":2: key 'problem.robot': " + inf + ":3: ", 0), 0u) << message;
  EXPECT_NE(message.find("non-finite"), std::string::npos) << message;
  const std::string lines = dir.write("lines.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\n");
  message = problemError(dir.write("lines.cfg", problemText("lines.obj", goal)));
  EXPECT_EQ(message.rfind(":2: key 'problem.robot': " + lines + ": the file holds no triangles", 0), 0u) << message;
}

// Was a bug in adsd/io: loadMesh ran assimp's JoinIdenticalVertices before it checked coordinates,
// and a vertex with a NaN compares "identical" to an earlier one (every comparison with NaN is
// false), so the NaN vertex was silently replaced and the file loaded as a degenerate triangle.
// Here the third vertex is NaN (tests/io's NaN test has it second, which passed). Reproducer:
//   printf 'v 0 0 0\nv 1 0 0\nv nan 0.5 0.7\nf 1 2 3\n' > nan.obj; adsd distance nan.obj nan.obj  (was exit 0)
TEST(BadInputCatalogue, NanCoordinateIsReportedWhereverTheVertexIs) {
  Scratch dir;
  writeMeshes(dir);
  const std::string goal = "goal.x = 0\ngoal.y = 0.5\ngoal.theta = 0\n";
  const std::string nan = dir.write("nan.obj", "v 0 0 0\nv 0.1 0 0\nv nan 0.1 0\nf 1 2 3\n");
  const std::string message = problemError(dir.write("nan.cfg", problemText("nan.obj", goal)));
  EXPECT_EQ(message.rfind(":2: key 'problem.robot': " + nan + ":3: ", 0), 0u) << message;
  EXPECT_NE(message.find("non-finite"), std::string::npos) << message;
}

// A value OMPL cannot convert: OMPL's ParamSet::setParam throws std::runtime_error ("Failed
// converting string to real number") instead of returning false, so the problem-file reader
// checks every value it hands to OMPL (fixed there; before, `adsd plan` said "internal error",
// exit 1). Reproducer: any valid cfg plus the line
//   longest_valid_segment_fraction = lots
TEST(BadInputCatalogue, AValueOmplRejectsNamesTheKey) {
  Scratch dir;
  writeMeshes(dir);
  const std::string cfg =
      dir.write("t.cfg", problemText("robot.obj", "goal.x = 0\ngoal.y = 0.5\ngoal.theta = 0\n") +
                             "longest_valid_segment_fraction = lots\n");
  const std::string message = problemError(cfg);
  EXPECT_EQ(message.rfind(":14: key 'problem.longest_valid_segment_fraction'", 0), 0u) << message;
}

TEST(BadInputCatalogue, APlannerNameOmplLacksIsNoPlannerNotAnException) {
  Scratch dir;
  writeMeshes(dir);
  const std::string cfg = dir.write("t.cfg", problemText("robot.obj", "goal.x = 0\ngoal.y = 0.5\ngoal.theta = 0\n") +
                                                 "[planner]\nteleport =\nrrtconnect =\n");
  const ProblemFile file = readProblemFile(cfg);
  // Documented: an unknown [planner] entry is a warning with its line, and the entry is dropped.
  ASSERT_EQ(file.planners.size(), 1u);
  EXPECT_EQ(file.planners[0].name, "rrtconnect");
  ASSERT_EQ(file.warnings.size(), 1u);
  EXPECT_EQ(file.warnings[0].rfind(cfg + ":15: key 'planner.teleport'", 0), 0u) << file.warnings[0];
  PlanningProblem problem(file, CheckingOptions{});
  EXPECT_EQ(makePlanner("teleport", problem.spaceInformation()), nullptr);
}

/// The InputError configurePlanner throws for \p planner with the file's [planner] lines \p lines
/// (the first names the planner), without the file's name; "" when it throws none.
std::string configureError(const std::string& planner, const std::string& lines) {
  Scratch dir;
  writeMeshes(dir);
  const std::string cfg = dir.write("t.cfg", problemText("robot.obj", "goal.x = 0\ngoal.y = 0.5\ngoal.theta = 0\n") +
                                                 "[planner]\n" + planner + " =\n" + lines);
  const ProblemFile file = readProblemFile(cfg);
  PlanningProblem problem(file, CheckingOptions{});
  const ompl::base::PlannerPtr p = makePlanner(planner, problem.spaceInformation());
  try {
    configurePlanner(*p, planner, file.planners.at(0).parameters);
  } catch (const InputError& e) {
    const std::string message = e.what();
    return message.rfind(cfg, 0) == 0 ? message.substr(cfg.size()) : message;
  }
  return "";
}

// RRT*'s ordered sampling orders the samples of informed or rejection sampling. Set without
// either, OMPL 1.5.2 logged an error, kept it, and dereferenced a null sampler when it set up:
// adsd plan and adsd benchmark ended in a segmentation fault (an adversarial review). Set
// before the line that turns informed sampling on, OMPL refused it with no word of the line; it
// is now set last.
TEST(BadInputCatalogue, OrderedSamplingWithoutInformedOrRejectionSamplingNamesTheKey) {
  EXPECT_EQ(configureError("rrtstar", "rrtstar.ordered_sampling = 1\n"),
            ":16: key 'planner.rrtstar.ordered_sampling': rrtstar: ordered_sampling orders the samples of informed "
            "or rejection sampling, and neither is on (set informed_sampling = 1 or sample_rejection = 1)");
  EXPECT_EQ(configureError("rrtstar", "rrtstar.ordered_sampling = 1\nrrtstar.informed_sampling = 1\n"), "");
  EXPECT_EQ(configureError("rrtstar", "rrtstar.sample_rejection = true\nrrtstar.ordered_sampling = true\n"), "");
  // A later line for a switch overrides an earlier one: only the last is held to what OMPL keeps.
  EXPECT_EQ(configureError("rrtstar", "rrtstar.informed_sampling = 1\nrrtstar.informed_sampling = 0\n"), "");
  // InformedRRT* samples the informed set always (it declares no switch for it).
  EXPECT_EQ(configureError("informedrrtstar", "informedrrtstar.ordered_sampling = 1\n"), "");
}

// AnytimePathShortening's list of planners, read by OMPL 1.5.2 alone: an unknown name was
// dropped with a line in OMPL's log (`rrt,prm` ran its default planners instead), and an unknown
// or nameless entry with parameters and no planner before it (`Foo[range=1]`, ` PRM`) crashed it
// (an adversarial review, then our own sweep).
TEST(BadInputCatalogue, UnknownOrMalformedPlannersOfAnytimePathShorteningNameTheKey) {
  const std::string key = ":16: key 'planner.anytimepathshortening.planners': anytimepathshortening";
  EXPECT_EQ(configureError("anytimepathshortening", "anytimepathshortening.planners = rrt,prm\n"),
            key + " knows no planner 'rrt' (it takes OMPL's class names, such as RRT, RRTConnect, PRM, RRTstar)");
  EXPECT_EQ(configureError("anytimepathshortening", "anytimepathshortening.planners = Foo[range=1]\n"),
            key + " knows no planner 'Foo' (it takes OMPL's class names, such as RRT, RRTConnect, PRM, RRTstar)");
  EXPECT_EQ(configureError("anytimepathshortening", "anytimepathshortening.planners = RRT, PRM\n"),
            key + ": expected planners as NAME or NAME[PARAMETER=VALUE ...] separated by commas, without spaces "
                  "around them, got ' PRM'");
  EXPECT_EQ(configureError("anytimepathshortening", "anytimepathshortening.planners = RRTstar[ordered_sampling=1]\n"),
            key + ": 'RRTstar[ordered_sampling=1]': ordered_sampling orders the samples of informed or rejection "
                  "sampling, and neither is on (set informed_sampling=1 or sample_rejection=1)");
  EXPECT_EQ(configureError("anytimepathshortening",
                           "anytimepathshortening.planners = RRTConnect,PRM[max_nearest_neighbors=5]\n"),
            "");
}

}  // namespace
}  // namespace adsd::planner
