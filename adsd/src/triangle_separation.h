#pragma once
// A cheap, sound filter in front of the exact triangle distance: "are two triangles proven farther
// apart than a bound?" by their boxes and their separating axes. A pair it cannot decide goes to
// triangleDistance (triangle_distance.h), which stays the one exact answer; this filter only ever
// says "farther" when a separating axis proves it, so it can never change a decision.

#include <algorithm>

#include "adsd/mesh.h"

namespace adsd::detail {

/// \brief True when triangle p (three corners) and triangle q (three corners, same frame) are
/// proven farther apart than \p bound (>= 0, length units, already including the caller's
/// roundoff allowance) along a coordinate axis, the line through their centroids, either
/// triangle's face normal or the cross product of an edge of each (the separating axes of two
/// triangles).
inline bool trianglesFartherThan(const Vec3 p[3], const Vec3 q[3], double bound) {
  const double bound2 = bound * bound;
  // Coordinate axes (the two triangles' boxes): the gap vector's length bounds the distance.
  double gap2 = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double loP = std::min({p[0][k], p[1][k], p[2][k]}), hiP = std::max({p[0][k], p[1][k], p[2][k]});
    const double loQ = std::min({q[0][k], q[1][k], q[2][k]}), hiQ = std::max({q[0][k], q[1][k], q[2][k]});
    const double gap = std::max({loQ - hiP, loP - hiQ, 0.0});
    gap2 += gap * gap;
  }
  if (gap2 > bound2) return true;
  // Every corner relative to p[0] (differences of nearby coordinates are exact), computed once
  // for the 11 axes below: rp[0] is 0.
  double rp[3][3], rq[3][3];
  for (int k = 0; k < 3; ++k) {
    for (int c = 0; c < 3; ++c) {
      rp[k][c] = p[k][c] - p[0][c];
      rq[k][c] = q[k][c] - p[0][c];
    }
  }
  // Along an axis n (unnormalized) the triangles project to intervals, and a gap g between them
  // proves distance >= g/|n|. All three corners of each triangle are projected, also those of the
  // triangle whose normal or edge n was made from, so a computed axis that is not exactly
  // perpendicular to them still gives true intervals.
  auto apartAlong = [&](double n0, double n1, double n2) {
    const double norm2 = n0 * n0 + n1 * n1 + n2 * n2;
    if (!(norm2 > 0.0)) return false;  // zero-area triangle or parallel edges: no axis here
    const double p1 = n0 * rp[1][0] + n1 * rp[1][1] + n2 * rp[1][2];
    const double p2 = n0 * rp[2][0] + n1 * rp[2][1] + n2 * rp[2][2];
    const double q0 = n0 * rq[0][0] + n1 * rq[0][1] + n2 * rq[0][2];
    const double q1 = n0 * rq[1][0] + n1 * rq[1][1] + n2 * rq[1][2];
    const double q2 = n0 * rq[2][0] + n1 * rq[2][1] + n2 * rq[2][2];
    const double loP = std::min({0.0, p1, p2}), hiP = std::max({0.0, p1, p2});
    const double loQ = std::min({q0, q1, q2}), hiQ = std::max({q0, q1, q2});
    const double g = std::max(loQ - hiP, loP - hiQ);
    return g > 0.0 && g * g > bound2 * norm2;
  };
  // The line through the centroids first: for triangles apart by more than their size it is near
  // the direction of their closest points, which no face or edge axis is when those points are
  // corners (vertex-vertex and vertex-edge minima, the common case between curved surfaces).
  if (apartAlong((rq[0][0] + rq[1][0] + rq[2][0] - rp[1][0] - rp[2][0]),
                 (rq[0][1] + rq[1][1] + rq[2][1] - rp[1][1] - rp[2][1]),
                 (rq[0][2] + rq[1][2] + rq[2][2] - rp[1][2] - rp[2][2]))) {
    return true;
  }
  // Edge vectors: ep[i] = p[i+1] - p[i], eq[j] = q[j+1] - q[j].
  double ep[3][3], eq[3][3];
  for (int i = 0; i < 3; ++i) {
    const int i1 = (i + 1) % 3;
    for (int c = 0; c < 3; ++c) {
      ep[i][c] = p[i1][c] - p[i][c];
      eq[i][c] = q[i1][c] - q[i][c];
    }
  }
  auto crossAxis = [&](const double* u, const double* v) {
    return apartAlong(u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]);
  };
  // Face normals: p's as (p1 - p0) x (p2 - p0), q's as (q1 - q0) x (q2 - q0).
  const double ep02[3] = {-ep[2][0], -ep[2][1], -ep[2][2]};  // p2 - p0
  const double eq02[3] = {-eq[2][0], -eq[2][1], -eq[2][2]};  // q2 - q0
  if (crossAxis(ep[0], ep02) || crossAxis(eq[0], eq02)) return true;
  // Edge-edge axes: the closest pair of two disjoint triangles is vertex-face (a face normal
  // above) or edge-edge (the common perpendicular of the two edges, one of these nine), so for
  // those the largest gap is the distance itself and the filter leaves only the pairs that
  // could matter. (Vertex-edge and vertex-vertex minima lie along none of the axes: there the
  // gaps are strict lower bounds and the exact routine decides.)
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (crossAxis(ep[i], eq[j])) return true;
    }
  }
  return false;
}

}  // namespace adsd::detail
