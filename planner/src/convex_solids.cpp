#include "adsd/planner/convex_solids.h"

#include <numeric>

#include "adsd/mesh_hierarchy.h"

namespace adsd::planner {

namespace {

/// The connected components of a mesh's triangles (by shared vertex index), each a list of
/// triangles, in order of first appearance.
std::vector<std::vector<std::uint32_t>> triangleComponents(const Mesh& mesh) {
  std::vector<std::uint32_t> parent(mesh.vertices().size());
  std::iota(parent.begin(), parent.end(), 0u);
  const auto root = [&parent](std::uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const TriangleIndices& t : mesh.triangles()) {
    for (int k = 1; k < 3; ++k) parent[root(t[k])] = root(t[0]);
  }
  std::vector<std::int64_t> componentOfRoot(parent.size(), -1);
  std::vector<std::vector<std::uint32_t>> components;
  for (std::uint32_t t = 0; t < mesh.triangleCount(); ++t) {
    const std::uint32_t r = root(mesh.triangles()[t][0]);
    if (componentOfRoot[r] < 0) {
      componentOfRoot[r] = static_cast<std::int64_t>(components.size());
      components.emplace_back();
    }
    components[static_cast<std::size_t>(componentOfRoot[r])].push_back(t);
  }
  return components;
}

}  // namespace

bool ConvexSolid::containsStrictly(const Vec3& p, double slack) const {
  if (!box.contains(p)) return false;
  for (const Eigen::Vector4d& plane : planes) {
    if (!(plane.head<3>().dot(p) < plane[3] - slack)) return false;
  }
  return true;
}

std::vector<ConvexSolid> convexSolidsOf(const Mesh& mesh) {
  std::vector<ConvexSolid> solids;
  for (const std::vector<std::uint32_t>& component : triangleComponents(mesh)) {
    // The component as a mesh of its own, its vertices renumbered, for isClosedConvex.
    std::vector<std::uint32_t> index(mesh.vertices().size(), UINT32_MAX);
    std::vector<Vec3> vertices;
    std::vector<TriangleIndices> triangles;
    for (std::uint32_t t : component) {
      TriangleIndices renumbered;
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t v = mesh.triangles()[t][k];
        if (index[v] == UINT32_MAX) {
          index[v] = static_cast<std::uint32_t>(vertices.size());
          vertices.push_back(mesh.vertices()[v]);
        }
        renumbered[k] = index[v];
      }
      triangles.push_back(renumbered);
    }
    const Mesh part(vertices, triangles, mesh.name());
    if (!isClosedConvex(part)) continue;
    ConvexSolid solid;
    solid.name = mesh.name();
    solid.box = part.bounds();
    // Outward: away from the vertices' mean, which lies inside a closed convex solid; faces may
    // be wound either way.
    const Vec3 mean = std::accumulate(vertices.begin(), vertices.end(), Vec3(Vec3::Zero())) /
                      static_cast<double>(vertices.size());
    for (std::size_t t = 0; t < part.triangleCount(); ++t) {
      const Vec3 a = part.corner(t, 0);
      Vec3 normal = (part.corner(t, 1) - a).cross(part.corner(t, 2) - a);
      const double length = normal.norm();
      if (!(length > 0.0)) continue;  // no area, no plane
      normal /= length;
      if (normal.dot(mean - a) > 0.0) normal = -normal;
      solid.planes.emplace_back(normal.x(), normal.y(), normal.z(), normal.dot(a));
    }
    if (!solid.planes.empty()) solids.push_back(std::move(solid));
  }
  return solids;
}

std::vector<Vec3> vertexPerComponent(const Mesh& mesh) {
  std::vector<Vec3> points;
  for (const std::vector<std::uint32_t>& component : triangleComponents(mesh)) {
    points.push_back(mesh.corner(component.front(), 0));
  }
  return points;
}

}  // namespace adsd::planner
