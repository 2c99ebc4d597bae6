#include "adsd/problem_scenes.h"
#include "scene_parts.h"

namespace adsd::shapes {

// A room (inside 5 × 3 × 3, centred at the origin) halved by a wall at x = 0 with a window 0.5 m
// wide (y) and 0.8 m tall (z). The CGAL cow (1.0 × 0.61 × 0.33 m) is 0.61 m wide standing upright:
// it passes only rolled onto its side. Start (-1.5, 0, 0), goal (1.5, 0, 0), both upright.
ProblemScene cowDoorwayScene() {
  constexpr double hx = 2.5, hy = 1.5, hz = 1.5, t = 0.1, windowY = 0.25, windowZ = 0.4;
  SceneParts parts;
  parts.add(room(Vec3(hx, hy, hz), t, 4));
  parts.addBox(Vec3(-t / 2, -hy, windowZ), Vec3(t / 2, hy, hz));
  parts.addBox(Vec3(-t / 2, -hy, -hz), Vec3(t / 2, hy, -windowZ));
  parts.addBox(Vec3(-t / 2, -hy, -windowZ), Vec3(t / 2, -windowY, windowZ));
  parts.addBox(Vec3(-t / 2, windowY, -windowZ), Vec3(t / 2, hy, windowZ));
  return {"cow_doorway", {}, parts.merged()};
}

}  // namespace adsd::shapes
