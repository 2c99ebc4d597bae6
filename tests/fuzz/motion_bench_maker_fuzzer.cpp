// Fuzz target: the MotionBenchMaker-format readers (issue 17): the MoveIt PlanningScene YAML
// reader, the MotionPlanRequest YAML reader and our arm problem .cfg reader, each on a file as
// users give it. The first byte picks the reader (even: scene, odd with bit 1 clear: request,
// else: cfg); the rest is the file. Properties: a scene whose meshes have finite vertices within
// 1e7 of the origin and at least one triangle each, named by the object ids, with one frame and
// line per object; a request whose numbers are finite with tolerances >= 0 and a positive
// planning time; a cfg with non-empty paths; or one adsd::InputError whose one-line message
// starts with the file's path; nothing else, no crash, no hang.
#include <cmath>
#include <string>

#include "adsd/planner/motion_bench_maker_problem.h"
#include "adsd/planner/motion_plan_request_yaml.h"
#include "adsd/planner/planning_scene_yaml.h"
#include "fuzz_support.h"

namespace {

using adsd::fuzz::violation;

void checkScene(const adsd::planner::PlanningSceneYaml& scene) {
  if (scene.frames.size() != scene.objects.size() || scene.lines.size() != scene.objects.size()) {
    violation("a scene's frames or lines do not match its objects");
  }
  for (const adsd::Mesh& m : scene.objects) {
    if (m.triangleCount() == 0) violation("a scene object without triangles");
    if (m.name().empty()) violation("a scene object without an id");
    for (const adsd::Vec3& v : m.vertices()) {
      // Coordinates and lengths within 1e6, through at most one object pose and one shape pose.
      if (!v.allFinite() || v.cwiseAbs().maxCoeff() > 1e7) violation("a scene vertex not finite or beyond 1e7");
    }
  }
  for (const auto& [joint, value] : scene.defaultJointValues) {
    if (!std::isfinite(value)) violation("a default joint value is not finite");
  }
}

void checkRequest(const adsd::planner::MotionPlanRequestYaml& r) {
  if (r.groupName.empty() || r.start.empty() || r.goal.empty()) violation("a request without group, start or goal");
  for (const auto& [joint, value] : r.start) {
    if (!std::isfinite(value)) violation("a start value is not finite");
  }
  for (const auto& [joint, g] : r.goal) {
    if (!std::isfinite(g.position) || !(g.toleranceAbove >= 0.0) || !(g.toleranceBelow >= 0.0) ||
        !std::isfinite(g.toleranceAbove) || !std::isfinite(g.toleranceBelow)) {
      violation("a goal value or tolerance is not finite and >= 0");
    }
  }
  if (r.allowedPlanningTime && !(*r.allowedPlanningTime > 0.0 && std::isfinite(*r.allowedPlanningTime))) {
    violation("a planning time not finite and > 0");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const adsd::fuzz::ScratchDirectory scratch;
  if (size == 0) return 0;
  const std::uint8_t which = data[0];
  if (which % 2 == 0) {
    const std::string path = scratch.write("scene.yaml", data + 1, size - 1);
    adsd::fuzz::acceptingOnlyInputError(path, [&] { checkScene(adsd::planner::readPlanningSceneYaml(path)); });
  } else if ((which & 2) == 0) {
    const std::string path = scratch.write("request.yaml", data + 1, size - 1);
    adsd::fuzz::acceptingOnlyInputError(path, [&] { checkRequest(adsd::planner::readMotionPlanRequestYaml(path)); });
  } else {
    const std::string path = scratch.write("problem.cfg", data + 1, size - 1);
    adsd::fuzz::acceptingOnlyInputError(path, [&] {
      const adsd::planner::MotionBenchMakerProblem p = adsd::planner::readMotionBenchMakerProblem(path);
      if (p.robotPath.empty() || p.scenePath.empty() || p.requestPath.empty()) violation("an empty path");
    });
  }
  return 0;
}
