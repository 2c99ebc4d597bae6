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
/// roundoff allowance) along a coordinate axis, either triangle's face normal or the cross
/// product of an edge of each (the separating axes of two triangles).
inline bool trianglesFartherThan(const Vec3 p[3], const Vec3 q[3], double bound) {
  // Coordinate axes (the two triangles' boxes): the gap vector's length bounds the distance.
  const Vec3 gap = (q[0].cwiseMin(q[1]).cwiseMin(q[2]) - p[0].cwiseMax(p[1]).cwiseMax(p[2]))
                       .cwiseMax(p[0].cwiseMin(p[1]).cwiseMin(p[2]) - q[0].cwiseMax(q[1]).cwiseMax(q[2]))
                       .cwiseMax(0.0);
  const double bound2 = bound * bound;
  if (gap.squaredNorm() > bound2) return true;
  // Face normals, unnormalized: along n the triangles project to intervals, and a gap g between
  // them proves distance >= g/|n|. Projections are taken relative to p[0] (differences of nearby
  // coordinates are exact) and all three corners of the normal's own triangle are projected too,
  // so a computed normal that is not exactly perpendicular still gives a true interval.
  auto apartAlong = [&](const Vec3& n) {
    const double n2 = n.squaredNorm();
    if (!(n2 > 0.0)) return false;  // zero-area triangle or parallel edges: no axis here
    double loP = 0.0, hiP = 0.0;    // p[0] projects to 0
    for (int k = 1; k < 3; ++k) {
      const double s = n.dot(p[k] - p[0]);
      loP = std::min(loP, s);
      hiP = std::max(hiP, s);
    }
    double loQ = n.dot(q[0] - p[0]), hiQ = loQ;
    for (int k = 1; k < 3; ++k) {
      const double s = n.dot(q[k] - p[0]);
      loQ = std::min(loQ, s);
      hiQ = std::max(hiQ, s);
    }
    const double g = std::max(loQ - hiP, loP - hiQ);
    return g > 0.0 && g * g > bound2 * n2;
  };
  if (apartAlong((p[1] - p[0]).cross(p[2] - p[0])) || apartAlong((q[1] - q[0]).cross(q[2] - q[0]))) return true;
  // Edge-edge axes: the closest pair of two disjoint triangles is vertex-face (a face normal
  // above) or edge-edge (the common perpendicular of the two edges, one of these nine), so for
  // those the largest gap is the distance itself and the filter leaves only the pairs that
  // could matter. (Vertex-edge and vertex-vertex minima lie along none of the axes: there the
  // gaps are strict lower bounds and the exact routine decides.)
  for (int i = 0; i < 3; ++i) {
    const Vec3 edgeP = p[(i + 1) % 3] - p[i];
    for (int j = 0; j < 3; ++j) {
      if (apartAlong(edgeP.cross(q[(j + 1) % 3] - q[j]))) return true;
    }
  }
  return false;
}

}  // namespace adsd::detail
