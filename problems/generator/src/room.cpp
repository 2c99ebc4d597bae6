#include "adsd/shapes.h"

#include "box_surface.h"
#include "ring_sweep.h"

namespace adsd::shapes {

Mesh room(const Vec3& halfExtents, double wallThickness, int divisions) {
  for (int axis = 0; axis < 3; ++axis) detail::requirePositive("room", "halfExtents", halfExtents[axis]);
  detail::requirePositive("room", "wallThickness", wallThickness);
  detail::requireAtLeast("room", "divisions", divisions, 1);

  // The walls are a solid between two box surfaces: the outer one faces outwards as usual, the
  // inner one (the surface the object in the room sees) faces into the cavity, i.e. away from the
  // wall material. Both shells are closed, so the room is a closed solid with a hole inside.
  const Mesh outer = detail::boxSurface(halfExtents + Vec3::Constant(wallThickness), divisions, "room");
  const Mesh inner = detail::boxSurface(halfExtents, divisions, "room");
  std::vector<Vec3> vertices = outer.vertices();
  std::vector<TriangleIndices> triangles = outer.triangles();
  const auto offset = static_cast<std::uint32_t>(vertices.size());
  vertices.insert(vertices.end(), inner.vertices().begin(), inner.vertices().end());
  for (const TriangleIndices& t : inner.triangles()) {
    triangles.push_back({t[0] + offset, t[2] + offset, t[1] + offset});  // reversed: faces inwards
  }
  return Mesh(std::move(vertices), std::move(triangles), "room");
}

}  // namespace adsd::shapes
