// The .cfg reader: good files parse into the problem they describe; each bad input of issue 7's
// catalogue is an adsd::InputError whose one-line message names the file, the line and the key.
#include <gtest/gtest.h>

#include <cmath>

#include "adsd/error.h"
#include "adsd/planner/problem_file.h"
#include "scratch_dir.h"

namespace adsd::planner {
namespace {

using test::ScratchDir;

const char* kSe2Problem = R"(# a comment
[problem]
name = corridor
robot = robot.obj
world = sub/world.obj
start.x = 1
start.y = 2   # trailing comment
start.theta = 0.5
goal.x=3
goal.y =4
goal.theta= -1
objective = max
longest_valid_segment_fraction = 0.02

[benchmark]
time_limit = 7.5
run_count = 3
simplify = 1

[planner]
rrtconnect =
rrtconnect.range = 0.3
prm =
prm.name = PRM-a
aps =
aps.range = 3
prm=
prm.max_nearest_neighbors = 5
)";

const char* kSe3Start = R"([problem]
robot = r.dae
world = w.dae
start.x = 1
start.y = 2
start.z = 3
start.theta = 1.5707963267948966
start.axis.x = 0
start.axis.y = 0
start.axis.z = 2
goal.x = 0
goal.y = 0
goal.z = 0
goal.theta = 0
goal.axis.x = 1
goal.axis.y = 0
goal.axis.z = 0
)";

/// Parses \p text as the file "t.cfg" and returns the message of the InputError it must raise.
std::string errorOf(const std::string& text) {
  ScratchDir dir;
  const std::string file = dir.write("t.cfg", text);
  try {
    readProblemFile(file);
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
    EXPECT_NE(message.find(file), std::string::npos) << "names the file: " << message;
    return message.substr(file.size());  // what follows the file name
  }
  ADD_FAILURE() << "no error for:\n" << text;
  return "";
}

TEST(ProblemFile, ReadsAnSe2ProblemWithBenchmarkAndPlannerSections) {
  ScratchDir dir;
  const ProblemFile p = readProblemFile(dir.write("corridor.cfg", kSe2Problem));
  EXPECT_EQ(p.space, RigidBodySpace::se2);
  EXPECT_EQ(p.name, "corridor");
  EXPECT_EQ(p.robotPath, (dir.root() / "robot.obj").string());
  EXPECT_EQ(p.worldPath, (dir.root() / "sub/world.obj").string());
  EXPECT_EQ(p.start.position, Vec3(1, 2, 0));
  EXPECT_EQ(p.start.theta, 0.5);
  EXPECT_EQ(p.start.location.line, 6);
  EXPECT_EQ(p.goal.position, Vec3(3, 4, 0));
  EXPECT_EQ(p.goal.theta, -1.0);
  EXPECT_FALSE(p.volume.has_value());
  EXPECT_EQ(p.objective, ObjectiveKind::maxMinClearance);  // "max" is a prefix, as in OMPL.app
  ASSERT_EQ(p.spaceParameters.size(), 1u);
  EXPECT_EQ(p.spaceParameters[0].key, "longest_valid_segment_fraction");
  EXPECT_EQ(p.spaceParameters[0].value, "0.02");
  EXPECT_EQ(p.spaceParameters[0].location.line, 13);
  EXPECT_EQ(p.benchmark.timeLimit, 7.5);
  EXPECT_EQ(p.benchmark.runCount, 3);
  EXPECT_EQ(p.benchmark.simplify, true);
  EXPECT_FALSE(p.benchmark.memoryLimit.has_value());
  // Three instances (the key repeats); aps is unknown: warned about with its line, dropped with
  // its parameter.
  ASSERT_EQ(p.planners.size(), 3u);
  EXPECT_EQ(p.planners[0].name, "rrtconnect");
  ASSERT_EQ(p.planners[0].parameters.size(), 1u);
  EXPECT_EQ(p.planners[0].parameters[0].key, "range");
  EXPECT_EQ(p.planners[1].label, "PRM-a");
  EXPECT_TRUE(p.planners[1].parameters.empty());
  EXPECT_EQ(p.planners[2].name, "prm");
  ASSERT_EQ(p.planners[2].parameters.size(), 1u);  // belongs to the latest prm
  EXPECT_EQ(p.planners[2].parameters[0].key, "max_nearest_neighbors");
  ASSERT_EQ(p.warnings.size(), 1u);
  EXPECT_NE(p.warnings[0].find(":25: key 'planner.aps'"), std::string::npos) << p.warnings[0];
}

TEST(ProblemFile, DetectsSe3AndBuildsAxisAnglePoses) {
  ScratchDir dir;
  const ProblemFile p = readProblemFile(dir.write("p.cfg", kSe3Start));
  EXPECT_EQ(p.space, RigidBodySpace::se3);
  EXPECT_EQ(p.name, "p");  // no name key: the file's stem
  const Pose start = p.start.toPose();
  EXPECT_TRUE(start.translation().isApprox(Vec3(1, 2, 3)));
  // 90 degrees about z (the axis is normalized): x goes to y.
  EXPECT_TRUE((start.linear() * Vec3::UnitX()).isApprox(Vec3::UnitY()));
  EXPECT_TRUE(p.goal.toPose().linear().isIdentity());
}

TEST(ProblemFile, ReadsTheVolumeAndIgnoresZForSe2) {
  ScratchDir dir;
  std::string text = kSe2Problem;
  text.insert(text.find("objective"), "volume.min.x = -1\nvolume.min.y = -2\nvolume.max.x = 5\nvolume.max.y = 6\n"
                                      "volume.min.z = 100\n");
  const ProblemFile p = readProblemFile(dir.write("v.cfg", text));
  ASSERT_TRUE(p.volume.has_value());
  EXPECT_EQ(p.volume->min(), Vec3(-1, -2, 0));
  EXPECT_EQ(p.volume->max(), Vec3(5, 6, 0));
}

TEST(ProblemFile, UnknownKeysAndSectionsWarnWithTheirLine) {
  ScratchDir dir;
  std::string text = std::string(kSe3Start) + "\n[display]\ncolour = red\n[benchmark]\nflavour = 2\n";
  const ProblemFile p = readProblemFile(dir.write("w.cfg", text));
  ASSERT_EQ(p.warnings.size(), 2u);
  EXPECT_NE(p.warnings[0].find(":20: key 'display.colour'"), std::string::npos) << p.warnings[0];
  EXPECT_NE(p.warnings[1].find(":22: key 'benchmark.flavour'"), std::string::npos) << p.warnings[1];
}

// ---- issue 7's catalogue, the cfg part -------------------------------------------------------

TEST(ProblemFileErrors, MissingFile) {
  ScratchDir dir;
  const std::string missing = dir.path("nope.cfg");
  try {
    readProblemFile(missing);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), missing + ": problem file does not exist");
  }
}

TEST(ProblemFileErrors, EmptyFile) { EXPECT_EQ(errorOf(""), ": no [problem] section"); }

TEST(ProblemFileErrors, MissingKeyNamesTheKeyAndTheSectionLine) {
  std::string text = kSe3Start;
  text.erase(text.find("goal.axis.y = 0\n"), std::string("goal.axis.y = 0\n").size());
  EXPECT_EQ(errorOf(text), ":1: key 'problem.goal.axis.y' is missing from the [problem] section");
  std::string noRobot = kSe3Start;
  noRobot.erase(noRobot.find("robot = r.dae\n"), std::string("robot = r.dae\n").size());
  EXPECT_EQ(errorOf(noRobot), ":1: key 'problem.robot' is missing from the [problem] section");
}

TEST(ProblemFileErrors, WrongTypes) {
  std::string text = kSe3Start;
  text.replace(text.find("start.y = 2"), 11, "start.y = two");
  EXPECT_EQ(errorOf(text), ":5: key 'problem.start.y': expected a number, got 'two'");
  std::string nan = kSe3Start;
  nan.replace(nan.find("start.z = 3"), 11, "start.z = nan");
  EXPECT_EQ(errorOf(nan), ":6: key 'problem.start.z': expected a finite number, got 'nan'");
  std::string inf = kSe3Start;
  inf.replace(inf.find("goal.x = 0"), 10, "goal.x = 1e999");
  EXPECT_EQ(errorOf(inf), ":11: key 'problem.goal.x': expected a finite number, got '1e999'");
  EXPECT_EQ(errorOf(std::string(kSe3Start) + "[benchmark]\nrun_count = 2.5\n"),
            ":19: key 'benchmark.run_count': expected a positive whole number, got '2.5'");
  EXPECT_EQ(errorOf(std::string(kSe3Start) + "objective = shortest\n"),
            ":18: key 'problem.objective': unknown objective 'shortest' (expected length or max_min_clearance)");
}

TEST(ProblemFileErrors, DuplicateSectionsAndKeys) {
  EXPECT_EQ(errorOf(std::string(kSe3Start) + "[problem]\nname = again\n"),
            ":18: section [problem] appears again (first at line 1)");
  EXPECT_EQ(errorOf(std::string(kSe3Start) + "start.x = 5\n"), ":18: key 'problem.start.x': repeated (first at line 4)");
}

TEST(ProblemFileErrors, SyntaxErrorsNameTheLine) {
  EXPECT_EQ(errorOf("[problem]\nrobot r.obj\n"), ":2: expected 'key = value', a [section] or a comment, got 'robot r.obj'");
  EXPECT_EQ(errorOf("[problem\n"), ":1: malformed section header '[problem'");
}

TEST(ProblemFileErrors, InconsistentPoseKeysAndBadVolumes) {
  // One SE(3) key makes the problem SE(3): the others must be there too.
  std::string text = kSe3Start;
  text.erase(text.find("start.z = 3\n"), std::string("start.z = 3\n").size());
  EXPECT_EQ(errorOf(text), ":1: key 'problem.start.z' is missing from the [problem] section");
  EXPECT_EQ(errorOf(std::string(kSe3Start) + "start.w = 1\n"),
            ":18: key 'problem.start.w': unknown pose field 'w' (expected x, y, theta, and for SE(3) z, axis.x, "
            "axis.y, axis.z)");
  std::string zeroAxis = kSe3Start;
  zeroAxis.replace(zeroAxis.find("start.axis.z = 2"), 16, "start.axis.z = 0");
  EXPECT_EQ(errorOf(zeroAxis), ":8: key 'problem.start.axis.x': the rotation axis is zero but the angle is not");
  EXPECT_EQ(errorOf(std::string(kSe3Start) + "volume.min.x = 0\n"),
            ":1: key 'problem.volume.min.y' is missing from the [problem] section");
  EXPECT_EQ(errorOf(std::string(kSe3Start) +
                    "volume.min.x = 0\nvolume.min.y = 0\nvolume.min.z = 0\nvolume.max.x = 1\nvolume.max.y = 0\n"
                    "volume.max.z = 1\n"),
            ":22: key 'problem.volume.max.y': must be greater than volume.min.y");
}

TEST(ProblemFileErrors, KinodynamicProblemsAreRejected) {
  EXPECT_EQ(errorOf(std::string(kSe3Start) + "control = kinematic_car\n"),
            ":18: key 'problem.control': kinodynamic problems ('kinematic_car') are not supported; only rigid bodies "
            "in SE(2) and SE(3)");
}

TEST(ProblemFileErrors, BinaryGarbage) {
  EXPECT_EQ(errorOf(std::string("[problem]\n\0\x01\x02", 13)), ": not a text file (contains a NUL byte)");
}

}  // namespace
}  // namespace adsd::planner
