#include "adsd/planner/convex_solids.h"

#include <algorithm>
#include <cmath>

#include "adsd/mesh_hierarchy.h"
#include "mesh_components.h"

namespace adsd::planner {

bool ConvexSolid::containsStrictly(const Vec3& p, double slack) const {
  if (!box.contains(p)) return false;
  for (const Eigen::Vector4d& plane : planes) {
    if (!(plane.head<3>().dot(p) < plane[3] - slack)) return false;
  }
  return true;
}

std::optional<ConvexSolid> convexSolidOf(const Mesh& mesh) {
  if (mesh.triangleCount() == 0 || !isClosedConvex(mesh)) return std::nullopt;
  ConvexSolid solid;
  solid.name = mesh.name();
  solid.box = mesh.bounds();
  // Thinner than this across a face is flat: isClosedConvex's own allowance (1e-9 of the extent).
  const double flat = 1e-9 * solid.box.sizes().maxCoeff();
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const Vec3 a = mesh.corner(t, 0);
    Vec3 normal = (mesh.corner(t, 1) - a).cross(mesh.corner(t, 2) - a);
    const double length = normal.norm();
    if (!(length > 0.0)) continue;  // no area, no plane
    normal /= length;
    // Out: away from the vertex farthest from the face's plane (faces may be wound either way;
    // every vertex lies on the inner side). None off the plane: a flat mesh, no solid.
    double farthest = 0.0;
    for (const Vec3& v : mesh.vertices()) {
      const double off = normal.dot(v - a);
      if (std::abs(off) > std::abs(farthest)) farthest = off;
    }
    if (!(std::abs(farthest) > flat)) return std::nullopt;
    if (farthest > 0.0) normal = -normal;
    solid.planes.emplace_back(normal.x(), normal.y(), normal.z(), normal.dot(a));
  }
  if (solid.planes.empty()) return std::nullopt;
  return solid;
}

std::vector<Vec3> vertexPerComponent(const Mesh& mesh) {
  std::vector<Vec3> points;
  for (const std::vector<std::size_t>& component : connectedComponents(mesh)) {
    points.push_back(mesh.corner(component.front(), 0));
  }
  return points;
}

}  // namespace adsd::planner
