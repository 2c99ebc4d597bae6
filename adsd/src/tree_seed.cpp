// A first upper bound for queries on two trees: one greedy dive to a nearby leaf pair.
//
// Sec. 6.2's rejection rule prunes only as well as the global upper bound is tight, and the
// query starts from the distance of two arbitrary corners. Diving once down both trees, always
// into the child pair whose circumscribed spheres are nearest, reaches a leaf pair close to the
// closest pair in 2 x depth cheap steps; its triangle distances are real distances, so they only
// ever seed the bound (the search that follows still proves the minimum).

#include "adsd/triangle_distance.h"
#include "query.h"

namespace adsd::detail {

namespace {

/// Centre distance minus the radii of the boxes' circumscribed spheres (negative when they
/// overlap): smaller means nearer.
double sphereGap(const OrientedBox& a, const Vec3& centerOfBInA, const OrientedBox& b) {
  return (centerOfBInA - a.center).norm() - a.half.norm() - b.half.norm();
}

}  // namespace

void Query::seedUpperBoundFromTrees() {
  const std::vector<MeshHierarchy::Node>& nodesA = treeA_->nodes();
  const std::vector<MeshHierarchy::Node>& nodesB = treeB_->nodes();
  std::int32_t a = 0, b = 0;
  while (!nodesA[a].isLeaf() || !nodesB[b].isLeaf()) {
    const MeshHierarchy::Node& na = nodesA[a];
    const MeshHierarchy::Node& nb = nodesB[b];
    const bool splitA = !na.isLeaf() && (nb.isLeaf() || na.box.half.squaredNorm() >= nb.box.half.squaredNorm());
    if (splitA) {
      const Vec3 centerB = toA(nb.box.center);
      a = sphereGap(nodesA[na.left].box, centerB, nb.box) <= sphereGap(nodesA[na.right].box, centerB, nb.box) ? na.left
                                                                                                               : na.right;
    } else {
      const double left = sphereGap(na.box, toA(nodesB[nb.left].box.center), nodesB[nb.left].box);
      const double right = sphereGap(na.box, toA(nodesB[nb.right].box.center), nodesB[nb.right].box);
      b = left <= right ? nb.left : nb.right;
    }
  }
  const MeshHierarchy::Node& la = nodesA[a];
  const MeshHierarchy::Node& lb = nodesB[b];
  for (std::uint32_t i = la.t0; i < la.t1; ++i) {
    const std::uint32_t ta = orderA_[i];
    for (std::uint32_t j = lb.t0; j < lb.t1; ++j) {
      const std::uint32_t tb = orderB_[j];
      const TrianglePairResult t = triangleDistance(a_.corner(ta, 0), a_.corner(ta, 1), a_.corner(ta, 2),
                                                    toA(b_.corner(tb, 0)), toA(b_.corner(tb, 1)), toA(b_.corner(tb, 2)));
      ++counters_.trianglePairsTested;
      offer(t.pointOnA, t.pointOnB, t.distance, ta, false, tb, false);
    }
  }
}

}  // namespace adsd::detail
