// Fuzz target: the OMPL.app `.cfg` reader (adsd::planner::readProblemFile, from a file as users
// give it) and, when a file parses and names the two meshes this target provides, the problem
// built from it (adsd::planner::PlanningProblem: bounds, space parameters handed to OMPL,
// objective, start and goal checked). Properties: a ProblemFile whose numbers are finite, or one
// adsd::InputError whose one-line message starts with the file's path; the same for the problem;
// nothing else (an OMPL exception escaping would break the rule), no crash, no hang.
#include <cmath>
#include <filesystem>
#include <string>

#include <ompl/util/Console.h>

#include "adsd/planner/planning_problem.h"
#include "adsd/planner/problem_file.h"
#include "fuzz_support.h"

namespace {

namespace fs = std::filesystem;
using adsd::fuzz::violation;

// The meshes a fuzzed problem may name (the seeds do): a 0.2 x 0.2 x 0.2 box for the robot, and
// two boxes 1 apart along x for the world, so that start and goal states can be free or in
// collision depending on the numbers.
const char* kRobotObj =
    "v -0.1 -0.1 -0.1\nv 0.1 -0.1 -0.1\nv 0.1 0.1 -0.1\nv -0.1 0.1 -0.1\n"
    "v -0.1 -0.1 0.1\nv 0.1 -0.1 0.1\nv 0.1 0.1 0.1\nv -0.1 0.1 0.1\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
const char* kWorldObj =
    "v -1 -1 -1\nv -0.5 -1 -1\nv -0.5 1 -1\nv -1 1 -1\nv -1 -1 1\nv -0.5 -1 1\nv -0.5 1 1\nv -1 1 1\n"
    "v 0.5 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv 0.5 1 -1\nv 0.5 -1 1\nv 1 -1 1\nv 1 1 1\nv 0.5 1 1\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n"
    "f 9 12 11 10\nf 13 14 15 16\nf 9 10 14 13\nf 10 11 15 14\nf 11 12 16 15\nf 12 9 13 16\n";

void requireFinite(const adsd::planner::ProblemFile& p) {
  for (const adsd::planner::ProblemPose* pose : {&p.start, &p.goal}) {
    if (!pose->position.allFinite() || !std::isfinite(pose->theta) || !pose->axis.allFinite()) {
      violation("a parsed start or goal is not finite");
    }
    if (!pose->toPose().matrix().allFinite()) violation("a parsed start or goal gives a non-finite pose");
  }
  if (p.volume && (!p.volume->min().allFinite() || !p.volume->max().allFinite())) {
    violation("the parsed volume is not finite");
  }
}

/// Whether \p path is one of the meshes in the scratch directory: only those are loaded, so that a
/// fuzzed path never makes the target read arbitrary files of the machine.
bool isProvidedMesh(const std::string& path, const adsd::fuzz::ScratchDirectory& scratch) {
  return path == scratch.path("robot.obj") || path == scratch.path("world.obj");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const adsd::fuzz::ScratchDirectory scratch;
  static const bool prepared = [] {
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    scratch.write("robot.obj", reinterpret_cast<const std::uint8_t*>(kRobotObj), std::string(kRobotObj).size());
    scratch.write("world.obj", reinterpret_cast<const std::uint8_t*>(kWorldObj), std::string(kWorldObj).size());
    return true;
  }();
  (void)prepared;

  const std::string path = scratch.write("problem.cfg", data, size);
  adsd::fuzz::acceptingOnlyInputError(path, [&] {
    const adsd::planner::ProblemFile file = adsd::planner::readProblemFile(path);
    requireFinite(file);
    if (!isProvidedMesh(file.robotPath, scratch) || !isProvidedMesh(file.worldPath, scratch)) return;
    adsd::planner::CheckingOptions options;
    // The certified validator too (it reads the space's extent and the robot's radius).
    if (size > 0 && data[size - 1] % 2 == 1) options.motion = adsd::planner::MotionKind::certified;
    adsd::planner::PlanningProblem problem(file, options);
    (void)problem;
  });
  return 0;
}
