#pragma once
// "Is a triangle proven farther than a bound from an oriented box?" by four separating axes: the
// box's three face normals and the triangle's normal. The tree traversal (tree_traversal.cpp)
// uses it where one node of a pair is a leaf: a leaf's few triangles bound far more tightly than
// the leaf's box (a leaf of an environment may hold a floor and a wall triangle, whose box fills
// the room corner), and a triangle proven far from a node's box is far from all of its subtree.

#include <algorithm>
#include <cmath>

#include "adsd/mesh_hierarchy.h"
#include "box_separation.h"

namespace adsd::detail {

/// \brief True when the triangle with corners \p p (same frame as \p box) is proven farther than
/// \p bound (>= 0, length units, including the caller's roundoff allowance) from the box.
inline bool triangleFartherFromBox(const Vec3 p[3], const OrientedBox& box, double bound) {
  // The corners in the box's frame (box centre at the origin, box = [-half, half]). A corner
  // inside the box settles it at once: nothing can be proven then. This is the common case where
  // a leaf faces a much larger node (on bench_scene_counters' bug trap, 4 of 5 tests prove
  // nothing), so the first corner is tried alone.
  Vec3 q[3];
  q[0] = box.axes.transpose() * (p[0] - box.center);
  if ((q[0].cwiseAbs().array() <= box.half.array()).all()) return false;
  for (int k = 1; k < 3; ++k) q[k] = box.axes.transpose() * (p[k] - box.center);
  // Box face normals: the gap vector between the triangle's box (in this frame) and the box.
  const Vec3 lo = q[0].cwiseMin(q[1]).cwiseMin(q[2]);
  const Vec3 hi = q[0].cwiseMax(q[1]).cwiseMax(q[2]);
  const Vec3 gap = (lo - box.half).cwiseMax(-box.half - hi).cwiseMax(0.0);
  const double bound2 = bound * bound;
  if (gap.squaredNorm() > bound2) return true;
  // The triangle's normal n (unnormalized): the box projects to [-|n|.half, |n|.half], the
  // triangle to the range of its corners' projections (all three taken, so a computed normal that
  // is not exactly perpendicular still gives a true interval).
  const Vec3 n = (q[1] - q[0]).cross(q[2] - q[0]);
  const double n2 = n.squaredNorm();
  if (!(n2 > 0.0)) return false;  // zero-area triangle: the face axes above are all it has
  const double reach = n.cwiseAbs().dot(box.half);
  const double s0 = n.dot(q[0]), s1 = n.dot(q[1]), s2 = n.dot(q[2]);
  const double g = std::max(std::min({s0, s1, s2}) - reach, -reach - std::max({s0, s1, s2}));
  return g > 0.0 && g * g > bound2 * n2;
}

/// \brief A lower bound of the distance between the triangle with corners \p p and the box, both
/// in the same frame, worked out only until it passes \p bound (as boxLowerBound does for two
/// boxes), with the spheres' gap for ordering: the bound of a tree node pair where one node is
/// a single triangle of a leaf (tree_traversal.cpp splits a leaf into its triangles when it faces
/// a much smaller node). Directions: the centre line of the triangle's and the box's spheres,
/// the box's three face normals (the gap vector of the two boxes in the box's frame) and the
/// triangle's normal.
inline BoxPairBound triangleBoxLowerBound(const Vec3 p[3], const OrientedBox& box, double bound) {
  const Vec3 centroid = (p[0] + p[1] + p[2]) / 3.0;
  const double radius =
      std::sqrt(std::max({(p[0] - centroid).squaredNorm(), (p[1] - centroid).squaredNorm(), (p[2] - centroid).squaredNorm()}));
  const double sphereGap = (centroid - box.center).norm() - radius - box.radius;
  if (sphereGap > bound) return {sphereGap, sphereGap};
  Vec3 q[3];
  for (int k = 0; k < 3; ++k) q[k] = box.axes.transpose() * (p[k] - box.center);
  const Vec3 lo = q[0].cwiseMin(q[1]).cwiseMin(q[2]);
  const Vec3 hi = q[0].cwiseMax(q[1]).cwiseMax(q[2]);
  const double faces = (lo - box.half).cwiseMax(-box.half - hi).cwiseMax(0.0).norm();
  if (faces > bound) return {faces, sphereGap};
  double normalGap = 0.0;
  const Vec3 n = (q[1] - q[0]).cross(q[2] - q[0]);
  const double n2 = n.squaredNorm();
  if (n2 > 0.0) {
    const double reach = n.cwiseAbs().dot(box.half);
    const double s0 = n.dot(q[0]), s1 = n.dot(q[1]), s2 = n.dot(q[2]);
    const double g = std::max(std::min({s0, s1, s2}) - reach, -reach - std::max({s0, s1, s2}));
    if (g > 0.0) normalGap = g / std::sqrt(n2);
  }
  return {std::max({sphereGap, faces, normalGap}), sphereGap};
}

}  // namespace adsd::detail
