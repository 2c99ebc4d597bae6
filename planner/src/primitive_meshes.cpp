#include "adsd/planner/primitive_meshes.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "adsd/error.h"

namespace adsd::planner {

namespace {

void requirePositive(double value, const char* what, const std::string& name) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw InputError(name + ": the " + what + " must be finite and > 0, got " + std::to_string(value));
  }
}

}  // namespace

Mesh boxMesh(const Vec3& size, const std::string& name) {
  for (int k = 0; k < 3; ++k) requirePositive(size[k], "box size", name);
  const Vec3 h = 0.5 * size;
  std::vector<Vec3> v;
  for (int i = 0; i < 8; ++i) {
    v.emplace_back((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(), (i & 4) ? h.z() : -h.z());
  }
  // Two triangles per face, wound outwards (the core accepts any winding; outwards is tidy).
  std::vector<TriangleIndices> t = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                                    {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return Mesh(std::move(v), std::move(t), name);
}

Mesh cylinderMesh(double radius, double length, const std::string& name) {
  requirePositive(radius, "cylinder radius", name);
  requirePositive(length, "cylinder length", name);
  // Circumscribed polygon: a regular n-gon whose edges touch the circle has its corners at
  // r / cos(pi / n), so the prism contains the cylinder.
  const int n = kCylinderSegments;
  const double pi = std::acos(-1.0);
  const double corner = radius / std::cos(pi / n);
  const double h = 0.5 * length;
  std::vector<Vec3> v;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * pi * i / n;
    v.emplace_back(corner * std::cos(a), corner * std::sin(a), -h);
    v.emplace_back(corner * std::cos(a), corner * std::sin(a), h);
  }
  const auto bottomCentre = static_cast<std::uint32_t>(v.size());
  v.emplace_back(0.0, 0.0, -h);
  const auto topCentre = static_cast<std::uint32_t>(v.size());
  v.emplace_back(0.0, 0.0, h);
  std::vector<TriangleIndices> t;
  for (int i = 0; i < n; ++i) {
    const auto b0 = static_cast<std::uint32_t>(2 * i), t0 = b0 + 1;
    const auto b1 = static_cast<std::uint32_t>(2 * ((i + 1) % n)), t1 = b1 + 1;
    t.push_back({b0, b1, t0});
    t.push_back({t0, b1, t1});
    t.push_back({bottomCentre, b1, b0});
    t.push_back({topCentre, t0, t1});
  }
  return Mesh(std::move(v), std::move(t), name);
}

Mesh sphereMesh(double radius, const std::string& name) {
  requirePositive(radius, "sphere radius", name);
  const int n = kSphereSegments, m = kSphereRings;
  const double pi = std::acos(-1.0);
  // A latitude-longitude sphere with its vertices on the unit sphere first: rings 1..m-1 between
  // the poles, n vertices each.
  std::vector<Vec3> v;
  v.emplace_back(0.0, 0.0, -1.0);
  for (int r = 1; r < m; ++r) {
    const double polar = pi * r / m;
    for (int i = 0; i < n; ++i) {
      const double a = 2.0 * pi * i / n;
      v.emplace_back(std::sin(polar) * std::cos(a), std::sin(polar) * std::sin(a), -std::cos(polar));
    }
  }
  v.emplace_back(0.0, 0.0, 1.0);
  const auto top = static_cast<std::uint32_t>(v.size() - 1);
  const auto at = [n](int ring, int i) { return static_cast<std::uint32_t>(1 + (ring - 1) * n + (i % n)); };
  std::vector<TriangleIndices> t;
  for (int i = 0; i < n; ++i) {
    t.push_back({0, at(1, i + 1), at(1, i)});
    for (int r = 1; r + 1 < m; ++r) {
      t.push_back({at(r, i), at(r, i + 1), at(r + 1, i)});
      t.push_back({at(r + 1, i), at(r, i + 1), at(r + 1, i + 1)});
    }
    t.push_back({top, at(m - 1, i), at(m - 1, i + 1)});
  }
  // The inscribed polytope's faces come closer to the centre than 1. Scaling by the inverse of the
  // nearest face plane's distance puts every face plane at least 1 away, so the convex polytope
  // holds the unit ball; then scale to the radius.
  double nearest = std::numeric_limits<double>::infinity();
  for (const TriangleIndices& tri : t) {
    const Vec3 normal = (v[tri[1]] - v[tri[0]]).cross(v[tri[2]] - v[tri[0]]).normalized();
    nearest = std::min(nearest, std::abs(normal.dot(v[tri[0]])));
  }
  for (Vec3& p : v) p *= radius / nearest;
  return Mesh(std::move(v), std::move(t), name);
}

}  // namespace adsd::planner
