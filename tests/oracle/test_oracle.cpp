/// \file
/// \brief The oracle on its own: hand-computed cases, optimality certificates on random cases,
/// the intersection predicate against constructions whose answer is known exactly, and the
/// brute-force mesh distance against an unpruned loop.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "adsd/shapes.h"
#include "oracle.h"
#include "random_geometry.h"

namespace adsd::oracle {
namespace {

/// Hand-computed distances are compared to this relative precision (binary128 keeps ~34 digits;
/// the face-pair solves lose a few).
constexpr Quad kAnalyticRelative = 1e-28Q;

::testing::AssertionResult distanceIs(const TrianglePairDistance& d, Quad expected, Quad scale = 1) {
  const Quad error = absQ(d.distance - expected);
  if (error <= kAnalyticRelative * scale) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "distance " << toString(d.distance) << " expected "
                                       << toString(expected) << " error " << toString(error);
}

/// The witness points must realize the distance.
::testing::AssertionResult witnessesRealize(const TrianglePairDistance& d, Quad scale = 1) {
  const Quad gap = absQ(norm(d.pointOnA - d.pointOnB) - d.distance);
  if (gap <= kAnalyticRelative * scale) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "|pA - pB| differs from the distance by " << toString(gap);
}

TEST(OracleTriangleDistance, VertexFace) {
  // B's lowest vertex hangs 0.5 above the interior of A (in z = 0).
  const auto d = triangleDistance(Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(0, 4, 0), Vec3(1, 1, 0.5), Vec3(1, 1, 3),
                                  Vec3(2, 1, 3));
  EXPECT_TRUE(distanceIs(d, 0.5Q));
  EXPECT_TRUE(witnessesRealize(d));
  EXPECT_EQ(d.featureA, Feature::interior);
  EXPECT_EQ(d.featureB, Feature::vertex);
  EXPECT_NEAR(double(d.pointOnA[0]), 1.0, 1e-30);
  EXPECT_NEAR(double(d.pointOnA[1]), 1.0, 1e-30);
}

TEST(OracleTriangleDistance, SkewEdges) {
  // A in the xz plane below z = 0 with its top edge on the x axis; B in the yz plane above z = h
  // with its bottom edge along y: the edges cross at distance h.
  const double h = 0.25;
  const auto d = triangleDistance(Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, 0, -1), Vec3(0, -1, h), Vec3(0, 1, h),
                                  Vec3(0, 0, h + 1));
  EXPECT_TRUE(distanceIs(d, 0.25Q));
  EXPECT_EQ(d.featureA, Feature::edge);
  EXPECT_EQ(d.featureB, Feature::edge);
  // A generic crossing: edge (0,0,0)-(2,0,0) against (1,-1,1)-(1,1,1.5) (skew).
  // In the plane x = 1 the second edge is the line z = 1.25 + y / 4, whose distance from the x
  // axis point (1, 0, 0) is 1.25 / sqrt(1 + 1/16) = 5 / sqrt(17).
  const auto e = triangleDistance(Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, 0, -3), Vec3(1, -1, 1), Vec3(1, 1, 1.5),
                                  Vec3(1, 0, 5));
  EXPECT_TRUE(distanceIs(e, 5 / sqrtq(17)));
  EXPECT_EQ(e.featureA, Feature::edge);
  EXPECT_EQ(e.featureB, Feature::edge);
  EXPECT_TRUE(witnessesRealize(e));
}

TEST(OracleTriangleDistance, ParallelEdges) {
  const double h = 0.125;
  // Overlapping parallel edges: A's top edge z = 0, x in [0, 2]; B's bottom edge z = h, x in [1, 3].
  const auto overlap = triangleDistance(Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, 0, -1), Vec3(1, 0, h), Vec3(3, 0, h),
                                        Vec3(2, 0, h + 1));
  EXPECT_TRUE(distanceIs(overlap, 0.125Q));
  // Shifted past the end: x in [3, 5]: the closest points are (2, 0, 0) and (3, 0, h).
  const auto apart = triangleDistance(Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, 0, -1), Vec3(3, 0, h), Vec3(5, 0, h),
                                      Vec3(4, 0, h + 1));
  EXPECT_TRUE(distanceIs(apart, sqrtq(1 + 0.125Q * 0.125Q)));
  // Parallel edges in different planes: A's edge along x at (y, z) = (0, 0), B's along x at
  // (y, z) = (3, 4), triangles pointing away from each other: distance 5.
  const auto offset = triangleDistance(Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, -1, -1), Vec3(0.5, 3, 4),
                                       Vec3(1.5, 3, 4), Vec3(1, 4, 5));
  EXPECT_TRUE(distanceIs(offset, 5));
}

TEST(OracleTriangleDistance, ParallelFaces) {
  // Two triangles in z = 0 and z = 0.75 overlapping in projection.
  const auto d = triangleDistance(Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 2, 0), Vec3(0.5, 0.5, 0.75),
                                  Vec3(3, 0.5, 0.75), Vec3(0.5, 3, 0.75));
  EXPECT_TRUE(distanceIs(d, 0.75Q));
  EXPECT_TRUE(witnessesRealize(d));
}

TEST(OracleTriangleDistance, Coplanar) {
  // Overlapping in the plane z = 1: distance 0.
  const auto overlap = triangleDistance(Vec3(0, 0, 1), Vec3(2, 0, 1), Vec3(0, 2, 1), Vec3(0.5, 0.5, 1),
                                        Vec3(3, 0.5, 1), Vec3(0.5, 3, 1));
  EXPECT_TRUE(distanceIs(overlap, 0));
  // Disjoint: A's hypotenuse x + y = 1 faces B's vertex (1, 1): distance sqrt(2)/2.
  const auto apart = triangleDistance(Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(0, 1, 1), Vec3(1, 1, 1), Vec3(3, 1, 1),
                                      Vec3(1, 3, 1));
  EXPECT_TRUE(distanceIs(apart, sqrtq(2) / 2));
  EXPECT_EQ(apart.featureA, Feature::edge);
  EXPECT_EQ(apart.featureB, Feature::vertex);
  // Touching at a shared vertex and along a shared edge.
  const auto vertex = triangleDistance(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 0, 0), Vec3(2, 0, 0),
                                       Vec3(2, 1, 0));
  EXPECT_TRUE(distanceIs(vertex, 0));
  const auto edge = triangleDistance(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 0, 0), Vec3(0, 1, 0),
                                     Vec3(1, 1, 0));
  EXPECT_TRUE(distanceIs(edge, 0));
}

TEST(OracleTriangleDistance, Intersecting) {
  // B pierces A's interior: distance 0 and coincident witnesses.
  const auto d = triangleDistance(Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(0, 4, 0), Vec3(1, 1, -1), Vec3(1, 1, 1),
                                  Vec3(2, 1, 1));
  EXPECT_TRUE(distanceIs(d, 0));
  EXPECT_TRUE(absQ(norm(d.pointOnA - d.pointOnB)) <= 1e-30Q);
}

TEST(OracleTriangleDistance, DegenerateTriangles) {
  const Vec3 p(1, 2, 3), q(4, 6, 3);
  // Point vs point: |p - q| = 5.
  EXPECT_TRUE(distanceIs(triangleDistance(p, p, p, q, q, q), 5));
  // Point vs segment (collinear triangle (0,0,0), (2,0,0), (1,0,0)): point (1, 3, 4) -> 5.
  EXPECT_TRUE(distanceIs(triangleDistance(Vec3(1, 3, 4), Vec3(1, 3, 4), Vec3(1, 3, 4), Vec3(0, 0, 0), Vec3(2, 0, 0),
                                          Vec3(1, 0, 0)),
                         5));
  // Segment vs segment, skew: x axis [0, 2] and the segment x = 1, z = 2, y in [-1, 1] -> 2.
  EXPECT_TRUE(distanceIs(triangleDistance(Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 0, 0), Vec3(1, -1, 2),
                                          Vec3(1, 1, 2), Vec3(1, 1, 2)),
                         2));
  // Point above a triangle's interior and beyond its edge.
  EXPECT_TRUE(distanceIs(triangleDistance(Vec3(1, 1, 3), Vec3(1, 1, 3), Vec3(1, 1, 3), Vec3(0, 0, 0),
                                          Vec3(4, 0, 0), Vec3(0, 4, 0)),
                         3));
  EXPECT_TRUE(distanceIs(triangleDistance(Vec3(2, -3, 4), Vec3(2, -3, 4), Vec3(2, -3, 4), Vec3(0, 0, 0),
                                          Vec3(4, 0, 0), Vec3(0, 4, 0)),
                         5));
  // Repeated vertex: (a, a, b) is the segment ab.
  EXPECT_TRUE(distanceIs(triangleDistance(Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, 3, 4),
                                          Vec3(1, 3, 4), Vec3(1, 5, 4)),
                         5));
  // Point vs a segment given as (a, b, b).
  EXPECT_TRUE(absQ(pointTriangleDistance(Quad3(Vec3(5, 0, 0)), Quad3(Vec3(0, 0, 0)), Quad3(Vec3(1, 0, 0)),
                                         Quad3(Vec3(1, 0, 0))) - 4) <= kAnalyticRelative);
}

TEST(OracleTriangleDistance, PqpParallelEdgesNear8000IsTheCoordinateGap) {
  // The PQP TriDist report (github.com/GammaUNC/PQP issue 4): S lies in the plane
  // z = 571.00166381103077 with its lowest-y vertex s2 at y = 6327.6345143037688; T lies in the
  // plane y = 6327.6345143037670 and s2 projects inside T. So the distance is exactly the
  // difference of those two doubles (about 1.8e-12), computed here exactly in binary128.
  const Vec3 s0(8000.0000000000036, 6817.7672478170962, 571.00166381103077);
  const Vec3 s1(7500.0000000000009, 6817.7672478170962, 571.00166381103077);
  const Vec3 s2(7500.0000000000009, 6327.6345143037688, 571.00166381103077);
  const Vec3 t0(8000.0000000000009, 6327.6345143037670, 88.336618780016408);
  const Vec3 t1(7500.0, 6327.6345143037670, 88.336618780016408);
  const Vec3 t2(7500.0, 6327.6345143037670, 1015.9309593449836);
  const Quad expected = Quad(s2.y()) - Quad(t0.y());
  const auto d = triangleDistance(s0, s1, s2, t0, t1, t2);
  EXPECT_GT(double(expected), 1e-12);
  EXPECT_LT(double(expected), 3e-12);
  EXPECT_TRUE(absQ(d.distance - expected) <= 1e-30Q * 8000) << toString(d.distance) << " vs " << toString(expected);
  EXPECT_FALSE(trianglesIntersect(s0, s1, s2, t0, t1, t2));
}

TEST(OracleTriangleDistance, SymmetricAndOrderIndependent) {
  SeededRandom random(7);
  for (int i = 0; i < 2000; ++i) {
    Vec3 a[3], b[3];
    for (auto& v : a) v = random.inCube(1);
    for (auto& v : b) v = random.inCube(1) + Vec3(random.uniform(-1, 1), 0, 0);
    const Quad d = triangleDistance(a[0], a[1], a[2], b[0], b[1], b[2]).distance;
    const Quad swapped = triangleDistance(b[2], b[0], b[1], a[1], a[0], a[2]).distance;
    ASSERT_TRUE(absQ(d - swapped) <= 1e-28Q) << i << ": " << toString(d) << " vs " << toString(swapped);
  }
}

/// For any unit u, min over A of u.a minus max over B of u.b is a lower bound on the distance;
/// with u along the witnesses it equals the distance exactly when the witnesses are optimal (the
/// planes through them orthogonal to u separate the triangles). Returns distance - bound.
Quad certificateGap(const Vec3 (&a)[3], const Vec3 (&b)[3], const TrianglePairDistance& d) {
  const Quad3 u = (1 / norm(d.pointOnA - d.pointOnB)) * (d.pointOnA - d.pointOnB);
  Quad minA = dot(u, Quad3(a[0])), maxB = dot(u, Quad3(b[0]));
  for (int k = 1; k < 3; ++k) {
    minA = std::min(minA, dot(u, Quad3(a[k])));
    maxB = std::max(maxB, dot(u, Quad3(b[k])));
  }
  return d.distance - (minA - maxB);
}

/// Random families, each checked by the separating-plane certificate when the triangles are
/// disjoint and by the exact predicate when they meet.
TEST(OracleTriangleDistance, RandomCasesCarryOptimalityCertificates) {
  SeededRandom random(20240601);
  int certified = 0, intersecting = 0;
  Quad worstGap = 0;
  for (int i = 0; i < 30000; ++i) {
    Vec3 a[3], b[3];
    const int family = i % 5;
    for (auto& v : a) v = random.inCube(1);
    if (family == 0) {  // generic, often intersecting
      for (auto& v : b) v = random.inCube(1);
    } else if (family == 1) {  // B shifted away: mostly disjoint
      const Vec3 shift = random.unitVector() * random.uniform(0.5, 2.5);
      for (auto& v : b) v = random.inCube(1) + shift;
    } else if (family == 2) {  // nearly parallel edges: B's edge is A's edge rotated by 1e-k rad
      const Eigen::Quaterniond tilt(Eigen::AngleAxisd(random.logUniform(-15, -1), random.unitVector()));
      const Vec3 offset = random.unitVector() * random.logUniform(-8, 0);
      b[0] = tilt * a[0] + offset;
      b[1] = tilt * a[1] + offset;
      b[2] = b[0] + random.unitVector() * random.uniform(0.1, 1.0);
    } else if (family == 3) {  // exactly parallel faces (z constant), dyadic offsets
      const double gap = std::ldexp(1.0, -int(random.below(40)));
      for (auto& v : a) v.z() = 0.0;
      for (auto& v : b) v = Vec3(random.uniform(-1, 1), random.uniform(-1, 1), gap);
    } else {  // large offsets: the same near configuration far from the origin
      const Vec3 far = random.unitVector() * random.logUniform(3, 8);
      const Vec3 shift = random.unitVector() * random.uniform(0.0, 1.5);
      for (auto& v : b) v = random.inCube(1) + shift + far;
      for (auto& v : a) v += far;
    }
    double scale = 0;
    for (const auto* t : {&a, &b}) {
      for (const Vec3& v : *t) scale = std::max(scale, v.cwiseAbs().maxCoeff());
    }
    const auto d = triangleDistance(a[0], a[1], a[2], b[0], b[1], b[2]);
    const bool meet = trianglesIntersect(a[0], a[1], a[2], b[0], b[1], b[2]);
    if (meet) {
      ++intersecting;
      // Meeting triangles: the oracle's distance is rounding noise of the coordinates' size.
      ASSERT_LE(double(d.distance), 1e-30 * scale) << "case " << i << " family " << family;
    } else {
      ASSERT_GT(d.distance, 0) << "case " << i << " family " << family;
      // Certificates need a well-defined direction: distances far above rounding noise.
      if (d.distance > 1e-20Q * scale) {
        // The witnesses carry binary128 rounding of the coordinates' size (~1e-33 x scale);
        // across a distance d that tilts u by ~1e-33 x scale / d, which moves the projections of
        // triangles of extent ~scale by scale^2 / d x 1e-33. Allowed: 100 times that, plus an
        // absolute 1e-24 x scale for the solves' own error.
        const Quad gap = certificateGap(a, b, d);
        worstGap = std::max(worstGap, gap / scale);
        ASSERT_LE(double(gap), 1e-24 * scale + 1e-31 * scale * scale / double(d.distance)) << "case " << i << " family " << family << " distance "
                                               << toString(d.distance);
        ++certified;
      }
    }
  }
  std::cout << "certified " << certified << ", intersecting " << intersecting
            << ", worst certificate gap / scale " << toString(worstGap) << "\n";
  EXPECT_GT(certified, 20000);
  EXPECT_GT(intersecting, 2000);
}

TEST(OracleTriangleIntersection, KnownAnswers) {
  const Vec3 a0(0, 0, 0), a1(4, 0, 0), a2(0, 4, 0);
  // Piercing, and missing by one unit in the last place.
  EXPECT_TRUE(trianglesIntersect(a0, a1, a2, Vec3(1, 1, -1), Vec3(1, 1, 1), Vec3(2, 1, 1)));
  const double justAbove = std::nextafter(0.0, 1.0);
  EXPECT_FALSE(trianglesIntersect(a0, a1, a2, Vec3(1, 1, justAbove), Vec3(1, 1, 1), Vec3(2, 1, 1)));
  // Touching: a vertex on the face, a vertex on an edge, an edge on an edge (crossing), vertex on vertex.
  EXPECT_TRUE(trianglesIntersect(a0, a1, a2, Vec3(1, 1, 0), Vec3(1, 1, 1), Vec3(2, 1, 1)));
  EXPECT_TRUE(trianglesIntersect(a0, a1, a2, Vec3(2, 0, 0), Vec3(2, -1, 1), Vec3(3, -1, 1)));
  EXPECT_TRUE(trianglesIntersect(a0, a1, a2, Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(1, 0, 5)));
  EXPECT_TRUE(trianglesIntersect(a0, a1, a2, Vec3(4, 0, 0), Vec3(5, 0, 1), Vec3(5, 1, 1)));
  // A vertex just beyond the hypotenuse x + y = 4 (in the plane): no contact.
  EXPECT_FALSE(trianglesIntersect(a0, a1, a2, Vec3(2, std::nextafter(2.0, 3.0), 0), Vec3(3, 3, 0), Vec3(3, 4, 0)));
  EXPECT_TRUE(trianglesIntersect(a0, a1, a2, Vec3(2, 2, 0), Vec3(3, 3, 0), Vec3(3, 4, 0)));
  // Coplanar overlapping without any vertex inside the other (a star of David).
  EXPECT_TRUE(trianglesIntersect(Vec3(0, 0, 0), Vec3(6, 0, 0), Vec3(3, 6, 0), Vec3(0, 4, 0), Vec3(6, 4, 0),
                                 Vec3(3, -2, 0)));
  // Coplanar, one inside the other.
  EXPECT_TRUE(trianglesIntersect(a0, a1, a2, Vec3(1, 1, 0), Vec3(1.5, 1, 0), Vec3(1, 1.5, 0)));
  // Parallel planes.
  EXPECT_FALSE(trianglesIntersect(a0, a1, a2, Vec3(1, 1, 1e-300), Vec3(1.5, 1, 1e-300), Vec3(1, 1.5, 1e-300)));
  // Degenerate: a segment through the face, a segment just beside it, a point on an edge, a
  // point off it by one ulp, two collinear overlapping segments, two collinear disjoint ones.
  EXPECT_TRUE(trianglesIntersect(a0, a1, a2, Vec3(1, 1, -1), Vec3(1, 1, 1), Vec3(1, 1, 1)));
  EXPECT_FALSE(trianglesIntersect(a0, a1, a2, Vec3(5, 1, -1), Vec3(5, 1, 1), Vec3(5, 1, 1)));
  EXPECT_TRUE(trianglesIntersect(a0, a1, a2, Vec3(2, 2, 0), Vec3(2, 2, 0), Vec3(2, 2, 0)));
  EXPECT_FALSE(trianglesIntersect(a0, a1, a2, Vec3(2, std::nextafter(2.0, 3.0), 0), Vec3(2, std::nextafter(2.0, 3.0), 0),
                                  Vec3(2, std::nextafter(2.0, 3.0), 0)));
  EXPECT_TRUE(trianglesIntersect(Vec3(0, 0, 0), Vec3(2, 2, 2), Vec3(1, 1, 1), Vec3(1.5, 1.5, 1.5), Vec3(3, 3, 3),
                                 Vec3(3, 3, 3)));
  EXPECT_FALSE(trianglesIntersect(Vec3(0, 0, 0), Vec3(2, 2, 2), Vec3(1, 1, 1), Vec3(2.5, 2.5, 2.5), Vec3(3, 3, 3),
                                  Vec3(3, 3, 3)));
  // Points: equal and unequal.
  EXPECT_TRUE(trianglesIntersect(Vec3(1, 2, 3), Vec3(1, 2, 3), Vec3(1, 2, 3), Vec3(1, 2, 3), Vec3(1, 2, 3),
                                 Vec3(1, 2, 3)));
  EXPECT_FALSE(trianglesIntersect(Vec3(1, 2, 3), Vec3(1, 2, 3), Vec3(1, 2, 3), Vec3(1, 2, 3.0000000000000004),
                                  Vec3(1, 2, 3.0000000000000004), Vec3(1, 2, 3.0000000000000004)));
}

TEST(OracleTriangleIntersection, ExactOnLargeOffsetsAndQuadAgreesOnClearCases) {
  SeededRandom random(99);
  int meet = 0;
  for (int i = 0; i < 20000; ++i) {
    Vec3 a[3], b[3];
    const Vec3 far = random.unitVector() * random.logUniform(0, 8);
    for (auto& v : a) v = random.inCube(1) + far;
    for (auto& v : b) v = random.inCube(1) + far;
    const bool exact = trianglesIntersect(a[0], a[1], a[2], b[0], b[1], b[2]);
    const bool swapped = trianglesIntersect(b[1], b[2], b[0], a[2], a[1], a[0]);
    ASSERT_EQ(exact, swapped) << i;
    const auto d = triangleDistance(a[0], a[1], a[2], b[0], b[1], b[2]);
    const double scale = far.norm() + 2;
    if (d.value > 1e-20 * scale) {
      ASSERT_FALSE(exact) << i << " distance " << d.value;
    } else {
      ASSERT_TRUE(exact) << i << " distance " << d.value;
    }
    meet += exact;
    ASSERT_EQ(exact, trianglesIntersect(Quad3(a[0]), Quad3(a[1]), Quad3(a[2]), Quad3(b[0]), Quad3(b[1]), Quad3(b[2])));
  }
  EXPECT_GT(meet, 3000);
}

/// The pruned brute force must find exactly what the unpruned loop over all pairs finds.
TEST(OracleMeshDistance, PruningLosesNothing) {
  const Mesh torus = shapes::torus(1.0, 0.3, 10, 5);
  const Mesh cShape = shapes::cShape(0.8, 0.2, 1.0, 6);
  SeededRandom random(3);
  for (int i = 0; i < 8; ++i) {
    const Pose poseA(Eigen::Translation3d(random.inCube(0.5)) * random.rotation());
    const Pose poseB(Eigen::Translation3d(random.inCube(1.5)) * random.rotation());
    const MeshPairDistance pruned = meshDistance(torus, poseA, cShape, poseB);
    Quad all = -1;
    for (std::size_t s = 0; s < torus.triangleCount(); ++s) {
      const auto ta = posedTriangle(torus, poseA, s);
      for (std::size_t t = 0; t < cShape.triangleCount(); ++t) {
        const auto tb = posedTriangle(cShape, poseB, t);
        const Quad d = triangleDistance(ta[0], ta[1], ta[2], tb[0], tb[1], tb[2]).distance;
        if (all < 0 || d < all) all = d;
      }
    }
    ASSERT_EQ(double(pruned.distance), double(all)) << i;
    ASSERT_TRUE(pruned.distance == all) << i << ": " << toString(pruned.distance) << " vs " << toString(all);
    EXPECT_LT(pruned.trianglePairsEvaluated, torus.triangleCount() * cShape.triangleCount());
    EXPECT_EQ(meshesIntersect(torus, poseA, cShape, poseB), pruned.value <= 1e-25) << i;
    const auto ta = posedTriangle(torus, poseA, pruned.triangleA);
    const auto tb = posedTriangle(cShape, poseB, pruned.triangleB);
    EXPECT_LE(double(pointTriangleDistance(Quad3(pruned.pointOnA), ta[0], ta[1], ta[2])), 1e-15);
    EXPECT_LE(double(pointTriangleDistance(Quad3(pruned.pointOnB), tb[0], tb[1], tb[2])), 1e-15);
  }
}

TEST(OracleMeshDistance, SpheresAtKnownDistance) {
  // Two octahedra (spheres with 4 segments) centred 5 apart along x: the tips at +-1 face each
  // other, so the distance is exactly 3, also after rotating the whole scene.
  const Mesh octahedron = shapes::sphere(1.0, 4);
  SeededRandom random(11);
  for (int i = 0; i < 20; ++i) {
    const Eigen::Quaterniond spin = random.rotation();
    const Vec3 shift = random.inCube(1e3);
    const Pose poseA(Eigen::Translation3d(shift) * spin);
    const Pose poseB(Eigen::Translation3d(shift + spin * Vec3(5, 0, 0)) * spin);
    const MeshPairDistance d = meshDistance(octahedron, poseA, octahedron, poseB);
    // The poses themselves are doubles rounded from the exact rotation: 1e-12 covers them.
    EXPECT_NEAR(d.value, 3.0, 1e-12) << i;
  }
}

}  // namespace
}  // namespace adsd::oracle
