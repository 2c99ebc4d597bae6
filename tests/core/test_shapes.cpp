/// \file
/// \brief The generated meshes the other suites stand on: closed, consistently and outwardly
/// wound, no zero-area triangles, the right size, deterministic, and bad parameters rejected.

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>

#include "adsd/error.h"
#include "adsd/shapes.h"

namespace adsd {
namespace {

/// Every directed edge once, and its reverse once: a closed, consistently wound 2-manifold
/// (edges shared by exactly two triangles, in opposite directions).
::testing::AssertionResult closedAndConsistent(const Mesh& mesh) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const TriangleIndices& t : mesh.triangles()) {
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  }
  for (const auto& [edge, count] : directed) {
    if (count != 1) {
      return ::testing::AssertionFailure() << "edge " << edge.first << "->" << edge.second << " used " << count << " times";
    }
    if (!directed.count({edge.second, edge.first})) {
      return ::testing::AssertionFailure() << "edge " << edge.first << "->" << edge.second << " has no twin (open)";
    }
  }
  return ::testing::AssertionSuccess();
}

double signedVolume(const Mesh& mesh) {
  double sum = 0;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    sum += mesh.corner(t, 0).dot(mesh.corner(t, 1).cross(mesh.corner(t, 2)));
  }
  return sum / 6;
}

double smallestArea(const Mesh& mesh) {
  double smallest = INFINITY;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    smallest = std::min(smallest, 0.5 * (mesh.corner(t, 1) - mesh.corner(t, 0)).cross(mesh.corner(t, 2) - mesh.corner(t, 0)).norm());
  }
  return smallest;
}

void expectValidSolid(const Mesh& mesh, double expectedVolume, double relativeTolerance) {
  EXPECT_TRUE(closedAndConsistent(mesh)) << mesh.name();
  const double size = mesh.bounds().diagonal().norm();
  EXPECT_GT(smallestArea(mesh), 1e-6 * size * size) << mesh.name();
  EXPECT_NEAR(signedVolume(mesh), expectedVolume, relativeTolerance * expectedVolume) << mesh.name();
}

TEST(Shapes, Box) {
  const Mesh m = shapes::box(Vec3(1, 2, 3));
  EXPECT_EQ(m.triangleCount(), 12u);
  expectValidSolid(m, 48.0, 1e-14);
  EXPECT_EQ(m.bounds().min(), Vec3(-1, -2, -3));
  EXPECT_EQ(m.bounds().max(), Vec3(1, 2, 3));
}

TEST(Shapes, Sphere) {
  for (int segments : {4, 5, 16, 48}) {
    const Mesh m = shapes::sphere(2.0, segments);
    EXPECT_TRUE(closedAndConsistent(m)) << segments;
    EXPECT_GT(signedVolume(m), 0) << segments;
    for (const Vec3& v : m.vertices()) EXPECT_NEAR(v.norm(), 2.0, 1e-14);
  }
  // A fine sphere's volume approaches 4/3 pi r^3 from below.
  const Mesh fine = shapes::sphere(2.0, 64);
  const double ball = 4.0 / 3.0 * M_PI * 8.0;
  expectValidSolid(fine, ball, 0.01);
  EXPECT_LT(signedVolume(fine), ball);
}

TEST(Shapes, Capsule) {
  const Mesh m = shapes::capsule(0.5, 1.0, 32);
  expectValidSolid(m, M_PI * 0.25 * 2.0 + 4.0 / 3.0 * M_PI * 0.125, 0.02);
  EXPECT_NEAR(m.bounds().max().z(), 1.5, 1e-14);
  EXPECT_NEAR(m.bounds().min().z(), -1.5, 1e-14);
  // A zero half length is a sphere: still closed, no zero-area band.
  expectValidSolid(shapes::capsule(0.5, 0.0, 32), 4.0 / 3.0 * M_PI * 0.125, 0.02);
}

TEST(Shapes, Torus) {
  const Mesh m = shapes::torus(1.0, 0.3, 64, 24);
  EXPECT_EQ(m.triangleCount(), 2u * 64 * 24);
  expectValidSolid(m, 2 * M_PI * M_PI * 1.0 * 0.09, 0.02);
  EXPECT_NEAR(m.bounds().max().x(), 1.3, 1e-14);
  EXPECT_NEAR(m.bounds().max().z(), 0.3, 1e-3);
}

TEST(Shapes, KnottedTube) {
  const double tube = 0.25;
  const Mesh m = shapes::knottedTube(1.0, tube, 2, 3, 200, 12);
  EXPECT_EQ(m.triangleCount(), 2u * 200 * 12);
  // Volume of a tube = section area x length of the centre line (Pappus), the trefoil's length
  // on the (2, 1) torus being 31.90 (numerically integrated); the polygonal section is smaller.
  const double polygonArea = 0.5 * 12 * tube * tube * std::sin(2 * M_PI / 12);
  expectValidSolid(m, polygonArea * 31.898, 0.02);
  // Every vertex is tubeRadius away from the centre line, which keeps between 1 and 3 (x scale)
  // from the z axis.
  double farthest = 0, nearest = INFINITY;
  for (const Vec3& v : m.vertices()) {
    farthest = std::max(farthest, v.head<2>().norm());
    nearest = std::min(nearest, v.head<2>().norm());
  }
  EXPECT_LE(farthest, 3.0 + tube + 1e-12);
  EXPECT_GE(nearest, 1.0 - tube - 1e-12);
}

TEST(Shapes, CShape) {
  const double radius = 1.0, thickness = 0.25, opening = 0.9;
  const Mesh m = shapes::cShape(radius, thickness, opening, 256);
  // Square section swept along an arc of angle 2 pi - opening at radius `radius` (Pappus).
  expectValidSolid(m, thickness * thickness * radius * (2 * M_PI - opening), 1e-3);
  // The gap is centred on +x: nothing of the C lies on the positive x axis.
  for (const Vec3& v : m.vertices()) {
    EXPECT_FALSE(v.x() > 0 && std::abs(std::atan2(v.y(), v.x())) < 0.5 * opening - 1e-12);
  }
}

TEST(Shapes, Room) {
  const Vec3 half(2, 1.5, 1);
  const double wall = 0.1;
  const Mesh m = shapes::room(half, wall, 8);
  EXPECT_EQ(m.triangleCount(), 24u * 64);
  const Vec3 outer = half + Vec3::Constant(wall);
  // Two closed shells, outer facing out and inner facing into the cavity: the signed volume is
  // that of the walls.
  expectValidSolid(m, 8 * (outer.prod() - half.prod()), 1e-12);
  EXPECT_EQ(m.bounds().max(), outer);
}

TEST(Shapes, MergePlacesParts) {
  const Mesh box = shapes::box(Vec3(1, 1, 1));
  const Pose shifted(Eigen::Translation3d(10, 0, 0));
  const Mesh m = shapes::merge({box, box}, {Pose::Identity(), shifted});
  EXPECT_EQ(m.triangleCount(), 24u);
  EXPECT_TRUE(closedAndConsistent(m));
  EXPECT_NEAR(signedVolume(m), 16.0, 1e-12);
  EXPECT_EQ(m.bounds().max(), Vec3(11, 1, 1));
  EXPECT_EQ(shapes::merge({box}, {}).triangleCount(), 12u);
}

TEST(Shapes, Deterministic) {
  auto same = [](const Mesh& x, const Mesh& y) { return x.vertices() == y.vertices() && x.triangles() == y.triangles(); };
  EXPECT_TRUE(same(shapes::knottedTube(1, 0.2, 2, 3, 90, 9), shapes::knottedTube(1, 0.2, 2, 3, 90, 9)));
  EXPECT_TRUE(same(shapes::room(Vec3(1, 2, 3), 0.2, 5), shapes::room(Vec3(1, 2, 3), 0.2, 5)));
  EXPECT_TRUE(same(shapes::cShape(1, 0.2, 1, 30), shapes::cShape(1, 0.2, 1, 30)));
}

TEST(Shapes, BadParametersAreRejected) {
  EXPECT_THROW(shapes::box(Vec3(1, 0, 1)), InputError);
  EXPECT_THROW(shapes::sphere(-1, 16), InputError);
  EXPECT_THROW(shapes::sphere(1, 3), InputError);
  EXPECT_THROW(shapes::sphere(NAN, 16), InputError);
  EXPECT_THROW(shapes::torus(1, 1.5, 16, 8), InputError);
  EXPECT_THROW(shapes::torus(1, 0.2, 2, 8), InputError);
  EXPECT_THROW(shapes::knottedTube(1, 0.2, 2, 4, 90, 9), InputError);
  EXPECT_THROW(shapes::knottedTube(1, 0.2, 2, 3, 2, 9), InputError);
  EXPECT_THROW(shapes::cShape(1, 0.2, 0.0, 30), InputError);
  EXPECT_THROW(shapes::cShape(1, 0.2, 7.0, 30), InputError);
  EXPECT_THROW(shapes::cShape(1, 2.5, 1.0, 30), InputError);
  EXPECT_THROW(shapes::capsule(1, -0.5, 16), InputError);
  EXPECT_THROW(shapes::room(Vec3(1, 1, 1), 0, 4), InputError);
  EXPECT_THROW(shapes::room(Vec3(1, 1, 1), 0.1, 0), InputError);
  EXPECT_THROW(shapes::merge({}, {}), InputError);
  EXPECT_THROW(shapes::merge({shapes::box(Vec3(1, 1, 1))}, {Pose::Identity(), Pose::Identity()}), InputError);
  try {
    shapes::torus(1, -0.2, 16, 8);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("tubeRadius"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace adsd
