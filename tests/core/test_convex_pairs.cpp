/// \file
/// \brief Queries between two small convex meshes with trees (MeshHierarchy::onHullBoundary):
/// GJK on their vertices settles them with one triangle pair (convex_pair.cpp). Checked against
/// the brute-force binary128 oracle on random poses from near contact (1e-8) to far apart, in
/// the modes that use it (exact, cap, tolerance), and on the cases where the hulls' distance is
/// not the meshes' (an open box facing its hole, a box inside a box), which must fall back to
/// the traversal and still answer the surfaces' distance.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "adsd/distance.h"
#include "adsd/mesh_hierarchy.h"
#include "adsd/shapes.h"
#include "open_box.h"
#include "oracle.h"
#include "random_geometry.h"

namespace adsd {
namespace {

using oracle::SeededRandom;

using oracle::kPromisedAccuracy;
using oracle::sceneDiagonal;

#ifdef ADSD_TESTS_UNDER_SANITIZER
constexpr int kPosesPerPair = 40;
#else
constexpr int kPosesPerPair = 400;
#endif

Mesh withTree(Mesh mesh) {
  mesh.buildHierarchy();
  return mesh;
}

using testing::openBox;

/// B turned by \p rotation and moved along unit \p u so that the two vertex sets' support planes
/// normal to u are \p gap apart: the meshes are at least that far apart, and near it.
Pose placedAlong(const Mesh& a, const Mesh& b, const Eigen::Quaterniond& rotation, const Vec3& u, double gap) {
  double reachA = -INFINITY, reachB = -INFINITY;
  for (const Vec3& v : a.vertices()) reachA = std::max(reachA, u.dot(v));
  for (const Vec3& v : b.vertices()) reachB = std::max(reachB, -u.dot(rotation * v));
  return Pose(Eigen::Translation3d(u * (reachA + reachB + gap)) * rotation);
}

TEST(ConvexPairs, SmallClosedConvexMeshesAreOnTheirHullsAndOthersAreNot) {
  EXPECT_TRUE(withTree(shapes::box(Vec3(1, 2, 3))).hierarchy()->onHullBoundary());
  EXPECT_TRUE(withTree(shapes::sphere(0.5, 8)).hierarchy()->onHullBoundary());
  EXPECT_TRUE(withTree(shapes::sphere(0.5, 16)).hierarchy()->onHullBoundary());
  EXPECT_FALSE(withTree(openBox(1.0)).hierarchy()->onHullBoundary());  // not closed
  EXPECT_FALSE(withTree(shapes::torus(1.0, 0.3, 8, 6)).hierarchy()->onHullBoundary());
  EXPECT_FALSE(withTree(shapes::cShape(1.0, 0.25, 0.9, 8)).hierarchy()->onHullBoundary());
  // Rounder (482 and 546 vertices), within the size that is checked (kConvexCheckVertices).
  EXPECT_TRUE(withTree(shapes::sphere(0.5, 32)).hierarchy()->onHullBoundary());
  EXPECT_TRUE(withTree(shapes::capsule(0.1, 0.5, 32)).hierarchy()->onHullBoundary());
  // Convex, but past that size.
  ASSERT_GT(shapes::sphere(0.5, 64).vertices().size(), MeshHierarchy::kConvexCheckVertices);
  EXPECT_FALSE(withTree(shapes::sphere(0.5, 64)).hierarchy()->onHullBoundary());
}

/// A vertex no triangle uses is not on the surface: a mesh with one above a closed box is not
/// taken for its hull's boundary, whose support points GJK would offer as surface points (it
/// answered 4.24 for the boxes' gap of 8 when only the used vertices were checked).
TEST(ConvexPairs, AVertexNoTriangleUsesIsNotTakenForTheSurface) {
  const Mesh box = shapes::box(Vec3(1, 1, 1));
  std::vector<Vec3> vertices = box.vertices();
  vertices.push_back(Vec3(0, 0, 5));
  Mesh withStray = withTree(Mesh(vertices, box.triangles(), "box and a stray vertex"));
  EXPECT_FALSE(withStray.hierarchy()->onHullBoundary());
  const Mesh other = withTree(shapes::box(Vec3(1, 1, 1)));
  const Pose above(Eigen::Translation3d(0, 0, 10));
  for (const DistanceOptions& options :
       {DistanceOptions::exactDistance(), DistanceOptions::cappedAt(20.0), DistanceOptions::withTolerance(0.0, 0.01)}) {
    const DistanceResult r = distance(withStray, Pose::Identity(), other, above, options);
    EXPECT_LE(r.lower, 8.0 + 1e-12);
    EXPECT_GE(r.upper, 8.0 - 1e-12);
    EXPECT_GE(r.distance, 8.0 - 1e-12);
  }
}

struct ConvexCase {
  std::string name;
  Mesh a, b;
};

std::vector<ConvexCase> convexCases() {
  return {
      {"box and box", withTree(shapes::box(Vec3(1, 1, 1))), withTree(shapes::box(Vec3(0.3, 0.2, 0.1)))},
      {"plate and box", withTree(shapes::box(Vec3(2, 0.01, 1.5))), withTree(shapes::box(Vec3(0.5, 0.1, 0.1)))},
      {"sphere and box", withTree(shapes::sphere(0.7, 8)), withTree(shapes::box(Vec3(0.2, 0.4, 0.3)))},
      {"sphere and sphere", withTree(shapes::sphere(0.7, 8)), withTree(shapes::sphere(0.3, 6))},
      // Rounder: 114 and 62 vertices, where only triangles at the support planes are measured.
      {"round and round", withTree(shapes::sphere(0.6, 16)), withTree(shapes::sphere(0.4, 12))},
  };
}

/// Exact, cap and tolerance queries at random poses, near contact to far, against the oracle;
/// and the path really settles most of them with GJK and one triangle pair (counted).
TEST(ConvexPairs, AnswersMatchTheOracleFromContactToFarApart) {
  SeededRandom random(4711);
  for (const ConvexCase& c : convexCases()) {
    int separated = 0, settledByOnePair = 0;
    for (int i = 0; i < kPosesPerPair; ++i) {
      // Gaps log-uniform over 1e-8 .. 3 (the meshes are about 1 across); one pose in eight
      // pushed into overlap (negative gap), where the traversal answers.
      const double gap = i % 8 == 7 ? -random.uniform(0.0, 0.2) : random.logUniform(-8.0, 0.5);
      const Pose poseB = placedAlong(c.a, c.b, random.rotation(), random.unitVector(), gap);
      const Pose poseA = Pose::Identity();
      const oracle::MeshPairDistance truth = oracle::meshDistance(c.a, poseA, c.b, poseB);
      const double allowed = kPromisedAccuracy * sceneDiagonal(c.a, poseA, c.b, poseB);
      SCOPED_TRACE(c.name + ", pose " + std::to_string(i) + ", gap " + std::to_string(gap) + ", oracle " +
                   std::to_string(truth.value));

      const DistanceResult exact = distance(c.a, poseA, c.b, poseB, DistanceOptions::exactDistance());
      ASSERT_EQ(exact.status, DistanceStatus::exact);
      EXPECT_NEAR(exact.distance, truth.value, allowed);
      EXPECT_NEAR((exact.witnessA - exact.witnessB).norm(), exact.distance, allowed);
      if (gap > 0.0) {
        ++separated;
        settledByOnePair += exact.counters.subMeshPairs == 0 && exact.counters.trianglePairsTested == 1;
      }

      if (truth.value > allowed) {  // not in contact (the oracle's contact is a few 1e-17)
        const DistanceResult below = distance(c.a, poseA, c.b, poseB, DistanceOptions::cappedAt(0.5 * truth.value));
        EXPECT_EQ(below.status, DistanceStatus::beyondCap);
        EXPECT_LE(below.lower, truth.value + allowed);
        const DistanceResult above = distance(c.a, poseA, c.b, poseB, DistanceOptions::cappedAt(2.0 * truth.value));
        EXPECT_EQ(above.status, DistanceStatus::exact);
        EXPECT_NEAR(above.distance, truth.value, allowed);
      }
      const DistanceResult tolerant = distance(c.a, poseA, c.b, poseB, DistanceOptions::withTolerance(0.0, 0.01));
      EXPECT_LE(tolerant.lower, truth.value + allowed);
      EXPECT_GE(tolerant.upper, truth.value - allowed);
      EXPECT_LE(tolerant.upper, 1.01 * tolerant.lower + allowed);
    }
    // Near contact the roundoff may leave a proof short (the traversal then answers); here all
    // separated poses were settled by GJK and one triangle pair, gaps of 1e-8 included.
    EXPECT_GE(settledByOnePair, separated * 19 / 20) << c.name << ": " << settledByOnePair << " of " << separated;
  }
}

/// An open box facing its hole: its hull is nearest where it has no triangle, so the hulls'
/// distance is well below the surfaces' and the query must go on to the traversal.
TEST(ConvexPairs, AnOpenBoxFacingItsHoleIsAnsweredByItsTriangles) {
  const Mesh a = withTree(openBox(1.0));
  const Mesh b = withTree(shapes::box(Vec3(0.2, 0.2, 0.2)));
  const Pose poseB(Eigen::Translation3d(1.5, 0, 0));  // 0.3 from the missing face's plane
  const oracle::MeshPairDistance truth = oracle::meshDistance(a, Pose::Identity(), b, poseB);
  ASSERT_GT(truth.value, 0.8);  // the rim: (0.3, 0.8) away
  const DistanceResult r = distance(a, Pose::Identity(), b, poseB);
  EXPECT_NEAR(r.distance, truth.value, 1e-12);
  const DistanceResult capped = distance(a, Pose::Identity(), b, poseB, DistanceOptions::cappedAt(0.5));
  EXPECT_EQ(capped.status, DistanceStatus::beyondCap);
}

/// A box inside a larger box: the hulls overlap, the surfaces are apart by the nearest wall.
TEST(ConvexPairs, ABoxInsideABoxIsApartFromItsWalls) {
  const Mesh a = withTree(shapes::box(Vec3(1, 1, 1)));
  const Mesh b = withTree(shapes::box(Vec3(0.2, 0.2, 0.2)));
  const Pose poseB(Eigen::Translation3d(0.5, 0.1, -0.2) * Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()));
  const oracle::MeshPairDistance truth = oracle::meshDistance(a, Pose::Identity(), b, poseB);
  ASSERT_GT(truth.value, 0.1);
  const DistanceResult r = distance(a, Pose::Identity(), b, poseB);
  EXPECT_NEAR(r.distance, truth.value, 1e-12);
  EXPECT_EQ(r.status, DistanceStatus::exact);
}

}  // namespace
}  // namespace adsd
