// The .cfg reader: good files parse into the problem they describe; each bad input of issue 7's
// catalogue is an adsd::InputError whose one-line message names the file, the line and the key.
#include <gtest/gtest.h>

#include <algorithm>
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

// A UTF-8 byte-order mark (Windows editors write one) is no part of the first line: "[problem]"
// after it was a malformed section header.
TEST(ProblemFile, Utf8ByteOrderMarkBeforeTheFirstLineIsSkipped) {
  ScratchDir dir;
  const ProblemFile p = readProblemFile(dir.write("bom.cfg", "\xEF\xBB\xBF" + std::string(kSe3Start)));
  EXPECT_EQ(p.space, RigidBodySpace::se3);
  EXPECT_EQ(p.start.position, Vec3(1, 2, 3));
  EXPECT_EQ(p.start.location.line, 4);
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

// `rrtconnect = yes`: OMPL.app's planner lines take no value; the value was dropped unsaid.
TEST(ProblemFile, APlannerLineWithAValueWarnsWithItsLine) {
  ScratchDir dir;
  const std::string text = std::string(kSe3Start) + "\n[planner]\nrrtconnect = yes\nprm =\n";
  const ProblemFile p = readProblemFile(dir.write("v.cfg", text));
  ASSERT_EQ(p.planners.size(), 2u);
  ASSERT_EQ(p.warnings.size(), 1u);
  EXPECT_NE(p.warnings[0].find(":20: key 'planner.rrtconnect': a planner line takes no value ('rrtconnect =', "
                               "parameters as 'rrtconnect.range = ...'); 'yes' ignored"),
            std::string::npos)
      << p.warnings[0];
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
  // UTF-16 (Windows Notepad may save one) is named, with the way to convert it.
  std::string utf16 = "\xFE\xFF";
  for (const char c : std::string(kSe3Start)) utf16 += std::string{'\0', c};
  EXPECT_EQ(errorOf(utf16), ": the file is UTF-16BE text; save it as UTF-8 (iconv -f UTF-16BE -t UTF-8)");
}

TEST(ProblemFileErrors, NumbersMustBeDecimal) {
  // strtod would read these; OMPL's conversion throws on them, so neither place may take them.
  std::string hex = kSe3Start;
  hex.replace(hex.find("start.x = 1"), 11, "start.x = 0x10");
  EXPECT_EQ(errorOf(hex), ":4: key 'problem.start.x': expected a number, got '0x10'");
  std::string comma = kSe3Start;
  comma.replace(comma.find("goal.x = 0"), 10, "goal.x = 0,5");
  EXPECT_EQ(errorOf(comma), ":11: key 'problem.goal.x': expected a number, got '0,5'");
}

// Beyond 1e75 a state would be a pose the distance query refuses (and beyond 1e150 OMPL's maximum
// extent, which squares the volume's extents, would be infinite).
TEST(ProblemFileErrors, CoordinatesBeyondWhatTheQueryTakes) {
  std::string start = kSe3Start;
  start.replace(start.find("start.y = 2"), 11, "start.y = 1e200");
  EXPECT_EQ(errorOf(start),
            ":5: key 'problem.start.y': '1e200' is too large for a coordinate (at most 1e75 in magnitude, the "
            "distance query's limit)");
  EXPECT_EQ(errorOf(std::string(kSe3Start) +
                    "volume.min.x = -1e76\nvolume.min.y = 0\nvolume.min.z = 0\nvolume.max.x = 1\n"
                    "volume.max.y = 1\nvolume.max.z = 1\n"),
            ":18: key 'problem.volume.min.x': '-1e76' is too large for a coordinate (at most 1e75 in magnitude, the "
            "distance query's limit)");
}

TEST(ProblemFile, AnAxisOfExtremeMagnitudeIsStillARotation) {
  ScratchDir dir;
  std::string text = kSe3Start;
  text.replace(text.find("start.axis.z = 2"), 16, "start.axis.z = 1e300");
  text.replace(text.find("goal.axis.x = 1"), 15, "goal.axis.x = 1e-300");
  text.replace(text.find("goal.theta = 0"), 14, "goal.theta = 1.5707963267948966");
  const ProblemFile p = readProblemFile(dir.write("axis.cfg", text));
  const Pose start = p.start.toPose(), goal = p.goal.toPose();
  ASSERT_TRUE(start.matrix().allFinite());
  ASSERT_TRUE(goal.matrix().allFinite());
  EXPECT_TRUE((start.linear() * Vec3::UnitX()).isApprox(Vec3::UnitY()));  // 90 degrees about z
  EXPECT_TRUE((goal.linear() * Vec3::UnitY()).isApprox(Vec3::UnitZ()));   // 90 degrees about x
}

// Fuzz finding (tests/fuzz/regressions/problem_file/segment_fraction_out_of_range.cfg): a value
// passed through to OMPL's space information made OMPL throw its own exception ("The fraction of
// the extent must be larger than 0 and less than 1"), or one it cannot convert ("Failed
// converting string to real number", ompl_set_param_throws.cfg), escaping the library.
TEST(ProblemFileErrors, SpaceParametersOmplWouldRefuseNameTheKey) {
  const std::string key = ":18: key 'problem.longest_valid_segment_fraction': ";
  const std::string fraction = "expected a number > 0 and < 1 (OMPL's bounds: 2.2e-16 to 1 - 2.2e-16), got ";
  EXPECT_EQ(errorOf(std::string(kSe3Start) + "longest_valid_segment_fraction = 0\n"), key + fraction + "'0'");
  EXPECT_EQ(errorOf(std::string(kSe3Start) + "longest_valid_segment_fraction = 1\n"), key + fraction + "'1'");
  EXPECT_EQ(errorOf(std::string(kSe3Start) + "longest_valid_segment_fraction = 1e-17\n"), key + fraction + "'1e-17'");
  EXPECT_EQ(errorOf(std::string(kSe3Start) + "longest_valid_segment_fraction = 0,01\n"),
            key + "expected a number, got '0,01'");
  EXPECT_EQ(errorOf(std::string(kSe3Start) + "longest_valid_segment_fraction = 0.01\n"
                                             "longest_valid_segment_fraction = 0.02\n"),
            ":19: key 'problem.longest_valid_segment_fraction': repeated (first at line 18)");
  // A negative count would wrap to ~4e9 segments per motion (a hang), 1.5 would be read as 1.
  EXPECT_EQ(errorOf(std::string(kSe3Start) + "valid_segment_count_factor = -3\n"),
            ":18: key 'problem.valid_segment_count_factor': expected a whole number from 1 to 4294967295, got '-3'");
  EXPECT_EQ(errorOf(std::string(kSe3Start) + "valid_segment_count_factor = 1.5\n"),
            ":18: key 'problem.valid_segment_count_factor': expected a whole number from 1 to 4294967295, got '1.5'");
  EXPECT_EQ(errorOf(std::string(kSe3Start) + "valid_segment_count_factor = 0\n"),
            ":18: key 'problem.valid_segment_count_factor': expected a whole number from 1 to 4294967295, got '0'");
}

// Adversarial review: Boost keeps the spaces of "[ problem ]", so its keys were reported missing
// ("key 'problem.start.x' is missing") while the file plainly has them.
TEST(ProblemFileErrors, SectionHeaderWithSpacesInsideItsBracketsIsNamed) {
  std::string text = kSe3Start;
  text.replace(0, std::string("[problem]").size(), "[ problem ]");
  EXPECT_EQ(errorOf(text), ":1: section header '[ problem ]' has spaces inside its brackets, which make another "
                           "section (write '[problem]')");
}

// Adversarial review: OMPL accepts a fraction down to 2.2e-16, but a discrete motion check ignores
// the planner's time limit, and `adsd plan --time 1` with a fraction of 1e-8 ran for minutes.
TEST(ProblemFileErrors, MotionsCheckedInTooManyStatesNameTheKey) {
  const std::string tooMany = ": a motion across the space would be checked in that many states (at most 100000)";
  EXPECT_EQ(errorOf(std::string(kSe3Start) + "longest_valid_segment_fraction = 1e-8\n"),
            ":18: key 'problem.longest_valid_segment_fraction': valid_segment_count_factor / "
            "longest_valid_segment_fraction is 1e+08" + tooMany);
  // With OMPL's default fraction (0.01), a factor of 10 000 000 checks 1e9 states.
  EXPECT_EQ(errorOf(std::string(kSe3Start) + "valid_segment_count_factor = 10000000\n"),
            ":18: key 'problem.valid_segment_count_factor': valid_segment_count_factor / "
            "longest_valid_segment_fraction is 1e+09" + tooMany);
  EXPECT_EQ(errorOf(std::string(kSe3Start) + "longest_valid_segment_fraction = 0.001\nvalid_segment_count_factor = 1000\n"),
            ":18: key 'problem.longest_valid_segment_fraction': valid_segment_count_factor / "
            "longest_valid_segment_fraction is 1e+06" + tooMany);
  ScratchDir dir;
  EXPECT_NO_THROW(readProblemFile(dir.write("a.cfg", std::string(kSe3Start) + "longest_valid_segment_fraction = 2e-5\n")));
  EXPECT_NO_THROW(readProblemFile(
      dir.write("b.cfg", std::string(kSe3Start) + "longest_valid_segment_fraction = 0.001\nvalid_segment_count_factor = 50\n")));
}

TEST(ProblemFileErrors, PlannerParametersOmplWouldMisreadNameTheKey) {
  const std::string planners = std::string(kSe3Start) + "[planner]\nprm =\nrrtstar =\nkpiece =\n";
  // PRM: -1 wraps to 2^32 - 1 neighbours (std::bad_alloc); 1e3 would be read as 1.
  EXPECT_EQ(errorOf(planners + "prm.max_nearest_neighbors = -1\n"),
            ":22: key 'planner.prm.max_nearest_neighbors': expected a whole number from 0 to 4294967295, got '-1'");
  EXPECT_EQ(errorOf(planners + "prm.max_nearest_neighbors = 1e3\n"),
            ":22: key 'planner.prm.max_nearest_neighbors': expected a whole number from 0 to 4294967295, got '1e3'");
  EXPECT_EQ(errorOf(planners + "prm.max_nearest_neighbors = 4294967296\n"),
            ":22: key 'planner.prm.max_nearest_neighbors': expected a whole number from 0 to 4294967295, got "
            "'4294967296'");
  EXPECT_EQ(errorOf(planners + "rrtstar.range = -0.5\n"),
            ":22: key 'planner.rrtstar.range': expected a number >= 0, got '-0.5'");
  EXPECT_EQ(errorOf(planners + "rrtstar.range = inf\n"),
            ":22: key 'planner.rrtstar.range': expected a finite number, got 'inf'");
  EXPECT_EQ(errorOf(planners + "rrtstar.goal_bias = 1.5\n"),
            ":22: key 'planner.rrtstar.goal_bias': expected a number from 0 to 1, got '1.5'");
  // OMPL reads "no" as true.
  EXPECT_EQ(errorOf(planners + "rrtstar.delay_collision_checking = no\n"),
            ":22: key 'planner.rrtstar.delay_collision_checking': expected 0, 1, true or false, got 'no'");
  // KPIECE1::setBorderFraction throws outside (0, 1].
  EXPECT_EQ(errorOf(planners + "kpiece.border_fraction = 0\n"),
            ":22: key 'planner.kpiece.border_fraction': expected a number > 0 and <= 1, got '0'");
  // Taken by KPIECE's setters, refused by its set-up below machine epsilon: adsd plan ended in an
  // internal error (an adversarial review).
  EXPECT_EQ(errorOf(planners + "kpiece.min_valid_path_fraction = 0\n"),
            ":22: key 'planner.kpiece.min_valid_path_fraction': expected a number > 0 and <= 1 (OMPL's bounds: "
            "2.2e-16 to 1), got '0'");
  EXPECT_EQ(errorOf(planners + "kpiece.failed_expansion_score_factor = 1e-300\n"),
            ":22: key 'planner.kpiece.failed_expansion_score_factor': expected a number > 0 and <= 1 (OMPL's "
            "bounds: 2.2e-16 to 1), got '1e-300'");
  // Each of CForest's threads and AnytimePathShortening's planners is a planner of its own, built
  // before the time limit is watched: 100 000 ran minutes past a 0.2 s limit, or aborted.
  const std::string parallel = std::string(kSe3Start) + "[planner]\ncforest =\nanytimepathshortening =\n";
  EXPECT_EQ(errorOf(parallel + "cforest.num_threads = 257\n"),
            ":21: key 'planner.cforest.num_threads': expected a whole number from 1 to 256, got '257'");
  EXPECT_EQ(errorOf(parallel + "anytimepathshortening.num_planners = 100000\n"),
            ":21: key 'planner.anytimepathshortening.num_planners': expected a whole number from 1 to 256, got "
            "'100000'");
  // STRIDE's tree reserves its leaf size in every node: 2^31 ended in an internal error.
  EXPECT_EQ(errorOf(std::string(kSe3Start) + "[planner]\nstride =\nstride.max_pts_per_leaf = 2147483647\n"),
            ":20: key 'planner.stride.max_pts_per_leaf': expected a whole number from 1 to 1000, got '2147483647'");
}

TEST(ProblemFile, PlannerParametersOmplReadsAlikeAreKept) {
  ScratchDir dir;
  const ProblemFile p = readProblemFile(dir.write(
      "ok.cfg", std::string(kSe3Start) + "longest_valid_segment_fraction = 5e-3\nvalid_segment_count_factor = +2\n"
                                         "[planner]\nrrtstar =\nrrtstar.range = .5\nrrtstar.delay_collision_checking = "
                                         "False\nrrtstar.rewire_factor = 1.2E0\nprm =\nprm.max_nearest_neighbors = "
                                         "007\nanytimepathshortening =\nanytimepathshortening.planners = RRT,PRM\n"
                                         "rrtstar.no_such_parameter = whatever\n"));
  ASSERT_EQ(p.spaceParameters.size(), 2u);
  ASSERT_EQ(p.planners.size(), 3u);
  EXPECT_EQ(p.planners[0].parameters.size(), 4u);  // an unknown name is the planner's to ignore
  EXPECT_EQ(p.planners[2].parameters[0].value, "RRT,PRM");
}

TEST(ProblemFileErrors, TimeLimitsBeyondTheClock) {
  EXPECT_EQ(errorOf(std::string(kSe3Start) + "[benchmark]\ntime_limit = 1e300\n"),
            ":19: key 'benchmark.time_limit': '1e300' seconds is longer than the clock can count (at most 1e8)");
}

// Fuzz finding (tests/fuzz/regressions/problem_file/carriage_return_in_message.cfg): the three
// bytes ".\r." were echoed into the message, which then spanned two lines on a terminal.
TEST(ProblemFileErrors, ControlCharactersAreNamedNotEchoed) {
  EXPECT_EQ(errorOf(".\r.\n"), ":1: control character 0x0d at column 2 (keys and values are text on one line)");
  EXPECT_EQ(errorOf(std::string(kSe3Start) + "name = a\x1b[2Jb\n"),
            ":18: control character 0x1b at column 9 (keys and values are text on one line)");
  // Windows line ends are line ends.
  std::string crlf;
  for (const char c : std::string(kSe3Start)) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  ScratchDir dir;
  const ProblemFile p = readProblemFile(dir.write("crlf.cfg", crlf));
  EXPECT_EQ(p.robotPath, (dir.root() / "r.dae").string());
  EXPECT_EQ(p.goal.location.line, 11);
  // So are old Mac line ends (CR alone) in a file that has no LF, as the mesh readers take them
  // (text_scan.h): the whole file was one comment line, "no [problem] section".
  std::string cr = kSe3Start;
  std::replace(cr.begin(), cr.end(), '\n', '\r');
  const ProblemFile q = readProblemFile(dir.write("cr.cfg", cr));
  EXPECT_EQ(q.robotPath, (dir.root() / "r.dae").string());
  EXPECT_EQ(q.goal.location.line, 11);
}

TEST(ProblemFileErrors, LongValuesAreShortenedInMessages) {
  std::string text = kSe3Start;
  text.replace(text.find("start.y = 2"), 11, "start.y = " + std::string(500, 'x'));
  EXPECT_EQ(errorOf(text), ":5: key 'problem.start.y': expected a number, got '" + std::string(60, 'x') + "...'");
}

}  // namespace
}  // namespace adsd::planner
