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
// and the time of each mode). A validity query tests its roots with them (rootBoxesApart).

#include <algorithm>
#include <cmath>
#include <limits>

#include "adsd/mesh_hierarchy.h"

namespace adsd::detail {

/// \brief What boxLowerBound found: whether the boxes are proven farther apart than the bound
/// asked about; if not, a lower bound of their distance, and how near they are by their
/// circumscribed spheres (centre distance minus radii, negative when the spheres overlap): the key
/// that orders a traversal's children. The lower bound cannot rank overlapping pairs (it is 0 for
/// every one of them); the spheres' gap can, and ordering by it finds pairs within a validity
/// query's threshold sooner. (triangleBoxLowerBound fills lower and nearness only.)
struct BoxPairBound {
  double lower;
  double nearness;
  /// Proven farther apart than the bound; lower is then that bound and nearness unset, so that
  /// the drop decided by comparing squares waits for no square root or division.
  bool apart = false;
};

/// \brief Box \p other expressed in the frame of \p rotation and \p translation
/// (x' = rotation x + translation): the traversal places the node it does not split once per
/// split, and both children are then tested against that one placed box.
inline OrientedBox placedBox(const OrientedBox& other, const Eigen::Matrix3d& rotation, const Vec3& translation) {
  OrientedBox box;
  // Into the box itself: through a temporary (Eigen's default for a product), the copy's loads
  // straddled the product's stores, a store-forwarding stall that took a quarter of the validity
  // traversal's samples (perf annotate).
  box.axes.noalias() = rotation * other.axes;
  box.center = rotation * other.center + translation;
  box.half = other.half;
  box.radius = other.radius;
  return box;
}

/// \brief Whether one of the nine edge-edge axes L = a_i x b_j of the full separating-axis test
/// proves two boxes farther apart than sqrt(\p bound2): \p t is the centres' offset in A's box
/// frame, \p c B's axes there (c[i][j] = a_i . b_j), \p ha and \p hb the half extents.
///
/// Validity queries need it where the face axes leave it out (see the file's head): two long
/// boxes crossing at an angle, a hand's fingers, are apart only along such an axis, and without
/// it a validity query on DRC-Hubo's fingers (dart-doc) opened 190 node pairs where FCL's root
/// test decided (0.16 us against 15). Along L the gap is (|t.L| - reach) / |L|, with
/// |L|^2 = 1 - c[i][j]^2. The gap's roundoff is that of the c entries (a few eps each) times |t|
/// and the half extents (up to the scene's magnitude M), some 24 eps M in all, and the division
/// magnifies it by 1 / |L|: axes within 30 degrees of parallel (|L| < 1/2) are skipped, so that
/// the rest stay within the 64 eps M the caller's bound allows. Nearly parallel edges are the
/// face axes' case anyway.
inline bool edgeAxesApart(const double t[3], const double c[3][3], const double absC[3][3], const double ha[3],
                          const double hb[3], double bound2) {
  constexpr double kMinAxisLength2 = 1.0 / 4.0;
  for (int i = 0; i < 3; ++i) {
    const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
    for (int j = 0; j < 3; ++j) {
      const double length2 = 1.0 - c[i][j] * c[i][j];
      if (length2 < kMinAxisLength2) continue;
      const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      const double reach = ha[i1] * absC[i2][j] + ha[i2] * absC[i1][j] + hb[j1] * absC[i][j2] + hb[j2] * absC[i][j1];
      const double gap = std::abs(t[i2] * c[i1][j] - t[i1] * c[i2][j]) - reach;  // times |L|
      if (gap > 0.0 && gap * gap > bound2 * length2) return true;
    }
  }
  return false;
}

/// \brief A lower bound of the distance between boxes \p a and \p b, both given in the same
/// frame (the traversal passes one node's own box and the other node's box placed into that
/// node's mesh frame), worked out only as far as needed: it returns `apart` as soon as a
/// direction proves the boxes farther apart than \p bound (>= 0, length units, including the
/// caller's roundoff allowance: projections of coordinates of size M carry errors of a few eps M).
/// When none does, the lower bound is the largest the directions gave (possibly 0).
///
/// In A's box frame, A is [-ha, ha] and B lies within the interval of its projections on each
/// axis, so the positive parts of the three interval gaps form a vector whose length bounds the
/// distance (two axis-aligned boxes): tighter than the largest single gap when the boxes are
/// offset diagonally. The same holds in B's box frame.
///
/// Every test compares squares, so that dropping a pair takes no square root or division
/// (perf annotate: the sphere test's square root alone held a sixth of the validity traversal's
/// samples); those are paid only by the pairs no direction drops, whose bound is returned.
///
/// With \p kEdgeAxes, boxes no face axis separates are tried on the nine edge-edge axes too
/// (a_i x b_j), for being apart only (edgeAxesApart): a validity query's test of the roots
/// (rootBoxesApart). Below the roots they cost more than they drop (bench_arms --validity-alone,
/// ours / FCL on the shipped arms: 0.53 without, 0.58 with them on every node pair).
template <bool kEdgeAxes = false>
[[gnu::always_inline]] inline BoxPairBound boxLowerBound(const OrientedBox& a, const OrientedBox& b, double bound) {
  const BoxPairBound apart{bound, 0.0, true};
  // The boxes' circumscribed spheres first: a dozen operations decide the pairs far apart
  // (centres > radii + bound, all sides >= 0).
  const Vec3 offset = b.center - a.center;
  const double centres2 = offset.squaredNorm();
  const double sphereReach = a.radius + b.radius + bound;
  if (centres2 > sphereReach * sphereReach) return apart;
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
  // size. A box's projection on u reaches sum_i half_i |axis_i . u|; with u = offset / |offset|,
  // the gap |offset| - reach / |offset| exceeds the bound when centres2 - reach > bound |offset|,
  // both sides >= 0 there, so squared.
  const double reach = ha[0] * std::abs(t[0]) + ha[1] * std::abs(t[1]) + ha[2] * std::abs(t[2]) +
                       hb[0] * std::abs(tB[0]) + hb[1] * std::abs(tB[1]) + hb[2] * std::abs(tB[2]);
  const double beyondReach = centres2 - reach;
  const double bound2 = bound * bound;
  if (beyondReach > 0.0 && beyondReach * beyondReach > bound2 * centres2) return apart;
  // B's axes in A's box frame, for the face axes' reach.
  double c[3][3], absC[3][3];
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      c[i][j] = a.axes.col(i).dot(b.axes.col(j));
      absC[i][j] = std::abs(c[i][j]);
    }
  }
  // A's face axes, then B's. One gap above the bound decides at once; else the positive gaps of
  // one box's three axes together bound the distance (their vector's length).
  double gapsA2 = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double gap = std::abs(t[i]) - ha[i] - (absC[i][0] * hb[0] + absC[i][1] * hb[1] + absC[i][2] * hb[2]);
    if (gap > bound) return apart;
    if (gap > 0.0) gapsA2 += gap * gap;
  }
  if (gapsA2 > bound2) return apart;
  double gapsB2 = 0.0;
  for (int j = 0; j < 3; ++j) {
    const double gap = std::abs(tB[j]) - hb[j] - (absC[0][j] * ha[0] + absC[1][j] * ha[1] + absC[2][j] * ha[2]);
    if (gap > bound) return apart;
    if (gap > 0.0) gapsB2 += gap * gap;
  }
  if (gapsB2 > bound2) return apart;
  if constexpr (kEdgeAxes) {
    if (edgeAxesApart(t, c, absC, ha, hb, bound2)) return apart;
  }
  const double centres = std::sqrt(centres2);
  const double sphereGap = centres - a.radius - b.radius;
  const double centreGap = beyondReach > 0.0 ? beyondReach / centres : sphereGap;
  return {std::max({sphereGap, centreGap, std::sqrt(std::max(gapsA2, gapsB2))}), sphereGap};
}

/// \brief Whether two root boxes (same frame) are proven farther apart than \p bound, by the
/// face axes and the nine edge-edge axes, for a validity query. When a box's centre lies inside
/// the other box, the boxes overlap and no axis can separate them: that case, the usual one of a
/// robot inside its environment's box, is answered after three projections of the offset.
inline bool rootBoxesApart(const OrientedBox& a, const OrientedBox& b, double bound) {
  const Vec3 offset = b.center - a.center;
  const Vec3 inA = a.axes.transpose() * offset;
  if ((inA.cwiseAbs().array() <= a.half.array()).all()) return false;
  const Vec3 inB = b.axes.transpose() * offset;
  if ((inB.cwiseAbs().array() <= b.half.array()).all()) return false;
  return boxLowerBound<true>(a, b, bound).apart;
}

}  // namespace adsd::detail
