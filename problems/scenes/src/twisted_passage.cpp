#include <cmath>

#include "adsd/problem_scenes.h"
#include "scene_parts.h"

namespace adsd::shapes {

// A square tunnel along x (inside y, z in [-2, 2], x in [-5.5, 5.5]) crossed by three plates at
// x = -1.8, 0, 1.8. Each plate has a 2.8 × 0.7 slot, turned about x by 0°, 60° and 120°. The robot
// is a flat bar (0.6 × 2.2 × 0.24) that fits a slot only when aligned with it, so it must twist
// between the plates. Start (-4, 0, 0), goal (4, 0, 0) turned by 120° about x.
ProblemScene twistedPassageScene() {
  constexpr double half = 2.0, t = 0.2, length = 5.5;
  constexpr double plate = 3.2, slotHalfWidth = 1.4, slotHalfHeight = 0.35, plateHalfThickness = 0.1;
  SceneParts parts;
  parts.addBox(Vec3(-length, -half - t, -half - t), Vec3(length, half + t, -half));
  parts.addBox(Vec3(-length, -half - t, half), Vec3(length, half + t, half + t));
  parts.addBox(Vec3(-length, -half - t, -half), Vec3(length, -half, half));
  parts.addBox(Vec3(-length, half, -half), Vec3(length, half + t, half));
  const double xs[] = {-1.8, 0.0, 1.8};
  for (int k = 0; k < 3; ++k) {
    Pose frame = Pose::Identity();
    frame.translate(Vec3(xs[k], 0, 0));
    frame.rotate(Eigen::AngleAxisd(k * M_PI / 3.0, Vec3::UnitX()));
    const double x0 = -plateHalfThickness, x1 = plateHalfThickness;
    parts.addBox(Vec3(x0, -plate, slotHalfHeight), Vec3(x1, plate, plate), frame);
    parts.addBox(Vec3(x0, -plate, -plate), Vec3(x1, plate, -slotHalfHeight), frame);
    parts.addBox(Vec3(x0, -plate, -slotHalfHeight), Vec3(x1, -slotHalfWidth, slotHalfHeight), frame);
    parts.addBox(Vec3(x0, slotHalfWidth, -slotHalfHeight), Vec3(x1, plate, slotHalfHeight), frame);
  }
  return {"twisted_passage", {centredOnVertexMean(box(Vec3(0.3, 1.1, 0.12)))}, parts.merged()};
}

}  // namespace adsd::shapes
