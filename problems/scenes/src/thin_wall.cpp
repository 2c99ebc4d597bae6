#include "adsd/problem_scenes.h"
#include "scene_parts.h"

namespace adsd::shapes {

// An 8 × 8 arena split at x = 0 by a wall 2 cm thick that leaves a 2 m gap at the top
// (y in [2, 4]). The robot is a bar 2 cm thick and 0.8 m long. Start (-2.03, -1) and goal
// (1.97, -1) face each other through the wall: OMPL's discrete check of that straight motion
// samples states about 0.1 m apart and never lands on the 4 cm band where bar and wall overlap.
ProblemScene thinWallScene() {
  constexpr double halfThickness = 0.01, outer = 0.2, halfHeight = 1.0;
  SceneParts parts;
  const auto slab = [&](double x0, double y0, double x1, double y1) {
    parts.addBox(Vec3(x0, y0, -halfHeight), Vec3(x1, y1, halfHeight));
  };
  slab(-4 - outer, -4 - outer, 4 + outer, -4);
  slab(-4 - outer, 4, 4 + outer, 4 + outer);
  slab(-4 - outer, -4, -4, 4);
  slab(4, -4, 4 + outer, 4);
  slab(-halfThickness, -4, halfThickness, 2);
  return {"thin_wall", {centredOnVertexMean(box(Vec3(0.01, 0.4, 0.25)))}, parts.merged()};
}

}  // namespace adsd::shapes
