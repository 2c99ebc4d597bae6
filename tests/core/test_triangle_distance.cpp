/// \file
/// \brief adsd::triangleDistance against hand-computed answers in every feature combination,
/// against the binary128 oracle on >= 100 000 random cases from fixed seeds (named families,
/// including near-parallel, degenerate and large-offset ones), and the two documented failures
/// of the PQP/FCL/Coal routine (issue 3) pinned as regressions.
///
/// Accuracy standard (issues 2 and 3): |distance - oracle| <= 1e-10 x the bounding-box diagonal
/// of the six corners. Witness points are doubles, so they are held to the same standard plus
/// the rounding of coordinates of their magnitude.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "adsd/triangle_distance.h"
#include "oracle.h"
#include "random_geometry.h"

namespace adsd {
namespace {

using oracle::Feature;
using oracle::Quad;
using oracle::Quad3;
using oracle::SeededRandom;

/// Relative accuracy demanded of distances (issues 2 and 3), times the scene's diagonal.
constexpr double kAccuracy = 1e-10;
/// A double witness coordinate of magnitude m carries rounding up to m * 2^-53 per operation
/// that produced it; 1e-15 x the largest |coordinate| (about 9 units in the last place) is the
/// allowance on top of kAccuracy for "lies on the triangle" and "realizes the distance".
constexpr double kWitnessRounding = 1e-15;

struct TrianglePair {
  std::array<Vec3, 3> a, b;
};

double diagonal(const TrianglePair& c) {
  Eigen::AlignedBox3d box;
  for (const Vec3& v : c.a) box.extend(v);
  for (const Vec3& v : c.b) box.extend(v);
  return box.diagonal().norm();
}

double largestCoordinate(const TrianglePair& c) {
  double m = 0;
  for (const Vec3& v : c.a) m = std::max(m, v.cwiseAbs().maxCoeff());
  for (const Vec3& v : c.b) m = std::max(m, v.cwiseAbs().maxCoeff());
  return m;
}

std::string describe(const TrianglePair& c) {
  std::ostringstream out;
  out.precision(17);
  out << "A = {";
  for (const Vec3& v : c.a) out << " (" << v.x() << ", " << v.y() << ", " << v.z() << ")";
  out << " }  B = {";
  for (const Vec3& v : c.b) out << " (" << v.x() << ", " << v.y() << ", " << v.z() << ")";
  out << " }";
  return out.str();
}

TrianglePairResult production(const TrianglePair& c) {
  return triangleDistance(c.a[0], c.a[1], c.a[2], c.b[0], c.b[1], c.b[2]);
}

oracle::TrianglePairDistance reference(const TrianglePair& c) {
  return oracle::triangleDistance(c.a[0], c.a[1], c.a[2], c.b[0], c.b[1], c.b[2]);
}

bool exactlyIntersecting(const TrianglePair& c) {
  return oracle::trianglesIntersect(c.a[0], c.a[1], c.a[2], c.b[0], c.b[1], c.b[2]);
}

/// Distance in binary128 from a double point to a triangle.
double offTriangle(const Vec3& p, const std::array<Vec3, 3>& t) {
  return double(oracle::pointTriangleDistance(Quad3(p), Quad3(t[0]), Quad3(t[1]), Quad3(t[2])));
}

/// The whole contract of one answer: no NaN or infinity, distance within the standard of the
/// oracle's, the collision decision right whenever the oracle is clear of zero, and (optionally)
/// witnesses on their triangles realizing the distance. Returns the error / diagonal via *error.
::testing::AssertionResult answersLikeOracle(const TrianglePair& c, const TrianglePairResult& r,
                                             const oracle::TrianglePairDistance& o, bool checkWitnesses,
                                             double* error = nullptr) {
  const double diag = diagonal(c);
  const double tolerance = kAccuracy * diag;
  const double witnessTolerance = tolerance + kWitnessRounding * largestCoordinate(c);
  auto fail = [&]() {
    return ::testing::AssertionFailure() << describe(c) << "\n  production " << r.distance << " oracle "
                                         << oracle::toString(o.distance) << " diagonal " << diag << ": ";
  };
  if (!std::isfinite(r.distance) || !r.pointOnA.allFinite() || !r.pointOnB.allFinite()) {
    return fail() << "[non-finite] result";
  }
  const double e = std::abs(r.distance - o.value);
  if (error) *error = diag > 0 ? e / diag : e;
  if (o.value > tolerance && !(r.distance > 0)) return fail() << "[false contact] reports 0, but they are apart";
  if (e > tolerance) {
    return fail() << (r.distance > o.value ? "[too large]" : "[too small]") << " error " << e << " exceeds " << tolerance;
  }
  if (checkWitnesses) {
    const double realized = (r.pointOnA - r.pointOnB).norm();
    if (std::abs(realized - r.distance) > witnessTolerance) {
      return fail() << "[witness gap] witnesses are " << realized << " apart, distance says " << r.distance;
    }
    if (offTriangle(r.pointOnA, c.a) > witnessTolerance) {
      return fail() << "[witness off A] pointOnA is " << offTriangle(r.pointOnA, c.a) << " off triangle A";
    }
    if (offTriangle(r.pointOnB, c.b) > witnessTolerance) {
      return fail() << "[witness off B] pointOnB is " << offTriangle(r.pointOnB, c.b) << " off triangle B";
    }
  }
  return ::testing::AssertionSuccess();
}

/// The 72 orderings of one case: the 6 corner orders of each triangle, and A and B swapped.
std::vector<TrianglePair> orderings(const TrianglePair& c) {
  static constexpr int kOrders[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  std::vector<TrianglePair> out;
  for (const auto& oa : kOrders) {
    for (const auto& ob : kOrders) {
      TrianglePair p;
      for (int k = 0; k < 3; ++k) {
        p.a[k] = c.a[oa[k]];
        p.b[k] = c.b[ob[k]];
      }
      out.push_back(p);
      out.push_back({p.b, p.a});
    }
  }
  return out;
}

/// A hand-computed case: every ordering must give the expected distance within the standard,
/// with valid witnesses; the oracle must agree with the hand computation too.
void expectDistance(const TrianglePair& c, double expected) {
  const double tolerance = kAccuracy * diagonal(c);
  const auto o = reference(c);
  ASSERT_NEAR(o.value, expected, 1e-25 * std::max(1.0, largestCoordinate(c))) << "oracle disagrees with the hand computation";
  for (const TrianglePair& p : orderings(c)) {
    const TrianglePairResult r = production(p);
    EXPECT_NEAR(r.distance, expected, tolerance) << describe(p);
    EXPECT_TRUE(answersLikeOracle(p, r, o, true));
  }
}

TrianglePair pair(Vec3 a0, Vec3 a1, Vec3 a2, Vec3 b0, Vec3 b1, Vec3 b2) { return {{a0, a1, a2}, {b0, b1, b2}}; }

// ---------------------------------------------------------------------------------------------
// Every feature pair, by hand.

TEST(TriangleDistance, VertexFace) {
  expectDistance(pair({0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, 0.5}, {1, 1, 3}, {2, 1, 3}), 0.5);
  // The vertex above a point of the face near an edge, and the face tilted out of the axes.
  expectDistance(pair({0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {3.9, 0.05, 0.25}, {3, 1, 3}, {4, 2, 3}), 0.25);
}

TEST(TriangleDistance, EdgeEdge) {
  expectDistance(pair({-1, 0, 0}, {1, 0, 0}, {0, 0, -1}, {0, -1, 0.25}, {0, 1, 0.25}, {0, 0, 1.25}), 0.25);
  expectDistance(pair({0, 0, 0}, {2, 0, 0}, {1, 0, -3}, {1, -1, 1}, {1, 1, 1.5}, {1, 0, 5}), 5 / std::sqrt(17.0));
}

TEST(TriangleDistance, VertexEdgeAndVertexVertex) {
  // B's corner faces A's edge from outside A's plane, past the ends of the other features.
  expectDistance(pair({0, 0, 0}, {2, 0, 0}, {1, 2, 0}, {1, -3, 4}, {1, -5, 4}, {0, -4, 6}), 5.0);
  // Corner to corner: (2, 0, 0) and (2 + 3, 4, 0) facing each other.
  expectDistance(pair({0, 0, 0}, {2, 0, 0}, {0, -2, 0}, {5, 4, 0}, {7, 4, 0}, {5, 6, 0}), 5.0);
}

TEST(TriangleDistance, ParallelEdges) {
  const double h = 0.125;
  expectDistance(pair({0, 0, 0}, {2, 0, 0}, {1, 0, -1}, {1, 0, h}, {3, 0, h}, {2, 0, h + 1}), h);
  expectDistance(pair({0, 0, 0}, {2, 0, 0}, {1, 0, -1}, {3, 0, h}, {5, 0, h}, {4, 0, h + 1}), std::sqrt(1 + h * h));
  expectDistance(pair({0, 0, 0}, {2, 0, 0}, {1, -1, -1}, {0.5, 3, 4}, {1.5, 3, 4}, {1, 4, 5}), 5.0);
  // Collinear edges with a gap between them.
  expectDistance(pair({0, 0, 0}, {2, 0, 0}, {1, 0, -1}, {2.5, 0, 0}, {4, 0, 0}, {3, 0, 1}), 0.5);
}

TEST(TriangleDistance, ParallelFaces) {
  expectDistance(pair({0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0.5, 0.5, 0.75}, {3, 0.5, 0.75}, {0.5, 3, 0.75}), 0.75);
  // Identical triangles stacked, and one fully inside the other's shadow.
  expectDistance(pair({0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 0, 1e-3}, {2, 0, 1e-3}, {0, 2, 1e-3}), 1e-3);
  expectDistance(pair({0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, -2}, {1.5, 1, -2}, {1, 1.5, -2}), 2.0);
}

TEST(TriangleDistance, Coplanar) {
  expectDistance(pair({0, 0, 1}, {2, 0, 1}, {0, 2, 1}, {0.5, 0.5, 1}, {3, 0.5, 1}, {0.5, 3, 1}), 0.0);
  expectDistance(pair({0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}, {3, 1, 1}, {1, 3, 1}), std::sqrt(0.5));
  expectDistance(pair({0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {2, 0, 1}, {3, 0, 1}, {2, 1, 1}), 1.0);
  // Touching at a shared vertex, along a shared edge, and a vertex on the other's edge.
  expectDistance(pair({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {2, 0, 0}, {2, 1, 0}), 0.0);
  expectDistance(pair({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}), 0.0);
  expectDistance(pair({0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 0, 0}, {2, -1, 0}, {1, -1, 0}), 0.0);
  // One inside the other; a star of David (overlap, no corner inside the other).
  expectDistance(pair({0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, 0}, {1.5, 1, 0}, {1, 1.5, 0}), 0.0);
  expectDistance(pair({0, 0, 0}, {6, 0, 0}, {3, 6, 0}, {0, 4, 0}, {6, 4, 0}, {3, -2, 0}), 0.0);
}

TEST(TriangleDistance, IntersectingGivesZeroAndOneWitness) {
  // Piercing through the interior; crossing like an X (each cuts the other); edge through edge.
  const TrianglePair cases[] = {
      pair({0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, -1}, {1, 1, 1}, {2, 1, 1}),
      pair({-2, -1, 0}, {2, -1, 0}, {0, 2, 0}, {0, -2, -1}, {0, 0.5, 1.5}, {0, 1.5, -1}),
      pair({0, 0, 0}, {2, 0, 0}, {1, 0, -2}, {1, -1, 0}, {1, 1, 0}, {1, 0, 3}),
  };
  for (const TrianglePair& c : cases) {
    ASSERT_TRUE(exactlyIntersecting(c));
    for (const TrianglePair& p : orderings(c)) {
      const TrianglePairResult r = production(p);
      // The header's contract: 0 when the triangles intersect, witnesses equal.
      EXPECT_EQ(r.distance, 0.0) << describe(p);
      EXPECT_LE((r.pointOnA - r.pointOnB).norm(), kWitnessRounding * 4) << describe(p);
      EXPECT_LE(offTriangle(r.pointOnA, p.a), 1e-14) << describe(p);
      EXPECT_LE(offTriangle(r.pointOnB, p.b), 1e-14) << describe(p);
    }
  }
}

TEST(TriangleDistance, ZeroAreaTriangles) {
  const Vec3 p(1, 2, 3), q(4, 6, 3);
  expectDistance(pair(p, p, p, q, q, q), 5.0);                                                  // point-point
  expectDistance(pair({1, 3, 4}, {1, 3, 4}, {1, 3, 4}, {0, 0, 0}, {2, 0, 0}, {1, 0, 0}), 5.0);  // point-segment
  expectDistance(pair({0, 0, 0}, {2, 0, 0}, {2, 0, 0}, {1, -1, 2}, {1, 1, 2}, {1, 1, 2}), 2.0);  // segment-segment
  expectDistance(pair({1, 1, 3}, {1, 1, 3}, {1, 1, 3}, {0, 0, 0}, {4, 0, 0}, {0, 4, 0}), 3.0);  // point-face
  expectDistance(pair({2, -3, 4}, {2, -3, 4}, {2, -3, 4}, {0, 0, 0}, {4, 0, 0}, {0, 4, 0}), 5.0);
  // A segment parallel to a face above it; a segment through a face; a segment in the face's plane.
  expectDistance(pair({1, 1, 2}, {2, 1, 2}, {1.5, 1, 2}, {0, 0, 0}, {4, 0, 0}, {0, 4, 0}), 2.0);
  expectDistance(pair({1, 1, -2}, {1, 1, 2}, {1, 1, 0.5}, {0, 0, 0}, {4, 0, 0}, {0, 4, 0}), 0.0);
  // (5, 1) is (5 + 1 - 4) / sqrt(2) from the hypotenuse x + y = 4.
  expectDistance(pair({5, 1, 0}, {7, 1, 0}, {6, 1, 0}, {0, 0, 0}, {4, 0, 0}, {0, 4, 0}), std::sqrt(2.0));
  // Collinear overlapping segments, and a point on a segment.
  expectDistance(pair({0, 0, 0}, {2, 2, 2}, {1, 1, 1}, {1.5, 1.5, 1.5}, {3, 3, 3}, {3, 3, 3}), 0.0);
  expectDistance(pair({1, 1, 1}, {1, 1, 1}, {1, 1, 1}, {0, 0, 0}, {2, 2, 2}, {2, 2, 2}), 0.0);
}

TEST(TriangleDistance, RepeatedVertices) {
  expectDistance(pair({0, 0, 0}, {0, 0, 0}, {2, 0, 0}, {1, 3, 4}, {1, 3, 4}, {1, 5, 4}), 5.0);
  expectDistance(pair({0, 0, 0}, {2, 0, 0}, {0, 0, 0}, {0, 0, 1}, {2, 0, 1}, {2, 0, 1}), 1.0);
  // Identical triangles: distance 0.
  expectDistance(pair({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}), 0.0);
}

// A corner of B 0.74 above a 1.4 cm face of A in the plane y = 0.25555 (CGAL's fandisk, a CAD
// mesh, against the mushroom, found by an outside review): its foot came out 3e-16 off that
// plane, outside the face's corner box (5e-17 thick), and the edges answered 2e-6 too far.
TEST(TriangleDistanceRegression, CornerFarAboveAFaceOfConstantCoordinateMeetsItsInterior) {
  const TrianglePair c = pair({0.1789, 0.25555, -0.0535}, {0.1697, 0.25555, -0.0674}, {0.1687, 0.25555, -0.0535},
                              {0.20943673757555648, 1.0002922856765244, -0.011716142802311258},
                              {0.17275487719336244, 0.99966491455999995, -0.059684878707933958},
                              {0.17942189596691793, 1.039065543696698, -0.023602224061893384});
  const auto o = reference(c);
  ASSERT_NEAR(o.value, 0.99966491455999995 - 0.25555, 1e-15);
  for (const TrianglePair& p : orderings(c)) {
    const TrianglePairResult r = production(p);
    EXPECT_TRUE(answersLikeOracle(p, r, o, true));
  }
}

// ---------------------------------------------------------------------------------------------
// Issue 3: the two documented failures of the PQP/FCL/Coal TriDist routine.

TEST(TriangleDistanceRegression, PqpExactlyParallelEdgesNear8000AreAbout1e12Apart) {
  // github.com/GammaUNC/PQP issue 4: TriDist returns hundreds of units. S is horizontal, T is
  // vertical; S's corner s2 is 2 ulps (1.8e-12) in y from T's plane and projects inside T.
  const TrianglePair c = pair({8000.0000000000036, 6817.7672478170962, 571.00166381103077},
                              {7500.0000000000009, 6817.7672478170962, 571.00166381103077},
                              {7500.0000000000009, 6327.6345143037688, 571.00166381103077},
                              {8000.0000000000009, 6327.6345143037670, 88.336618780016408},
                              {7500.0, 6327.6345143037670, 88.336618780016408},
                              {7500.0, 6327.6345143037670, 1015.9309593449836});
  const auto o = reference(c);
  ASSERT_NEAR(o.value, 6327.6345143037688 - 6327.6345143037670, 1e-25);
  ASSERT_FALSE(exactlyIntersecting(c));
  for (const TrianglePair& p : orderings(c)) {
    const TrianglePairResult r = production(p);
    EXPECT_TRUE(answersLikeOracle(p, r, o, true));
    EXPECT_LT(r.distance, 1e-9) << describe(p);  // not hundreds, not even a nanometre per metre
  }
}

TEST(TriangleDistanceRegression, TrianglesWithEdgesBelow2e4AreNotReportedTouching) {
  // PQP/FCL/Coal skip the vertex-face test when the squared normal length is below 1e-15, i.e.
  // for edges below about 2e-4, and fall through to "distance 0". Here a corner hangs over the
  // face (vertex-face) and a face hovers over the face (parallel), at every size from 1e-3 down.
  for (double size = 1e-3; size >= 1e-9; size /= 4) {
    const double gap = 0.5 * size;
    const TrianglePair vertexFace = pair({0, 0, 0}, {size, 0, 0}, {0, size, 0}, {0.2 * size, 0.2 * size, gap},
                                         {size, 0.2 * size, 1.5 * size}, {0.2 * size, size, 1.5 * size});
    const TrianglePair parallel = pair({0, 0, 0}, {size, 0, 0}, {0, size, 0}, {0.1 * size, 0.1 * size, gap},
                                       {1.1 * size, 0.1 * size, gap}, {0.1 * size, 1.1 * size, gap});
    for (const TrianglePair& c : {vertexFace, parallel}) {
      const auto o = reference(c);
      ASSERT_NEAR(o.value, gap, 1e-30);
      for (const TrianglePair& p : orderings(c)) {
        const TrianglePairResult r = production(p);
        EXPECT_GT(r.distance, 0.0) << "false contact at size " << size << ": " << describe(p);
        EXPECT_TRUE(answersLikeOracle(p, r, o, true)) << "size " << size;
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Random families against the oracle.

/// What one family's cases turned out to be (so that a test can check the sample really hit the
/// intended mix: STYLE habit 10).
struct FamilyStats {
  int cases = 0;
  int intersecting = 0;
  int edgeEdge = 0;    ///< oracle's minimum on an edge x edge (or vertex x edge) pair
  int vertexFace = 0;  ///< oracle's minimum on a vertex/edge x interior pair
  double worstError = 0;  ///< max |error| / diagonal
};

using Generator = std::function<TrianglePair(SeededRandom&)>;

/// The "[kind]" tag of a failure message.
std::string failureKind(const std::string& message) {
  const auto open = message.find('['), close = message.find(']', open == std::string::npos ? 0 : open);
  return open == std::string::npos || close == std::string::npos ? "other" : message.substr(open, close - open + 1);
}

FamilyStats runFamily(const char* name, std::uint64_t seed, int count, const Generator& generate) {
  SeededRandom random(seed);
  FamilyStats stats;
  int failures = 0;
  std::map<std::string, int> failuresByKind;
  for (int i = 0; i < count; ++i) {
    const TrianglePair c = generate(random);
    const auto o = reference(c);
    const TrianglePairResult r = production(c);
    double error = 0;
    // Witnesses on every 8th case (they cost two more oracle calls); orderings on every 16th.
    const auto verdict = answersLikeOracle(c, r, o, i % 8 == 0, &error);
    if (!verdict) {
      // The first two cases of each kind of failure are reported in full (exact inputs).
      if (failuresByKind[failureKind(verdict.message())]++ < 2) {
        ADD_FAILURE() << name << " seed " << seed << " case " << i << ": " << verdict.message();
      }
      ++failures;
    }
    if (i % 16 == 0) {
      for (const TrianglePair& p : {TrianglePair{c.b, c.a}, TrianglePair{{c.a[1], c.a[2], c.a[0]}, {c.b[2], c.b[1], c.b[0]}}}) {
        const auto permuted = answersLikeOracle(p, production(p), o, false);
        if (!permuted) {
          if (failuresByKind[failureKind(permuted.message()) + " reordered"]++ < 2) {
            ADD_FAILURE() << name << " seed " << seed << " case " << i << " reordered: " << permuted.message();
          }
          ++failures;
        }
      }
    }
    ++stats.cases;
    stats.worstError = std::max(stats.worstError, error);
    if (exactlyIntersecting(c)) ++stats.intersecting;
    const bool onEdges = o.featureA != Feature::interior && o.featureB != Feature::interior &&
                         (o.featureA == Feature::edge || o.featureB == Feature::edge);
    stats.edgeEdge += onEdges;
    stats.vertexFace += (o.featureA == Feature::interior) != (o.featureB == Feature::interior);
  }
  EXPECT_EQ(failures, 0) << name << ": " << failures << " of " << count << " cases failed";
  std::printf("%-22s cases %6d  intersecting %6d  edge-edge %6d  vertex-face %6d  max error/diagonal %.3g\n",
              name, stats.cases, stats.intersecting, stats.edgeEdge, stats.vertexFace, stats.worstError);
  for (const auto& [kind, n] : failuresByKind) std::printf("    failed %-28s %d times\n", kind.c_str(), n);
  return stats;
}

std::array<Vec3, 3> randomTriangle(SeededRandom& random, double halfSide = 1.0) {
  return {random.inCube(halfSide), random.inCube(halfSide), random.inCube(halfSide)};
}

/// Any unit vector perpendicular to the unit vector d.
Vec3 perpendicularTo(const Vec3& d, SeededRandom& random) {
  for (;;) {
    const Vec3 v = random.unitVector();
    const Vec3 p = v - v.dot(d) * d;
    if (p.norm() > 0.1) return p.normalized();
  }
}

/// A close but separated generic pair: B shifted so that the gap is gap-ish (or overlapping
/// when gap is small).
TrianglePair closePair(SeededRandom& random, double gap) {
  TrianglePair c{randomTriangle(random), randomTriangle(random, 0.5)};
  const Vec3 away = random.unitVector();
  // Push B out along `away` until its projection clears A's by `gap`.
  double maxA = -INFINITY, minB = INFINITY;
  for (const Vec3& v : c.a) maxA = std::max(maxA, v.dot(away));
  for (const Vec3& v : c.b) minB = std::min(minB, v.dot(away));
  for (Vec3& v : c.b) v += (maxA - minB + gap) * away;
  return c;
}

/// Exact axis permutation and sign flips of all six points (keeps exact parallelism/coplanarity).
TrianglePair shuffleAxes(TrianglePair c, SeededRandom& random) {
  static constexpr int kPermutations[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  const int* perm = kPermutations[random.below(6)];
  const Vec3 sign(random.below(2) ? 1 : -1, random.below(2) ? 1 : -1, random.below(2) ? 1 : -1);
  for (auto* t : {&c.a, &c.b}) {
    for (Vec3& v : *t) v = Vec3(sign[0] * v[perm[0]], sign[1] * v[perm[1]], sign[2] * v[perm[2]]);
  }
  return c;
}

/// Multiple of 2^-10 in [-1, 1]: sums, differences and halves of these are exact.
double dyadic(SeededRandom& random) { return std::ldexp(double(random.below(2049)) - 1024.0, -10); }

TEST(TriangleDistanceRandom, AgainstOracle) {
  int total = 0;
  std::map<std::string, FamilyStats> stats;
  auto run = [&](const char* name, std::uint64_t seed, int count, const Generator& g) {
    stats[name] = runFamily(name, seed, count, g);
    total += count;
  };

  run("generic", 101, 12000, [](SeededRandom& r) { return TrianglePair{randomTriangle(r), randomTriangle(r)}; });

  run("separated", 102, 12000, [](SeededRandom& r) { return closePair(r, r.uniform(0.01, 2.0)); });

  run("near-parallel edges", 103, 14000, [](SeededRandom& r) {
    // A's edge a0a1 and B's edge b0b1 nearly parallel (tilt 1e-16 ... 1e-1 rad, or exactly 0),
    // overlapping along their length, offset by 1e-12 ... 1 of the edge length; the two third
    // corners point away from each other, so the edges carry the minimum.
    const Vec3 a0 = r.inCube(1), direction = r.unitVector();
    const double length = r.uniform(0.2, 2.0);
    const Vec3 side = perpendicularTo(direction, r);
    const double tilt = r.below(8) == 0 ? 0.0 : r.logUniform(-16, -1);
    const Vec3 tilted = Eigen::AngleAxisd(tilt, perpendicularTo(direction, r)) * direction;
    const double offset = length * r.logUniform(-12, 0);
    TrianglePair c;
    c.a = {a0, a0 + length * direction, a0 + 0.5 * length * direction - r.uniform(0.1, 1.0) * side +
                                            r.uniform(-0.3, 0.3) * perpendicularTo(side, r)};
    const Vec3 b0 = a0 + r.uniform(-0.5, 0.5) * length * direction + offset * side;
    c.b = {b0, b0 + r.uniform(0.3, 1.5) * length * tilted,
           b0 + r.uniform(-0.5, 1.0) * length * direction + r.uniform(0.1, 1.0) * side};
    return c;
  });

  run("parallel faces", 104, 12000, [](SeededRandom& r) {
    // Exactly parallel planes z = c and z = c + gap (gap 1e-14 ... 1), then an exact axis shuffle.
    const double c0 = dyadic(r), gap = r.logUniform(-14, 0);
    TrianglePair c;
    for (Vec3& v : c.a) v = Vec3(r.uniform(-1, 1), r.uniform(-1, 1), c0);
    for (Vec3& v : c.b) v = Vec3(r.uniform(-1, 1), r.uniform(-1, 1), c0 + gap);
    return shuffleAxes(c, r);
  });

  run("coplanar", 105, 12000, [](SeededRandom& r) {
    // Both in the plane z = c on a dyadic grid: overlapping, disjoint, or touching exactly (a
    // shared corner, or B's corner at the midpoint of A's edge with B pointing away).
    const double z = dyadic(r);
    TrianglePair c;
    for (Vec3& v : c.a) v = Vec3(dyadic(r), dyadic(r), z);
    const int kind = int(r.below(3));
    if (kind == 0) {
      for (Vec3& v : c.b) v = Vec3(dyadic(r), dyadic(r), z);
    } else {
      const int k = int(r.below(3));
      const Vec3 touch = kind == 1 ? c.a[k] : Vec3(0.5 * (c.a[k] + c.a[(k + 1) % 3]));
      // Away from A: the side of edge k opposite A's third corner (or away from A's centroid).
      const Vec3 centroid = (c.a[0] + c.a[1] + c.a[2]) / 3.0;
      Vec3 outward = touch - centroid;
      outward.z() = 0;
      c.b = {touch, touch + Vec3(std::ldexp(std::round(std::ldexp(outward.x(), 8)), -8), std::ldexp(std::round(std::ldexp(outward.y(), 8)), -8), 0),
             touch + Vec3(dyadic(r), dyadic(r), 0)};
    }
    return shuffleAxes(c, r);
  });

  run("large offset", 106, 12000, [](SeededRandom& r) {
    // A close pair (gap 1e-6 ... 1) translated far away: 1e3 ... 1e8 from the origin.
    TrianglePair c = closePair(r, r.logUniform(-6, 0));
    const Vec3 far = r.unitVector() * r.logUniform(3, 8);
    for (auto* t : {&c.a, &c.b}) {
      for (Vec3& v : *t) v += far;
    }
    return c;
  });

  run("scaled", 107, 10000, [](SeededRandom& r) {
    TrianglePair c = closePair(r, r.logUniform(-4, 0));
    const double scale = r.logUniform(-6, 6);
    for (auto* t : {&c.a, &c.b}) {
      for (Vec3& v : *t) v *= scale;
    }
    return c;
  });

  run("degenerate", 108, 12000, [](SeededRandom& r) {
    // Slivers, needles, exactly collinear, repeated corners and points, against anything.
    auto make = [&r]() -> std::array<Vec3, 3> {
      std::array<Vec3, 3> t = randomTriangle(r);
      switch (r.below(6)) {
        case 0: {  // sliver: third corner 1e-16 ... 1e-4 off the line of the other two
          const Vec3 d = (t[1] - t[0]).normalized();
          t[2] = t[0] + r.uniform(-0.5, 1.5) * (t[1] - t[0]) + r.logUniform(-16, -4) * perpendicularTo(d, r);
          break;
        }
        case 1: t[1] = t[0] + r.logUniform(-12, -4) * r.unitVector(); break;  // needle
        case 2: t[2] = t[1]; break;                                           // repeated corner
        case 3: t[1] = t[0]; t[2] = t[0]; break;                              // a point
        case 4: {  // exactly collinear: an axis-parallel segment
          const int axis = int(r.below(3));
          t[1] = t[0];
          t[2] = t[0];
          t[1][axis] += r.uniform(-1, 1);
          t[2][axis] += r.uniform(-1, 1);
          break;
        }
        default: break;  // a regular triangle
      }
      return t;
    };
    return TrianglePair{make(), make()};
  });

  run("near contact", 109, 12000, [](SeededRandom& r) {
    // B's corner hovering 1e-14 ... 1e-6 (x size) above a point of A's interior, or exactly on
    // A's corner (touching, distance 0), the rest of B further out on the same side.
    TrianglePair c;
    c.a = randomTriangle(r);
    const Vec3 normal = (c.a[1] - c.a[0]).cross(c.a[2] - c.a[0]).normalized();
    const double size = diagonal({c.a, c.a});
    Vec3 tip;
    if (r.below(4) == 0) {
      tip = c.a[r.below(3)];
    } else {
      double u = r.uniform(), v = r.uniform();
      if (u + v > 1) {
        u = 1 - u;
        v = 1 - v;
      }
      tip = c.a[0] + u * (c.a[1] - c.a[0]) + v * (c.a[2] - c.a[0]) + r.logUniform(-14, -6) * size * normal;
    }
    c.b = {tip, tip + r.uniform(0.1, 1) * normal + 0.5 * r.inCube(1), tip + r.uniform(0.1, 1) * normal + 0.5 * r.inCube(1)};
    return c;
  });

  run("far above a flat face", 110, 8000, [](SeededRandom& r) {
    // A small face (1e-3 ... 1e-1 across) in a plane of constant coordinate, as CAD meshes have
    // them, and B's lowest corner 20 ... 2000 face sizes above a point over it: the foot of that
    // corner carries rounding of its height, not of the face, and must still count as inside.
    const double size = r.logUniform(-3, -1), level = r.uniform(-1, 1);
    TrianglePair c;
    for (Vec3& v : c.a) v = Vec3(r.uniform(-size, size), r.uniform(-size, size), level);
    const Vec3 centroid = (c.a[0] + c.a[1] + c.a[2]) / 3.0;
    const Vec3 tip =
        centroid + Vec3(r.uniform(-0.3, 0.3) * size, r.uniform(-0.3, 0.3) * size, size * r.logUniform(1.3, 3.3));
    c.b = {tip, tip + r.uniform(0.1, 1) * size * Vec3(r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(0.2, 1)),
           tip + r.uniform(0.1, 1) * size * Vec3(r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(0.2, 1))};
    return shuffleAxes(c, r);
  });

  EXPECT_GE(total, 100000);
  // The families hit what they are named for.
  EXPECT_GT(stats["generic"].intersecting, 2000);
  EXPECT_LT(stats["separated"].intersecting, 100);
  EXPECT_GT(stats["near-parallel edges"].edgeEdge, 7000);
  EXPECT_GT(stats["parallel faces"].vertexFace, 1500);
  EXPECT_GT(stats["parallel faces"].edgeEdge, 1500);
  EXPECT_GT(stats["coplanar"].intersecting, 6000);
  EXPECT_LT(stats["coplanar"].intersecting, 11000);
  EXPECT_GT(stats["near contact"].vertexFace, 6000);
  EXPECT_GT(stats["near contact"].intersecting, 2000);
  EXPECT_GT(stats["far above a flat face"].vertexFace, 2000);
}

/// Triangles that cross each other with a margin (an edge pierces the other's interior well
/// away from its boundary) must report exactly 0 with coincident witnesses: the header's
/// contract for intersecting triangles.
TEST(TriangleDistanceRandom, ClearlyCrossingTrianglesGiveExactlyZero) {
  SeededRandom random(110);
  for (int i = 0; i < 5000; ++i) {
    TrianglePair c;
    c.a = randomTriangle(random);
    const Vec3 normal = (c.a[1] - c.a[0]).cross(c.a[2] - c.a[0]).normalized();
    // A point well inside A (barycentric >= 0.2), and B's edge through it, both ends >= 0.1 away
    // from A's plane.
    double u = random.uniform(0.2, 0.6), v = random.uniform(0.2, 0.6);
    if (u + v > 0.8) {
      u *= 0.5;
      v *= 0.5;
    }
    const Vec3 inside = c.a[0] + u * (c.a[1] - c.a[0]) + v * (c.a[2] - c.a[0]);
    const Vec3 through = (normal + 0.5 * random.inCube(1)).normalized();
    c.b = {inside + random.uniform(0.1, 1) * through, inside - random.uniform(0.1, 1) * through,
           inside + random.inCube(1)};
    if ((c.a[1] - c.a[0]).cross(c.a[2] - c.a[0]).norm() < 0.05) continue;  // too thin for a margin
    ASSERT_TRUE(exactlyIntersecting(c)) << describe(c);
    const TrianglePairResult r = production(c);
    ASSERT_EQ(r.distance, 0.0) << "case " << i << ": " << describe(c);
    ASSERT_LE((r.pointOnA - r.pointOnB).norm(), 1e-15) << describe(c);
  }
}

/// triangleDistanceUpTo, the validity queries' version that may stop at the first candidate
/// within `enough`, against the oracle: it decides "within enough?" as the minimum does, never
/// reports less than the minimum, its witnesses realize what it reports, and when the minimum is
/// clearly beyond `enough` it is triangleDistance's answer to the bit.
TEST(TriangleDistanceRandom, UpToDecidesLikeTheMinimum) {
  SeededRandom random(111);
  int stoppedEarly = 0, within = 0, beyond = 0;
  for (int i = 0; i < 20000; ++i) {
    // Pairs from deeply overlapping to 0.1 apart, thresholds from 0 to 0.15.
    const TrianglePair c = closePair(random, random.uniform(-1.0, 0.1));
    const double enough = i % 4 == 0 ? 0.0 : random.uniform(0.0, 0.15);
    const auto o = reference(c);
    const double tolerance = kAccuracy * diagonal(c);
    const TrianglePairResult full = production(c);
    const TrianglePairResult r = triangleDistanceUpTo(c.a[0], c.a[1], c.a[2], c.b[0], c.b[1], c.b[2], enough);
    ASSERT_TRUE(std::isfinite(r.distance) && r.pointOnA.allFinite() && r.pointOnB.allFinite()) << describe(c);
    ASSERT_GE(r.distance, o.value - tolerance) << "below the minimum: " << describe(c);
    ASSERT_NEAR((r.pointOnA - r.pointOnB).norm(), r.distance, tolerance) << describe(c);
    ASSERT_LE(offTriangle(r.pointOnA, c.a), tolerance + kWitnessRounding * largestCoordinate(c)) << describe(c);
    ASSERT_LE(offTriangle(r.pointOnB, c.b), tolerance + kWitnessRounding * largestCoordinate(c)) << describe(c);
    if (o.value < enough - tolerance) {
      ++within;
      ASSERT_LE(r.distance, enough) << "minimum " << o.value << " within " << enough << ": " << describe(c);
      stoppedEarly += r.distance != full.distance || r.pointOnA != full.pointOnA;
    } else if (o.value > enough + tolerance) {
      ++beyond;
      ASSERT_EQ(r.distance, full.distance) << describe(c);
      ASSERT_EQ(r.pointOnA, full.pointOnA) << describe(c);
      ASSERT_EQ(r.pointOnB, full.pointOnB) << describe(c);
    }
  }
  // The sample covers both sides, and the early stop happens (it is what the function is for).
  std::printf("within %d, beyond %d, stopped early (answer differs from the minimum's) %d\n", within, beyond,
              stoppedEarly);
  EXPECT_GT(within, 3000);
  EXPECT_GT(beyond, 3000);
  EXPECT_GT(stoppedEarly, 200);
}

/// triangleDistanceBelow against the oracle, with ceilings on both sides of the minimum: below its
/// ceiling it is as accurate as triangleDistance; at or beyond it, it never reports less than the
/// ceiling (nor, when it reports a finite distance, anything its witnesses do not realize), so a
/// traversal that passes its best answer so far can neither miss a nearer pair nor take a false one.
TEST(TriangleDistanceRandom, BelowIsExactUnderItsCeilingAndNeverBelowItAbove) {
  SeededRandom random(112);
  int under = 0, over = 0, leftOut = 0;
  for (int i = 0; i < 20000; ++i) {
    // Pairs from overlapping to 0.5 apart, ceilings from half to twice the minimum.
    const TrianglePair c = closePair(random, random.uniform(-0.2, 0.5));
    const auto o = reference(c);
    const double tolerance = kAccuracy * diagonal(c);
    const double ceiling = i % 5 == 0 ? o.value : o.value * random.uniform(0.5, 2.0);
    const TrianglePairResult r =
        triangleDistanceBelow(c.a[0], c.a[1], c.a[2], c.b[0], c.b[1], c.b[2], -1.0, ceiling);
    ASSERT_FALSE(std::isnan(r.distance)) << describe(c);
    if (o.value < ceiling - tolerance) {
      ++under;
      ASSERT_TRUE(answersLikeOracle(c, r, o, i % 4 == 0)) << "ceiling " << ceiling;
      continue;
    }
    ++over;
    ASSERT_GE(r.distance, ceiling - tolerance) << "minimum " << o.value << ", ceiling " << ceiling << ": " << describe(c);
    if (std::isinf(r.distance)) {
      ++leftOut;
      continue;
    }
    ASSERT_NEAR((r.pointOnA - r.pointOnB).norm(), r.distance, tolerance + kWitnessRounding * largestCoordinate(c));
    ASSERT_LE(offTriangle(r.pointOnA, c.a), tolerance + kWitnessRounding * largestCoordinate(c)) << describe(c);
    ASSERT_LE(offTriangle(r.pointOnB, c.b), tolerance + kWitnessRounding * largestCoordinate(c)) << describe(c);
  }
  std::printf("under the ceiling %d, at or over it %d, every candidate left out %d\n", under, over, leftOut);
  EXPECT_GT(under, 3000);
  EXPECT_GT(over, 3000);
  EXPECT_GT(leftOut, 500);  // the pruning happens (it is what the function is for)
}

}  // namespace
}  // namespace adsd
