/// \file
/// \brief Triangle-triangle distance by enumerating the faces of the product of the triangles.
///
/// Write A = {a0 + s1 (a1 - a0) + s2 (a2 - a0) : s in the standard simplex S} and B likewise with
/// t. The distance is the minimum of the convex quadratic f(s, t) = |A(s) - B(t)|^2 over the
/// polytope S x S. The relative interiors of the faces F x G (F, G each a vertex, an edge or all of
/// S: 7 x 7 pairs) partition S x S, so a minimizer x* lies in the relative interior of one of them.
/// There no inequality is active, so (KKT) x* is a stationary point, hence a minimizer, of f on
/// the affine hull of F x G. Therefore:
/// - if f restricted to aff(F x G) has a unique minimizer (full column rank of the least-squares
///   matrix below), solving that least-squares problem and keeping it when it is feasible finds
///   x* whenever x* belongs to this face pair;
/// - if the restriction is singular, its minimizers form an affine subspace of positive dimension
///   through x*, whose intersection with the bounded F x G reaches the relative boundary: the
///   same minimum value is attained on a lower-dimensional face pair, so this pair may be skipped.
///   (This always happens for interior x interior: 4 unknowns, 3 equations.)
/// Zero-area triangles need no special case: S stays a proper simplex and their degeneracy only
/// makes more face pairs singular.
///
/// Numerics: every candidate is evaluated as the distance between two actual points of the
/// triangles (feasible parameters, clamped onto the simplex), so candidates are never below the
/// true minimum beyond binary128 rounding. The least-squares problems are solved by modified
/// Gram-Schmidt with reorthogonalization on the 3 x n matrix itself (not the normal equations,
/// which would square its condition number), without square roots (they are the slowest
/// binary128 operation).

#include <algorithm>
#include <array>

#include "oracle.h"

namespace adsd::oracle {

namespace {

/// A face of the standard simplex, named by the triangle corners it spans (1, 2 or 3 of them).
struct Face {
  int cornerCount;
  std::array<int, 3> corners;
  Feature feature;
};

constexpr std::array<Face, 7> kFaces = {{
    {1, {0, 0, 0}, Feature::vertex},
    {1, {1, 0, 0}, Feature::vertex},
    {1, {2, 0, 0}, Feature::vertex},
    {2, {0, 1, 0}, Feature::edge},
    {2, {1, 2, 0}, Feature::edge},
    {2, {2, 0, 0}, Feature::edge},
    {3, {0, 1, 2}, Feature::interior},
}};

/// A face pair whose least-squares matrix has a Gram-Schmidt pivot below this fraction of its
/// largest column norm is treated as singular and skipped. Dimensionless. Why this value: the
/// solve loses about log10(condition) of binary128's 34 digits, so 1e-20 keeps >= 14 correct
/// digits in the parameters of every pair that is solved; a pair with condition beyond 1e20 is
/// within an angle of ~1e-20 rad of singular, and skipping it changes the minimum by at most
/// ~1e-20 x the triangles' extent (the lower face pair attains the singular pair's minimum).
constexpr Quad kRankTolerance = 1e-20Q;

/// Minimizers outside their face by more than this (in barycentric units, dimensionless) are
/// dropped: the global minimizer's own face pair holds it inside. Those within it are clamped
/// onto the face, which keeps them actual points of the triangles. Any value >= the parameter
/// error bound above (1e-14) is safe; larger only evaluates a few more valid candidates.
constexpr Quad kFeasibilityTolerance = 1e-12Q;

/// Clamps barycentric parameters (k = 0, 1 or 2 of them) onto {x >= 0, sum x <= 1}; returns
/// false if they lie further outside than kFeasibilityTolerance.
bool clampOntoSimplex(Quad* x, int k) {
  Quad sum = 0;
  for (int i = 0; i < k; ++i) {
    if (x[i] < -kFeasibilityTolerance) return false;
    sum += x[i];
  }
  if (sum > 1 + kFeasibilityTolerance) return false;
  sum = 0;
  for (int i = 0; i < k; ++i) {
    x[i] = std::max<Quad>(x[i], 0);
    sum += x[i];
  }
  if (sum > 1) {
    for (int i = 0; i < k; ++i) x[i] /= sum;
  }
  return true;
}

struct Candidate {
  Quad squaredDistance;
  Quad3 p, q;
};

/// One triangle's corners with the differences and plane normal every face pair reuses.
struct Corners {
  std::array<Quad3, 3> at;
  Quad3 difference[3][3];     ///< at[j] - at[i]
  Quad squaredLength[3][3];   ///< |at[j] - at[i]|^2
  Quad3 normal;               ///< (at[1] - at[0]) x (at[2] - at[0]), zero if degenerate

  Corners(const Quad3& c0, const Quad3& c1, const Quad3& c2) : at{c0, c1, c2} {
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        difference[i][j] = at[j] - at[i];
        squaredLength[i][j] = squaredNorm(difference[i][j]);
      }
    }
    normal = cross(difference[0][1], difference[0][2]);
  }
};

/// Minimizes |A(s) - B(t)|^2 over aff(F) x aff(G); returns false if singular or infeasible.
bool minimizeOnFacePair(const Corners& a, const Face& faceA, const Corners& b, const Face& faceB,
                        Candidate& out) {
  const int kA = faceA.cornerCount - 1;
  const int kB = faceB.cornerCount - 1;
  const int n = kA + kB;
  if (n > 3) return false;  // interior x interior: always singular (see the file comment)
  const int originA = faceA.corners[0];
  const int originB = faceB.corners[0];

  // Residual A(s) - B(t) = d + M x with x = (s, t) and columns of M: A's edge vectors, then
  // B's edge vectors negated.
  std::array<Quad3, 3> columns;
  std::array<Quad, 3> columnSquared{};
  for (int i = 0; i < kA; ++i) {
    columns[i] = a.difference[originA][faceA.corners[i + 1]];
    columnSquared[i] = a.squaredLength[originA][faceA.corners[i + 1]];
  }
  for (int j = 0; j < kB; ++j) {
    columns[kA + j] = b.difference[faceB.corners[j + 1]][originB];
    columnSquared[kA + j] = b.squaredLength[originB][faceB.corners[j + 1]];
  }
  const Quad3 d = a.at[originA] - b.at[originB];

  std::array<Quad, 3> x{};
  if (n > 0) {
    // Modified Gram-Schmidt without normalization (no square roots): M = V U with orthogonal
    // columns v_k and U unit upper triangular. A second pass (reorthogonalization) is made when
    // the first lost more than half of the column's squared length: "twice is enough" (Kahan,
    // Parlett), and once is enough without such cancellation.
    std::array<Quad3, 3> v;
    std::array<Quad, 3> inverseSquared{};
    Quad u[3][3] = {};
    Quad largestSquared = 0;
    for (int k = 0; k < n; ++k) largestSquared = std::max(largestSquared, columnSquared[k]);
    if (largestSquared == 0) return false;
    for (int k = 0; k < n; ++k) {
      v[k] = columns[k];
      Quad vSquared = columnSquared[k];
      for (int pass = 0; pass < 2 && k > 0; ++pass) {
        for (int j = 0; j < k; ++j) {
          const Quad coefficient = dot(v[j], v[k]) * inverseSquared[j];
          u[j][k] += coefficient;
          v[k] = v[k] - coefficient * v[j];
        }
        const Quad before = vSquared;
        vSquared = squaredNorm(v[k]);
        if (vSquared >= 0.5Q * before) break;
      }
      if (vSquared <= kRankTolerance * kRankTolerance * largestSquared) return false;
      inverseSquared[k] = 1 / vSquared;
    }
    // Least squares: with z = U x the residual d + V z is minimized by z_k = -(v_k . d) / |v_k|^2;
    // then U x = z by back substitution.
    for (int k = n - 1; k >= 0; --k) {
      Quad value = -dot(v[k], d) * inverseSquared[k];
      for (int j = k + 1; j < n; ++j) value -= u[k][j] * x[j];
      x[k] = value;
    }
    if (!clampOntoSimplex(x.data(), kA) || !clampOntoSimplex(x.data() + kA, kB)) return false;
  }

  out.p = a.at[originA];
  for (int i = 0; i < kA; ++i) out.p = out.p + x[i] * columns[i];
  out.q = b.at[originB];
  for (int j = 0; j < kB; ++j) out.q = out.q - x[kA + j] * columns[kA + j];
  out.squaredDistance = squaredNorm(out.p - out.q);
  return true;
}

/// Shortcut for an edge of one triangle against the interior of the other: unless the edge is
/// parallel to the plane (singular, skipped anyway), the minimizer on the affine hulls is where
/// the edge's line crosses the plane, at distance 0, and it is feasible only if the endpoints are
/// not strictly on the same side. When they are, the pair is skipped without solving. (Should a
/// side test round the wrong way, the endpoint is within rounding of the plane and the
/// vertex-interior pair finds the same point.)
bool edgeMissesPlane(const Corners& edgeOwner, const Face& edge, const Corners& plane) {
  const Quad sideP = dot(edgeOwner.at[edge.corners[0]] - plane.at[0], plane.normal);
  const Quad sideQ = dot(edgeOwner.at[edge.corners[1]] - plane.at[0], plane.normal);
  return (sideP > 0 && sideQ > 0) || (sideP < 0 && sideQ < 0);
}

}  // namespace

const char* toString(Feature feature) {
  switch (feature) {
    case Feature::vertex: return "vertex";
    case Feature::edge: return "edge";
    case Feature::interior: return "interior";
  }
  return "?";
}

TrianglePairDistance triangleDistance(const Quad3& a0, const Quad3& a1, const Quad3& a2, const Quad3& b0,
                                      const Quad3& b1, const Quad3& b2) {
  const Corners a(a0, a1, a2);
  const Corners b(b0, b1, b2);
  TrianglePairDistance best;
  Quad bestSquared = -1;
  // Lower-dimensional pairs first, and only a strictly smaller value replaces the best, so a tie
  // is reported at the simplest feature pair (vertex-vertex before vertex-edge, ...).
  for (int dimensionSum = 0; dimensionSum <= 4; ++dimensionSum) {
    for (const Face& faceA : kFaces) {
      for (const Face& faceB : kFaces) {
        if ((faceA.cornerCount - 1) + (faceB.cornerCount - 1) != dimensionSum) continue;
        if (faceA.feature == Feature::edge && faceB.feature == Feature::interior && edgeMissesPlane(a, faceA, b)) continue;
        if (faceB.feature == Feature::edge && faceA.feature == Feature::interior && edgeMissesPlane(b, faceB, a)) continue;
        Candidate candidate;
        if (!minimizeOnFacePair(a, faceA, b, faceB, candidate)) continue;
        if (bestSquared < 0 || candidate.squaredDistance < bestSquared) {
          bestSquared = candidate.squaredDistance;
          best.pointOnA = candidate.p;
          best.pointOnB = candidate.q;
          best.featureA = faceA.feature;
          best.featureB = faceB.feature;
        }
      }
    }
  }
  // vertex x vertex pairs are never singular, so bestSquared >= 0 here.
  best.distance = sqrtq(bestSquared);
  best.value = double(best.distance);
  return best;
}

TrianglePairDistance triangleDistance(const Vec3& a0, const Vec3& a1, const Vec3& a2, const Vec3& b0,
                                      const Vec3& b1, const Vec3& b2) {
  return triangleDistance(Quad3(a0), Quad3(a1), Quad3(a2), Quad3(b0), Quad3(b1), Quad3(b2));
}

Quad pointTriangleDistance(const Quad3& p, const Quad3& a0, const Quad3& a1, const Quad3& a2) {
  return triangleDistance(p, p, p, a0, a1, a2).distance;
}

}  // namespace adsd::oracle
