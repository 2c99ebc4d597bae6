#include "adsd/planner/primitive_meshes.h"

#include <cmath>
#include <vector>

namespace adsd::planner {

namespace {

/// Rings of vertices joined band by band, closed by fans to a top and a bottom vertex: the shape
/// of both the cylinder (two rings) and the UV sphere (bands - 1 rings). Rings run from top to
/// bottom, counter-clockwise seen from +z, so that every triangle winds outward.
Mesh ringsAndPoles(const std::vector<std::vector<Vec3>>& rings, const Vec3& top, const Vec3& bottom,
                   const std::string& name) {
  const auto n = static_cast<std::uint32_t>(rings.front().size());
  std::vector<Vec3> vertices;
  for (const auto& ring : rings) vertices.insert(vertices.end(), ring.begin(), ring.end());
  const auto topIndex = static_cast<std::uint32_t>(vertices.size());
  vertices.push_back(top);
  vertices.push_back(bottom);
  const std::uint32_t bottomIndex = topIndex + 1;
  std::vector<TriangleIndices> triangles;
  for (std::uint32_t k = 0; k < n; ++k) {
    const std::uint32_t next = (k + 1) % n;
    triangles.push_back({topIndex, k, next});
    for (std::uint32_t r = 0; r + 1 < rings.size(); ++r) {
      const std::uint32_t a = r * n + k, b = r * n + next, c = (r + 1) * n + k, d = (r + 1) * n + next;
      triangles.push_back({a, c, d});
      triangles.push_back({a, d, b});
    }
    const auto last = static_cast<std::uint32_t>(rings.size() - 1) * n;
    triangles.push_back({bottomIndex, last + next, last + k});
  }
  return Mesh(std::move(vertices), std::move(triangles), name);
}

}  // namespace

Mesh boxMesh(const Vec3& size, const std::string& name) {
  const Vec3 h = size / 2;
  std::vector<Vec3> v;
  for (int i = 0; i < 8; ++i) v.emplace_back(i & 1 ? h.x() : -h.x(), i & 2 ? h.y() : -h.y(), i & 4 ? h.z() : -h.z());
  // Two triangles per face, wound outward (vertex i has bit 0 for +x, bit 1 for +y, bit 2 for +z).
  std::vector<TriangleIndices> t = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                                    {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  return Mesh(std::move(v), std::move(t), name);
}

Mesh cylinderMesh(double height, double radius, const std::string& name) {
  // Circumscribed prism: the sides' mid-lines touch the cylinder when the corners lie at
  // radius / cos(pi / n).
  const double corner = radius / std::cos(M_PI / kPrimitiveSegments);
  std::vector<std::vector<Vec3>> rings(2);
  for (int k = 0; k < kPrimitiveSegments; ++k) {
    const double a = 2.0 * M_PI * k / kPrimitiveSegments;
    rings[0].emplace_back(corner * std::cos(a), corner * std::sin(a), height / 2);
    rings[1].emplace_back(corner * std::cos(a), corner * std::sin(a), -height / 2);
  }
  return ringsAndPoles(rings, Vec3(0, 0, height / 2), Vec3(0, 0, -height / 2), name);
}

Mesh sphereMesh(double radius, const std::string& name) {
  // A face of the UV sphere spans at most pi / segments of azimuth either side of its middle and
  // pi / (2 bands) of latitude: its plane lies at least cos(pi / segments) cos(pi / (2 bands))
  // of the vertices' radius from the centre (equality on the equator's faces), so vertices at
  // radius / that product put every face at least `radius` out.
  const double scaled = radius / (std::cos(M_PI / kPrimitiveSegments) * std::cos(M_PI / (2 * kSphereBands)));
  std::vector<std::vector<Vec3>> rings;
  for (int i = 1; i < kSphereBands; ++i) {
    const double polar = M_PI * i / kSphereBands;
    std::vector<Vec3> ring;
    for (int k = 0; k < kPrimitiveSegments; ++k) {
      const double a = 2.0 * M_PI * k / kPrimitiveSegments;
      ring.emplace_back(scaled * std::sin(polar) * std::cos(a), scaled * std::sin(polar) * std::sin(a),
                        scaled * std::cos(polar));
    }
    rings.push_back(std::move(ring));
  }
  return ringsAndPoles(rings, Vec3(0, 0, scaled), Vec3(0, 0, -scaled), name);
}

}  // namespace adsd::planner
