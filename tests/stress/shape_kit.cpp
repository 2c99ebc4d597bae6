#include "shape_kit.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "adsd/shapes.h"

namespace adsd::stress {

Mesh triangleMesh(const Vec3& p0, const Vec3& p1, const Vec3& p2, const std::string& name) {
  return Mesh({p0, p1, p2}, {TriangleIndices{0, 1, 2}}, name);
}

namespace {

/// lo + (hi - lo) k / n, but exactly lo at k = 0 and exactly hi at k = n (the faces of a grid box
/// must be exactly where the caller put them).
double gridLine(double lo, double hi, int k, int n) {
  if (k == 0) return lo;
  if (k == n) return hi;
  return lo + (hi - lo) * (double(k) / n);
}

}  // namespace

Mesh gridBox(const Vec3& lo, const Vec3& hi, int divisions) {
  const int n = std::max(1, divisions);
  std::vector<Vec3> vertices;
  std::vector<TriangleIndices> triangles;
  // Each of the six faces: fixed axis `axis` at lo or hi, grid over the two other axes, wound so
  // that the normal points out of the box.
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (int side = 0; side < 2; ++side) {
      const auto base = static_cast<std::uint32_t>(vertices.size());
      for (int i = 0; i <= n; ++i) {
        for (int j = 0; j <= n; ++j) {
          Vec3 p;
          p[axis] = side ? hi[axis] : lo[axis];
          p[u] = gridLine(lo[u], hi[u], i, n);
          p[v] = gridLine(lo[v], hi[v], j, n);
          vertices.push_back(p);
        }
      }
      auto at = [&](int i, int j) { return base + static_cast<std::uint32_t>(i * (n + 1) + j); };
      for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
          // (u, v, axis) is right-handed: counter-clockwise in (u, v) faces +axis.
          if (side) {
            triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
          } else {
            triangles.push_back({at(i, j), at(i + 1, j + 1), at(i + 1, j)});
            triangles.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1)});
          }
        }
      }
    }
  }
  return Mesh(std::move(vertices), std::move(triangles), "grid box");
}

Mesh plate(const Vec3& origin, const Vec3& u, const Vec3& v, int nu, int nv) {
  std::vector<Vec3> vertices;
  std::vector<TriangleIndices> triangles;
  for (int i = 0; i <= nu; ++i) {
    for (int j = 0; j <= nv; ++j) vertices.push_back(origin + (double(i) / nu) * u + (double(j) / nv) * v);
  }
  auto at = [&](int i, int j) { return static_cast<std::uint32_t>(i * (nv + 1) + j); };
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return Mesh(std::move(vertices), std::move(triangles), "plate");
}

Mesh polygonPrism(double radius, int sides, double length, int rings) {
  std::vector<Vec3> vertices;
  std::vector<TriangleIndices> triangles;
  for (int r = 0; r <= rings; ++r) {
    const double z = r == rings ? length : length * (double(r) / rings);
    for (int k = 0; k < sides; ++k) {
      const double angle = 2.0 * M_PI * k / sides;
      vertices.emplace_back(radius * std::cos(angle), radius * std::sin(angle), z);
    }
  }
  auto at = [&](int r, int k) { return static_cast<std::uint32_t>(r * sides + (k % sides)); };
  for (int r = 0; r < rings; ++r) {
    for (int k = 0; k < sides; ++k) {
      triangles.push_back({at(r, k), at(r, k + 1), at(r + 1, k + 1)});
      triangles.push_back({at(r, k), at(r + 1, k + 1), at(r + 1, k)});
    }
  }
  const auto bottom = static_cast<std::uint32_t>(vertices.size());
  vertices.emplace_back(0.0, 0.0, 0.0);
  const auto top = static_cast<std::uint32_t>(vertices.size());
  vertices.emplace_back(0.0, 0.0, length);
  for (int k = 0; k < sides; ++k) {
    triangles.push_back({bottom, at(0, k + 1), at(0, k)});
    triangles.push_back({top, at(rings, k), at(rings, k + 1)});
  }
  return Mesh(std::move(vertices), std::move(triangles), "prism");
}

Mesh transformedMesh(const Mesh& mesh, const Pose& transform) {
  std::vector<Vec3> vertices;
  vertices.reserve(mesh.vertices().size());
  for (const Vec3& v : mesh.vertices()) vertices.push_back(transform * v);
  return Mesh(std::move(vertices), mesh.triangles(), mesh.name());
}

Mesh offsetMesh(const Mesh& mesh, const Vec3& offset) {
  std::vector<Vec3> vertices;
  vertices.reserve(mesh.vertices().size());
  for (const Vec3& v : mesh.vertices()) vertices.push_back(v + offset);
  return Mesh(std::move(vertices), mesh.triangles(), mesh.name());
}

Mesh mergedMesh(const Mesh& a, const Mesh& b, const std::string& name) {
  std::vector<Vec3> vertices = a.vertices();
  std::vector<TriangleIndices> triangles = a.triangles();
  const auto shift = static_cast<std::uint32_t>(vertices.size());
  vertices.insert(vertices.end(), b.vertices().begin(), b.vertices().end());
  for (const TriangleIndices& t : b.triangles()) triangles.push_back({t[0] + shift, t[1] + shift, t[2] + shift});
  return Mesh(std::move(vertices), std::move(triangles), name);
}

Mesh permutedMesh(const Mesh& mesh, SeededRandom& random) {
  static constexpr int kOrders[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  const std::size_t n = mesh.vertices().size();
  std::vector<std::uint32_t> newIndex(n);
  std::iota(newIndex.begin(), newIndex.end(), 0u);
  std::shuffle(newIndex.begin(), newIndex.end(), random.engine());
  std::vector<Vec3> vertices(n);
  for (std::size_t i = 0; i < n; ++i) vertices[newIndex[i]] = mesh.vertices()[i];
  std::vector<TriangleIndices> triangles;
  triangles.reserve(mesh.triangleCount());
  for (const TriangleIndices& t : mesh.triangles()) {
    const int* o = kOrders[random.below(6)];
    triangles.push_back({newIndex[t[o[0]]], newIndex[t[o[1]]], newIndex[t[o[2]]]});
  }
  std::shuffle(triangles.begin(), triangles.end(), random.engine());
  return Mesh(std::move(vertices), std::move(triangles), mesh.name() + " (permuted)");
}

Mesh withRepeatedVertices(const Mesh& mesh, int copies, SeededRandom& random) {
  const std::size_t n = mesh.vertices().size();
  std::vector<Vec3> vertices;
  vertices.reserve(n * copies);
  for (int c = 0; c < copies; ++c) vertices.insert(vertices.end(), mesh.vertices().begin(), mesh.vertices().end());
  std::vector<TriangleIndices> triangles;
  for (const TriangleIndices& t : mesh.triangles()) {
    TriangleIndices u;
    for (int k = 0; k < 3; ++k) u[k] = static_cast<std::uint32_t>(t[k] + n * random.below(copies));
    triangles.push_back(u);
  }
  return Mesh(std::move(vertices), std::move(triangles), mesh.name() + " (repeated vertices)");
}

Eigen::Matrix3d axisRotation(SeededRandom& random) {
  static constexpr int kPermutations[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  const int p = int(random.below(6));
  const int* perm = kPermutations[p];
  Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
  for (int r = 0; r < 3; ++r) m(r, perm[r]) = random.below(2) ? 1.0 : -1.0;
  // A reflection (determinant -1) is turned into a rotation by flipping one row.
  if (m.determinant() < 0) m.row(0) *= -1.0;
  return m;
}

Mesh randomShape(SeededRandom& random, double size, bool convexOnly, std::string* name) {
  const int kinds = convexOnly ? 5 : 8;
  const double h = 0.5 * size;
  Mesh mesh = shapes::box(Vec3(h, h, h));
  std::string picked;
  switch (random.below(kinds)) {
    case 0:
      mesh = shapes::box(Vec3(h * random.uniform(0.2, 1), h * random.uniform(0.2, 1), h * random.uniform(0.2, 1)));
      picked = "box";
      break;
    case 1: {
      const Vec3 e(h * random.uniform(0.3, 1), h * random.uniform(0.3, 1), h * random.uniform(0.3, 1));
      mesh = gridBox(-e, e, 2 + int(random.below(2)));
      picked = "grid box";
      break;
    }
    case 2:
      mesh = shapes::sphere(h, 8 + 2 * int(random.below(4)));
      picked = "sphere";
      break;
    case 3:
      mesh = shapes::capsule(0.4 * h, 0.6 * h, 8 + 2 * int(random.below(3)));
      picked = "capsule";
      break;
    case 4:
      mesh = transformedMesh(polygonPrism(0.5 * h, 6 + int(random.below(20)), size, 1 + int(random.below(3))),
                             Pose(Eigen::Translation3d(0, 0, -h)));
      picked = "prism";
      break;
    case 5:
      mesh = shapes::torus(0.7 * h, 0.25 * h, 16, 8);
      picked = "torus";
      break;
    case 6:
      mesh = shapes::cShape(0.8 * h, 0.25 * h, random.uniform(0.5, 2.5), 24);
      picked = "C-shape";
      break;
    default:
      mesh = shapes::knottedTube(0.3 * h, 0.1 * h, 2, 3, 36, 6);
      picked = "knotted tube";
      break;
  }
  if (name) *name = picked;
  return mesh;
}

SurfacePoint randomSurfacePoint(const Mesh& mesh, const Pose& pose, SeededRandom& random, double margin) {
  SurfacePoint s;
  s.triangle = random.below(mesh.triangleCount());
  const Vec3 p0 = pose * mesh.corner(s.triangle, 0), p1 = pose * mesh.corner(s.triangle, 1),
             p2 = pose * mesh.corner(s.triangle, 2);
  // Barycentric coordinates uniform on the shrunken simplex {w >= margin}.
  double u = random.uniform(), v = random.uniform();
  if (u + v > 1) {
    u = 1 - u;
    v = 1 - v;
  }
  const double shrink = 1.0 - 3.0 * margin;
  u = margin + shrink * u;
  v = margin + shrink * v;
  s.point = p0 + u * (p1 - p0) + v * (p2 - p0);
  const Vec3 n = (p1 - p0).cross(p2 - p0);
  s.normal = n.norm() > 0 ? Vec3(n.normalized()) : Vec3::Zero();
  return s;
}

Pose placeSupportAt(const Mesh& b, const Eigen::Matrix3d& rotation, const Vec3& direction, const Vec3& target) {
  double lowest = INFINITY;
  Vec3 support = Vec3::Zero();
  for (const TriangleIndices& t : b.triangles()) {
    for (std::uint32_t i : t) {
      const Vec3 p = rotation * b.vertices()[i];
      if (p.dot(direction) < lowest) {
        lowest = p.dot(direction);
        support = p;
      }
    }
  }
  Pose pose = Pose::Identity();
  pose.linear() = rotation;
  pose.translation() = target - support;
  return pose;
}

double dyadic(SeededRandom& random, int bits) {
  const double steps = std::ldexp(1.0, bits);
  return std::ldexp(double(random.below(std::uint64_t(2 * steps) + 1)) - steps, -bits);
}

Vec3 perpendicularTo(const Vec3& d, SeededRandom& random) {
  for (;;) {
    const Vec3 v = random.unitVector();
    const Vec3 p = v - v.dot(d) * d;
    if (p.norm() > 0.1) return p.normalized();
  }
}

double powerOfTwoNear(double x) { return std::ldexp(1.0, int(std::lround(std::log2(x)))); }

}  // namespace adsd::stress
