#pragma once
// A lower bound of the distance between two oriented boxes, worked out only until it passes a
// given bound: the node test of the tree traversal (tree_traversal.cpp).
//
// Along any unit direction u the boxes project to intervals, and the gap between them bounds the
// distance of everything inside the boxes from below (the paper's support-plane bound, sec. 4,
// eq. 4, applied to boxes). Three kinds of direction are tried, cheapest first: the circumscribed
// spheres (the centre line with the radii as reach), the centre line with the boxes' true reach,
// then the 3 + 3 face normals (Gottschalk, Lin and Manocha, "OBBTree", 1996). The centre line is
// what decides pairs apart by more than their size, where face axes see one component of a
// diagonal offset each; the face normals decide boxes that are close and nearly aligned. The nine
// edge-edge axes of the full separating-axis test are left out: a distance query visits mostly
// pairs no axis can drop (they are split), and for those the nine axes were the dearest part of
// the test while dropping a small share of the rest (bench_scene_counters shows the node pairs
// and the time of each mode).

#include <algorithm>
#include <cmath>
#include <limits>

#include "adsd/mesh_hierarchy.h"

namespace adsd::detail {

/// \brief What boxLowerBound found: a lower bound of the boxes' distance, and how near they are by
/// their circumscribed spheres (centre distance minus radii, negative when the spheres overlap):
/// the key that orders a traversal's children. The lower bound cannot rank overlapping pairs (it
/// is 0 for every one of them); the spheres' gap can, and ordering by it finds pairs within a
/// validity query's threshold sooner.
struct BoxPairBound {
  double lower;
  double nearness;
};

/// \brief Box \p other expressed in the frame of \p rotation and \p translation
/// (x' = rotation x + translation): the traversal places the node it does not split once per
/// split, and both children are then tested against that one placed box.
inline OrientedBox placedBox(const OrientedBox& other, const Eigen::Matrix3d& rotation, const Vec3& translation) {
  OrientedBox box;
  box.axes = rotation * other.axes;
  box.center = rotation * other.center + translation;
  box.half = other.half;
  box.radius = other.radius;
  return box;
}

/// \brief A lower bound of the distance between boxes \p a and \p b, both given in the same
/// frame (the traversal passes one node's own box and the other node's box placed into that
/// node's mesh frame), worked out only as far as needed: it returns as soon as a direction proves
/// a bound above \p bound (>= 0, length units, including the caller's roundoff allowance:
/// projections of coordinates of size M carry errors of a few eps M). When none does, the lower
/// bound is the largest the directions gave (possibly 0).
///
/// In A's box frame, A is [-ha, ha] and B lies within the interval of its projections on each
/// axis, so the positive parts of the three interval gaps form a vector whose length bounds the
/// distance (two axis-aligned boxes): tighter than the largest single gap when the boxes are
/// offset diagonally. The same holds in B's box frame.
inline BoxPairBound boxLowerBound(const OrientedBox& a, const OrientedBox& b, double bound) {
  // The boxes' circumscribed spheres first: a dozen operations decide the pairs far apart.
  const Vec3 offset = b.center - a.center;
  const double centres = offset.norm();
  const double sphereGap = centres - a.radius - b.radius;
  if (sphereGap > bound) return {sphereGap, sphereGap};
  // The offset between the centres in each box's own frame (t in A's, tB in B's). Written out
  // in scalars: this is the traversal's innermost test.
  double t[3], tB[3];
  for (int i = 0; i < 3; ++i) {
    t[i] = a.axes.col(i).dot(offset);
    tB[i] = b.axes.col(i).dot(offset);
  }
  const double ha[3] = {a.half[0], a.half[1], a.half[2]};
  const double hb[3] = {b.half[0], b.half[1], b.half[2]};
  // The axis through the two centres. Any unit direction u bounds the distance of two convex sets
  // from below by the gap of their projections (sec. 4, eq. 4: the support planes' margin), and
  // the centre line is near the best direction whenever the boxes are apart by more than their
  // size. A box's projection on u reaches sum_i half_i |axis_i . u|.
  double centreGap = -std::numeric_limits<double>::infinity();
  if (centres > 0.0) {
    const double reach = ha[0] * std::abs(t[0]) + ha[1] * std::abs(t[1]) + ha[2] * std::abs(t[2]) +
                         hb[0] * std::abs(tB[0]) + hb[1] * std::abs(tB[1]) + hb[2] * std::abs(tB[2]);
    centreGap = centres - reach / centres;
    if (centreGap > bound) return {centreGap, sphereGap};
  }
  // B's axes in A's box frame, for the face axes' reach.
  double absC[3][3];
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) absC[i][j] = std::abs(a.axes.col(i).dot(b.axes.col(j)));
  }
  const double bound2 = bound * bound;
  // A's face axes, then B's. One gap above the bound decides at once; else the positive gaps of
  // one box's three axes together bound the distance (their vector's length).
  double gapsA2 = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double gap = std::abs(t[i]) - ha[i] - (absC[i][0] * hb[0] + absC[i][1] * hb[1] + absC[i][2] * hb[2]);
    if (gap > bound) return {gap, sphereGap};
    if (gap > 0.0) gapsA2 += gap * gap;
  }
  if (gapsA2 > bound2) return {std::sqrt(gapsA2), sphereGap};
  double gapsB2 = 0.0;
  for (int j = 0; j < 3; ++j) {
    const double gap = std::abs(tB[j]) - hb[j] - (absC[0][j] * ha[0] + absC[1][j] * ha[1] + absC[2][j] * ha[2]);
    if (gap > bound) return {gap, sphereGap};
    if (gap > 0.0) gapsB2 += gap * gap;
  }
  if (gapsB2 > bound2) return {std::sqrt(gapsB2), sphereGap};
  return {std::max({sphereGap, centreGap, std::sqrt(std::max(gapsA2, gapsB2))}), sphereGap};
}

}  // namespace adsd::detail
