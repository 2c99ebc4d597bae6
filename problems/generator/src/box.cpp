#include "adsd/shapes.h"

#include "box_surface.h"
#include "ring_sweep.h"

namespace adsd::shapes {

Mesh box(const Vec3& halfExtents) {
  for (int axis = 0; axis < 3; ++axis) detail::requirePositive("box", "halfExtents", halfExtents[axis]);
  return detail::boxSurface(halfExtents, 1, "box");
}

}  // namespace adsd::shapes
