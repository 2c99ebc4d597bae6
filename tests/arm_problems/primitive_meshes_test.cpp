// Primitives as meshes: closed, wound outward, and containing the primitive (every face's plane at
// least the radius from the centre or axis), reaching out no more than documented.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>

#include "adsd/planner/primitive_meshes.h"

namespace adsd::planner {
namespace {

/// Every edge is shared by exactly two triangles, in opposite directions (closed, consistently wound).
void expectClosed(const Mesh& m) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const TriangleIndices& t : m.triangles()) {
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  }
  for (const auto& [edge, count] : directed) {
    EXPECT_EQ(count, 1);
    EXPECT_EQ(directed.count({edge.second, edge.first}), 1u) << edge.first << "-" << edge.second;
  }
}

/// The signed distance of triangle t's plane from the origin along its normal (> 0: wound outward).
double planeOffset(const Mesh& m, std::size_t t) {
  const Vec3 n = (m.corner(t, 1) - m.corner(t, 0)).cross(m.corner(t, 2) - m.corner(t, 0)).normalized();
  return n.dot(m.corner(t, 0));
}

TEST(PrimitiveMeshes, BoxIsExact) {
  const Mesh box = boxMesh(Vec3(0.4, 0.2, 0.1), "b");
  expectClosed(box);
  EXPECT_EQ(box.triangleCount(), 12u);
  EXPECT_TRUE(box.bounds().min().isApprox(Vec3(-0.2, -0.1, -0.05)));
  EXPECT_TRUE(box.bounds().max().isApprox(Vec3(0.2, 0.1, 0.05)));
  for (std::size_t t = 0; t < box.triangleCount(); ++t) EXPECT_GT(planeOffset(box, t), 0.0);
}

TEST(PrimitiveMeshes, SphereMeshContainsTheBall) {
  const double r = 0.3;
  const Mesh s = sphereMesh(r, "s");
  expectClosed(s);
  double least = 1e9, most = 0;
  for (std::size_t t = 0; t < s.triangleCount(); ++t) {
    const double d = planeOffset(s, t);
    EXPECT_GE(d, r * (1 - 1e-12)) << "face " << t;
    least = std::min(least, d);
  }
  for (const Vec3& v : s.vertices()) most = std::max(most, v.norm());
  EXPECT_NEAR(least, r, 1e-3 * r);           // tight: some face touches the ball
  EXPECT_LE(most, r * 1.0097);               // the documented excess, 0.97 % of the radius
}

TEST(PrimitiveMeshes, CylinderMeshContainsTheCylinder) {
  const double h = 0.6, r = 0.05;
  const Mesh c = cylinderMesh(r, h, "c");
  expectClosed(c);
  for (std::size_t t = 0; t < c.triangleCount(); ++t) {
    const Vec3 n = (c.corner(t, 1) - c.corner(t, 0)).cross(c.corner(t, 2) - c.corner(t, 0)).normalized();
    if (std::abs(n.z()) > 0.5) {
      EXPECT_NEAR(n.dot(c.corner(t, 0)), h / 2, 1e-15);  // a cap
    } else {
      EXPECT_NEAR(n.dot(c.corner(t, 0)), r, 1e-15);  // a side, tangent to the cylinder
    }
  }
  for (const Vec3& v : c.vertices()) EXPECT_LE(std::hypot(v.x(), v.y()), r / std::cos(M_PI / 32) * (1 + 1e-15));
}

}  // namespace
}  // namespace adsd::planner
