#include "adsd/problem_scenes.h"
#include "scene_parts.h"

namespace adsd::shapes {

// Floor plan (metres): a 20 × 12 room; two rows of four cubicles (4 × 2.5 each) face a 2 m
// corridor along y = 0; each cubicle's front has a 1.4 m door. The robot (a 1 × 0.4 cart) starts in
// the top-left cubicle, (-6, 2.5), and must reach the bottom-right one, (6, -2.5).
ProblemScene officeScene() {
  constexpr double wall = 0.1;        // partition thickness
  constexpr double outer = 0.2;       // outer wall thickness
  constexpr double halfHeight = 1.0;  // walls span z in [-1, 1]
  constexpr double door = 1.4;
  SceneParts parts;
  const auto slab = [&](double x0, double y0, double x1, double y1) {
    parts.addBox(Vec3(x0, y0, -halfHeight), Vec3(x1, y1, halfHeight));
  };
  // Outer walls.
  slab(-10 - outer, -6 - outer, 10 + outer, -6);
  slab(-10 - outer, 6, 10 + outer, 6 + outer);
  slab(-10 - outer, -6, -10, 6);
  slab(10, -6, 10 + outer, 6);
  // Cubicle rows: back wall at |y| = 3.5, front at |y| = 1.
  for (const double side : {1.0, -1.0}) {
    const double front = side * 1.0, back = side * 3.5;
    slab(-8, std::min(back, back + side * wall), 8, std::max(back, back + side * wall));
    for (int k = 0; k <= 4; ++k) {
      const double x = -8 + 4.0 * k;
      slab(x - wall / 2, std::min(front, back), x + wall / 2, std::max(front, back));
    }
    for (int k = 0; k < 4; ++k) {
      const double x0 = -8 + 4.0 * k, x1 = x0 + 4.0;
      const double doorLo = 0.5 * (x0 + x1) - door / 2, doorHi = 0.5 * (x0 + x1) + door / 2;
      const double y0 = std::min(front, front - side * wall), y1 = std::max(front, front - side * wall);
      slab(x0, y0, doorLo, y1);
      slab(doorHi, y0, x1, y1);
    }
  }
  ProblemScene scene{"office", {centredOnVertexMean(box(Vec3(0.5, 0.2, 0.3)))}, parts.merged()};
  return scene;
}

}  // namespace adsd::shapes
