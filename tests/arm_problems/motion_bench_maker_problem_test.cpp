// Our arm problem .cfg: keys, paths relative to the cfg, ${ADSD_ROBOTS} and other variables,
// package_path, and the errors naming file and line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <string>

#include "adsd/error.h"
#include "adsd/planner/motion_bench_maker_problem.h"
#include "reader_errors.h"
#include "scratch_dir.h"

namespace adsd::planner {
namespace {

/// Sets an environment variable for the scope of the test and restores it after.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old, had_ = true;
    if (value != nullptr) {
      setenv(name, value, 1);
    } else {
      unsetenv(name);
    }
  }
  ~ScopedEnv() {
    if (had_) {
      setenv(name_.c_str(), old_.c_str(), 1);
    } else {
      unsetenv(name_.c_str());
    }
  }

 private:
  std::string name_, old_;
  bool had_ = false;
};

const char* kCfg = R"(# an arm problem
[problem]
name = kr5_table
robot = ${ADSD_ROBOTS}/KR5/KR5 sixx R650.urdf
srdf = kr5.srdf
scene = scene.yaml     # beside the cfg
request = sub/../request.yaml
package_path = ${ADSD_ROBOTS}:extra
)";

TEST(MotionBenchMakerProblem, ResolvesPathsAndTheRobotsVariable) {
  ScopedEnv robots("ADSD_ROBOTS", "/opt/robots");
  const MotionBenchMakerProblem p = parseMotionBenchMakerProblem(kCfg, "/p/x.cfg", "/p");
  EXPECT_EQ(p.name, "kr5_table");
  EXPECT_EQ(p.robotPath, "/opt/robots/KR5/KR5 sixx R650.urdf");
  ASSERT_TRUE(p.srdfPath.has_value());
  EXPECT_EQ(*p.srdfPath, "/p/kr5.srdf");
  EXPECT_EQ(p.scenePath, "/p/scene.yaml");
  EXPECT_EQ(p.requestPath, "/p/request.yaml");
  ASSERT_EQ(p.packagePath.size(), 2u);
  EXPECT_EQ(p.packagePath[0], "/opt/robots");
  EXPECT_EQ(p.packagePath[1], "/p/extra");
  EXPECT_EQ(p.robotLocation.line, 4);
  EXPECT_TRUE(p.warnings.empty());
}

// Classic Mac OS text (CR alone, no LF) has line ends, as a mesh file has.
TEST(MotionBenchMakerProblem, LoneCarriageReturnsEndLines) {
  ScopedEnv robots("ADSD_ROBOTS", "/opt/robots");
  std::string text = kCfg;
  std::replace(text.begin(), text.end(), '\n', '\r');
  const MotionBenchMakerProblem p = parseMotionBenchMakerProblem(text, "/p/x.cfg", "/p");
  EXPECT_EQ(p.robotPath, "/opt/robots/KR5/KR5 sixx R650.urdf");
  EXPECT_EQ(p.requestPath, "/p/request.yaml");
  EXPECT_EQ(p.robotLocation.line, 4);
}

TEST(MotionBenchMakerProblem, RobotsDefaultToTheCacheUnderHome) {
  ScopedEnv robots("ADSD_ROBOTS", nullptr);
  ScopedEnv home("HOME", "/home/someone");
  const MotionBenchMakerProblem p = parseMotionBenchMakerProblem(kCfg, "/p/x.cfg", "/p");
  EXPECT_EQ(p.robotPath, "/home/someone/.cache/adsd/robots/KR5/KR5 sixx R650.urdf");
  EXPECT_EQ(defaultRobotsDirectory(), "/home/someone/.cache/adsd/robots");
}

TEST(MotionBenchMakerProblem, OtherVariablesComeFromTheEnvironment) {
  ScopedEnv v("ADSD_TEST_SCENES", "/scenes");
  const SourceLocation at{"f.cfg", 3, "problem.scene"};
  EXPECT_EQ(expandPathVariables("${ADSD_TEST_SCENES}/a/${ADSD_TEST_SCENES}", at), "/scenes/a//scenes");
  EXPECT_EQ(expandPathVariables("no variables", at), "no variables");
}

TEST(MotionBenchMakerProblem, ReadsAFileAndNamesItByItsStem) {
  test::ScratchDir dir;
  const MotionBenchMakerProblem p =
      readMotionBenchMakerProblem(dir.write("shelf.cfg", "[problem]\nrobot = r.urdf\nscene = s.yaml\nrequest = q.yaml\n"));
  EXPECT_EQ(p.name, "shelf");
  EXPECT_EQ(p.robotPath, dir.path("r.urdf"));
  EXPECT_FALSE(p.srdfPath.has_value());
  EXPECT_TRUE(p.packagePath.empty());
}

std::string errorOf(const std::string& text) {
  return test::errorAfterName([](const std::string& t) { parseMotionBenchMakerProblem(t, "arm.cfg", "/p"); }, text,
                              "arm.cfg");
}

TEST(MotionBenchMakerProblemErrors, EachNamesTheFileAndLine) {
  EXPECT_EQ(errorOf("[problem]\nrobot = r\nscene = s\n"), ":1: key 'problem.request' is missing from the [problem] section");
  EXPECT_EQ(errorOf("[problem]\nrobot = r\nscene = s\nrequest = q\nscene = t\n"),
            ":5: key 'problem.scene': repeated (first at line 3)");
  EXPECT_EQ(errorOf("[problem]\nrobot =\n"), ":2: key 'problem.robot': the value is empty");
  EXPECT_EQ(errorOf("robot = r\n"), ":1: key 'robot': outside the [problem] section");
  EXPECT_EQ(errorOf("[problem]\nrobot r\n"), ":2: expected 'key = value', a [section] or a comment");
  EXPECT_EQ(errorOf("[problem]\nrobot = ${ADSD_NO_SUCH_VARIABLE_17}/r\nscene = s\nrequest = q\n"),
            ":2: key 'problem.robot': the environment variable 'ADSD_NO_SUCH_VARIABLE_17' is not set (only "
            "${ADSD_ROBOTS} has a default)");
  EXPECT_EQ(errorOf("[problem]\nrobot = r\nscene = ${ADSD_ROBOTS\nrequest = q\n"),
            ":3: key 'problem.scene': '${' without a closing '}'");
  EXPECT_EQ(errorOf("[problem]\nrobot = r\x01\n"), ":2: control character 0x01 (keys and values are text on one line)");
  EXPECT_EQ(errorOf(std::string("[problem]\nrobot = r\0\n", 20)), ": not a text file (contains a NUL byte)");
}

TEST(MotionBenchMakerProblemErrors, UnknownKeysAndSectionsAreWarnings) {
  const MotionBenchMakerProblem p =
      parseMotionBenchMakerProblem("[problem]\nrobot = r\nscene = s\nrequest = q\nspeed = 3\n[other]\nx = 1\n", "w.cfg", "");
  ASSERT_EQ(p.warnings.size(), 2u);
  EXPECT_EQ(p.warnings[0], "w.cfg:6: unknown section [other], its keys ignored");
  EXPECT_EQ(p.warnings[1], "w.cfg:5: key 'problem.speed': unknown key, ignored");
}

}  // namespace
}  // namespace adsd::planner
