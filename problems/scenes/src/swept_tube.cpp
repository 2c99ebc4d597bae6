#include <cmath>

#include "adsd/error.h"
#include "adsd/problem_scenes.h"

namespace adsd::shapes {

Mesh sweptTube(const std::vector<Vec3>& centreLine, double radius, int sides) {
  if (centreLine.size() < 2 || sides < 3 || !(radius > 0.0)) {
    throw InputError("sweptTube: needs at least 2 points, 3 sides and a positive radius");
  }
  const std::size_t n = centreLine.size();
  std::vector<Vec3> tangents(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 d = centreLine[std::min(i + 1, n - 1)] - centreLine[i == 0 ? 0 : i - 1];
    if (d.norm() == 0.0) throw InputError("sweptTube: repeated centre-line point " + std::to_string(i));
    tangents[i] = d.normalized();
  }
  // Parallel transport: each ring's normal is the previous one with its tangential part removed,
  // so the section turns no more than the centre line does.
  Vec3 normal = tangents[0].unitOrthogonal();
  std::vector<Vec3> vertices;
  std::vector<TriangleIndices> triangles;
  for (std::size_t i = 0; i < n; ++i) {
    normal = (normal - normal.dot(tangents[i]) * tangents[i]).normalized();
    const Vec3 binormal = tangents[i].cross(normal);
    for (int k = 0; k < sides; ++k) {
      const double a = 2.0 * M_PI * k / sides;
      vertices.push_back(centreLine[i] + radius * (std::cos(a) * normal + std::sin(a) * binormal));
    }
  }
  const auto ring = [sides](std::size_t i, int k) { return static_cast<std::uint32_t>(i * sides + (k % sides)); };
  for (std::size_t i = 0; i + 1 < n; ++i) {
    for (int k = 0; k < sides; ++k) {
      triangles.push_back({ring(i, k), ring(i + 1, k), ring(i + 1, k + 1)});
      triangles.push_back({ring(i, k), ring(i + 1, k + 1), ring(i, k + 1)});
    }
  }
  // Caps: a fan around each end's centre.
  const auto beginCentre = static_cast<std::uint32_t>(vertices.size());
  vertices.push_back(centreLine.front());
  const auto endCentre = static_cast<std::uint32_t>(vertices.size());
  vertices.push_back(centreLine.back());
  for (int k = 0; k < sides; ++k) {
    triangles.push_back({beginCentre, ring(0, k + 1), ring(0, k)});
    triangles.push_back({endCentre, ring(n - 1, k), ring(n - 1, k + 1)});
  }
  return Mesh(std::move(vertices), std::move(triangles), "swept tube");
}

}  // namespace adsd::shapes
