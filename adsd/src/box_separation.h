#pragma once
// A lower bound of the distance between two oriented boxes by separating axes, worked out only
// until it passes a given bound: the node test of the tree traversal (tree_traversal.cpp).
//
// The 15 candidate axes of two boxes are the 3 + 3 face normals and the 9 cross products of an
// edge of one with an edge of the other (Gottschalk, Lin and Manocha, "OBBTree", 1996). Along a
// unit axis L the boxes' projections are intervals; the gap between them bounds the distance of
// everything inside the boxes from below (the quantitative form of the paper's support-plane bound,
// sec. 4, eq. 4, applied to boxes). Face axes are tried first: they decide most pairs and cost a
// few multiplications each once the relative rotation is known.

#include <cmath>

#include "adsd/mesh_hierarchy.h"

namespace adsd::detail {

/// Squared length below which an edge-edge axis e_i x c_j is skipped: the two edges are then
/// parallel to within ~1e-6 rad and the face axes bound nearly as well. Skipping claims nothing,
/// so it is always sound; the value only keeps the division-free comparison below well scaled.
inline constexpr double kParallelEdgeAxis2 = 1e-12;

/// \brief What boxLowerBound found: a lower bound of the boxes' distance, and how near they are by
/// their circumscribed spheres (centre distance minus radii, negative when the spheres overlap):
/// the key that orders a traversal's children. Measured on the scenes benchmark's camels at 1 %
/// of the diagonal, ordering by it found pairs within the threshold with ~1/3 less work than
/// ordering by the lower bound, which is 0 for every overlapping pair and so cannot rank them.
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
/// node's mesh frame), worked out only as far as needed: it returns as soon as an axis proves a
/// bound above \p bound (>= 0, length units, including the caller's roundoff allowance:
/// projections of coordinates of size M carry errors of a few eps M). When no axis does, the
/// lower bound is the face axes' (possibly 0).
///
/// In A's box frame, A is [-ha, ha] and B lies within the interval of its projections on each
/// axis, so the positive parts of the three interval gaps form a vector whose length bounds the
/// distance (two axis-aligned boxes): tighter than the largest single gap when the boxes are
/// offset diagonally. The same holds in B's box frame.
inline BoxPairBound boxLowerBound(const OrientedBox& a, const OrientedBox& b, double bound) {
  // The boxes' circumscribed spheres first: a dozen operations decide the pairs far apart.
  const Vec3 offset = b.center - a.center;
  const double sphereGap = offset.norm() - a.radius - b.radius;
  if (sphereGap > bound) return {sphereGap, sphereGap};
  // B's centre (t) and axes (columns of c) in A's box frame. Written out in scalars: this is the
  // traversal's innermost test, and most pairs leave it at one of the first face axes below.
  double t[3], c[3][3], absC[3][3];
  for (int i = 0; i < 3; ++i) {
    t[i] = a.axes.col(i).dot(offset);
    for (int j = 0; j < 3; ++j) {
      c[i][j] = a.axes.col(i).dot(b.axes.col(j));
      absC[i][j] = std::abs(c[i][j]);
    }
  }
  const double ha[3] = {a.half[0], a.half[1], a.half[2]};
  const double hb[3] = {b.half[0], b.half[1], b.half[2]};
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
    const double tj = c[0][j] * t[0] + c[1][j] * t[1] + c[2][j] * t[2];
    const double gap = std::abs(tj) - hb[j] - (absC[0][j] * ha[0] + absC[1][j] * ha[1] + absC[2][j] * ha[2]);
    if (gap > bound) return {gap, sphereGap};
    if (gap > 0.0) gapsB2 += gap * gap;
  }
  if (gapsB2 > bound2) return {std::sqrt(gapsB2), sphereGap};
  // Edge-edge axes L = e_i x c_j = (0 at i, -c[i2][j] at i1, c[i1][j] at i2), unnormalized:
  // gap/|L| > bound <=> gap > 0 and gap^2 > bound^2 |L|^2. B's reach is projected with the
  // computed c (not the orthonormality identities of the textbook test), so the error of c enters
  // in proportion to |L| and the bound stays relative. Along L, B's axis k projects to
  // c_k . L = c[i2][k] c[i1][j] - c[i1][k] c[i2][j], which is exactly 0 for k = j.
  for (int i = 0; i < 3; ++i) {
    const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
    for (int j = 0; j < 3; ++j) {
      const double l1 = -c[i2][j], l2 = c[i1][j];
      const double norm2 = l1 * l1 + l2 * l2;
      if (norm2 < kParallelEdgeAxis2) continue;
      const double reachA = ha[i1] * std::abs(l1) + ha[i2] * std::abs(l2);
      const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      const double reachB = hb[j1] * std::abs(c[i1][j1] * l1 + c[i2][j1] * l2) +
                            hb[j2] * std::abs(c[i1][j2] * l1 + c[i2][j2] * l2);
      const double gap = std::abs(l1 * t[i1] + l2 * t[i2]) - reachA - reachB;
      if (gap > 0.0 && gap * gap > bound2 * norm2) return {gap / std::sqrt(norm2), sphereGap};
    }
  }
  return {std::max(sphereGap, std::sqrt(std::max(gapsA2, gapsB2))), sphereGap};
}

}  // namespace adsd::detail
