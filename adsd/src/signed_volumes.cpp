#include "signed_volumes.h"

#include <algorithm>
#include <cmath>

namespace adsd::detail {

namespace {

bool sameSign(double a, double b) { return (a > 0.0 && b > 0.0) || (a < 0.0 && b < 0.0); }

SimplexSolution fromWeights(const Vec3* p, const double* w, const int* index, int n) {
  SimplexSolution s;
  for (int i = 0; i < n; ++i) {
    s.weight[index[i]] = w[i];
    s.closest += w[i] * p[index[i]];
  }
  return s;
}

// Segment p[i0] p[i1]: parameter of the origin's projection, clamped to the segment (the S1D
// step; a zero-length segment is its first point).
SimplexSolution segment(const Vec3* p, int i0, int i1) {
  const Vec3 d = p[i1] - p[i0];
  const double len2 = d.squaredNorm();
  const int index[2] = {i0, i1};
  double u = len2 > 0.0 ? -p[i0].dot(d) / len2 : 0.0;
  u = std::clamp(u, 0.0, 1.0);
  const double w[2] = {1.0 - u, u};
  return fromWeights(p, w, index, 2);
}

// Keeps whichever candidate is closer to the origin.
void keepCloser(SimplexSolution& best, bool& have, const SimplexSolution& candidate) {
  if (!have || candidate.closest.squaredNorm() < best.closest.squaredNorm()) {
    best = candidate;
    have = true;
  }
}

// Triangle p[i0] p[i1] p[i2] (the S2D step). The signed areas of the origin's projection against
// each edge, measured along the normal n, are n . (p_j x p_k): the normal component of the origin
// drops out of them, so no projected point is formed.
SimplexSolution triangle(const Vec3* p, int i0, int i1, int i2) {
  const Vec3 n = (p[i1] - p[i0]).cross(p[i2] - p[i0]);
  const double total = n.squaredNorm();
  const int idx[3] = {i0, i1, i2};
  SimplexSolution best;
  bool have = false;
  if (total > 0.0) {
    const double c[3] = {n.dot(p[i1].cross(p[i2])), n.dot(p[i2].cross(p[i0])), n.dot(p[i0].cross(p[i1]))};
    if (sameSign(c[0], total) && sameSign(c[1], total) && sameSign(c[2], total)) {
      const double w[3] = {c[0] / total, c[1] / total, c[2] / total};
      return fromWeights(p, w, idx, 3);
    }
    // The origin projects outside the edge opposite vertex k for each k whose area has the wrong
    // sign: the closest point is on one of those edges.
    for (int k = 0; k < 3; ++k) {
      if (!sameSign(c[k], total)) keepCloser(best, have, segment(p, idx[(k + 1) % 3], idx[(k + 2) % 3]));
    }
    if (have) return best;
  }
  // Degenerate (collinear) triangle: it is the union of its edges.
  for (int k = 0; k < 3; ++k) keepCloser(best, have, segment(p, idx[k], idx[(k + 1) % 3]));
  return best;
}

// Signed volume (times 6) of tetrahedron (a, b, c, d).
double volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return (b - a).dot((c - a).cross(d - a));
}

// Tetrahedron (the S3D step): c[k] is the signed volume with vertex k replaced by the origin; they
// sum to the whole volume, and all share its sign exactly when the origin is inside.
SimplexSolution tetrahedron(const Vec3* p) {
  const Vec3 o = Vec3::Zero();
  const double total = volume(p[0], p[1], p[2], p[3]);
  const double c[4] = {volume(o, p[1], p[2], p[3]), volume(p[0], o, p[2], p[3]),
                       volume(p[0], p[1], o, p[3]), volume(p[0], p[1], p[2], o)};
  static constexpr int kFace[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
  SimplexSolution best;
  bool have = false;
  if (total != 0.0) {
    if (sameSign(c[0], total) && sameSign(c[1], total) && sameSign(c[2], total) && sameSign(c[3], total)) {
      const int idx[4] = {0, 1, 2, 3};
      const double w[4] = {c[0] / total, c[1] / total, c[2] / total, c[3] / total};
      SimplexSolution s = fromWeights(p, w, idx, 4);
      s.containsOrigin = true;
      s.closest = Vec3::Zero();
      return s;
    }
    for (int k = 0; k < 4; ++k) {
      if (!sameSign(c[k], total)) keepCloser(best, have, triangle(p, kFace[k][0], kFace[k][1], kFace[k][2]));
    }
    if (have) return best;
  }
  // Flat tetrahedron: it is the union of its faces.
  for (int k = 0; k < 4; ++k) keepCloser(best, have, triangle(p, kFace[k][0], kFace[k][1], kFace[k][2]));
  return best;
}

}  // namespace

SimplexSolution closestPointOfSimplex(const Vec3* points, int count) {
  switch (count) {
    case 1: {
      SimplexSolution s;
      s.weight[0] = 1.0;
      s.closest = points[0];
      return s;
    }
    case 2: return segment(points, 0, 1);
    case 3: return triangle(points, 0, 1, 2);
    default: return tetrahedron(points);
  }
}

}  // namespace adsd::detail
