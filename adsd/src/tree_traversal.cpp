// Queries between two rigid meshes with sub-mesh trees: a traversal of node pairs (best first by
// lower bound for queries that lower an upper bound, depth first for validity queries), each
// pair dropped by the cheapest sound test that proves it cannot matter.
//
// The paper's stages exist to find and cull without preprocessing (sec. 4-6). With trees built
// once, the boxes already hold most of what GJK and the hash grid would work out per query: a
// node pair is dropped when its boxes are proven farther apart than the current bound (sec.
// 6.2's rejection rule: for exact queries the global upper bound, for validity queries the
// threshold D), along the line through their centres or their face normals (box_separation.h),
// or else the larger node is split. Where boxes are weakest, on curved sub-meshes apart by more
// than their size, the paper's own bound takes over: GJK on the two nodes' hulls (sec. 4), with
// supports found by branch and bound over the subtrees, gives the support planes' margin as a
// lower bound and the closest support points as an upper bound. Leaves' triangles are tested
// against the other node's box and against each other's (filters that only ever prove
// "farther"), and only the pairs no filter separates reach the exact triangle distance. A
// validity query stops at the first triangle pair within D. Two nodes that are closed convex
// components (MeshHierarchy::Node::convexSolid), or one and a leaf outside it, are settled by GJK
// to convergence and the one triangle pair at the hulls' nearest points (convex_pair.cpp),
// unopened; a validity query drops a capsule-like solid's pair with a leaf outside it when GJK's
// support planes prove them farther apart than D.
//
// distance.cpp sends every query between two meshes with trees here (pruneBound holds each
// mode's rule); the paper's stages answer queries from scratch (decomposition.cpp).

#include <algorithm>
#include <functional>
#include <limits>

#include "adsd/triangle_distance.h"
#include "box_separation.h"
#include "query.h"
#include "triangle_box_separation.h"
#include "triangle_separation.h"

namespace adsd::detail {

namespace {

/// How large a box is, for choosing which node of a pair to split: the larger one, as halving
/// a small robot part against a room-sized node only multiplies the pairs.
inline double boxSize2(const OrientedBox& box) { return box.half.squaredNorm(); }

/// GJK iterations a node pair's hull bound may take (hullBound): its lower bound holds at any
/// iteration, and the first few do most of the tightening.
constexpr int kHullBoundIterations = 3;
/// The share of the room between a node pair's least distance found and the bound that each of
/// a hull bound's support searches may stop short of the support (Query::gjkOnNodes). The margin
/// then falls short of the exact supports' by at most twice that share of the room: a pair whose
/// hull gap passes the bound by less is split instead of dropped, while a search on a gently
/// curved sheet leaves unopened the many boxes that only tie its best vertex. Instructions per
/// exact query (callgrind, 40 poses per band), near / mid / far: the blade against the bull 1.92 /
/// 3.02 / 1.97 M with exact supports, 1.69 / 2.66 / 1.85 M with this; the turbine against the
/// blade -9 / -17 / -9 %; two cows -0 / -3 / -7 %, two camels -0 / -7 / -10 %. A share of 0.25
/// gave back half of that, more pairs being split.
constexpr double kHullBoundSupportSlack = 0.08;
/// Node pairs with fewer triangles than this on both sides are left to boxes and triangles:
/// there GJK's support descents cost more than the few pairs they could save.
constexpr std::uint32_t kHullBoundMinTriangles = 8;

/// Whether a query that lowers an upper bound should bound node pair (na, nb), whose boxes are
/// `lower` apart, by GJK on the nodes' hulls (sec. 4). Only pairs apart by more than their
/// circumscribed radii: there the hulls' margin lies close to the sub-meshes' distance (the near
/// sides of sub-meshes seen from afar are on their hulls), so one GJK run can drop a pair that
/// the boxes, fat around curved sub-meshes, would have split down to the leaves, and a tolerance
/// query can settle it within its tolerance. Closer pairs' hulls overlap or nearly, and GJK
/// there is cost without a bound. One side may be a leaf of a few triangles when the other is
/// larger: a coarse mesh's leaf is a box fat at the scale of a fine mesh far from it, which boxes
/// alone opened down to its leaves against it (the dragon 60 times smaller than the bunny, far
/// band: 44 484 node pairs per query before, 259 after; the man and the bunny, mid: 1185 us per
/// query before, 273 after).
inline bool worthHullBound(const MeshHierarchy::Node& na, const MeshHierarchy::Node& nb, double lower) {
  return lower > na.box.radius + nb.box.radius &&
         std::max(na.t1 - na.t0, nb.t1 - nb.t0) >= kHullBoundMinTriangles;
}

/// A traversal's budget of node pairs (traverseTrees), per triangle of both meshes, and at least:
/// past it, the query is finished from scratch.
constexpr std::uint64_t kTraversalPairsPerTriangle = 8;
constexpr std::uint64_t kTraversalPairsAtLeast = 1u << 12;

/// How many levels below a convex solid partsAsLargeAsWhole looks, and how large (boxSize2) the
/// largest node there must still be, relative to the solid's box.
constexpr int kPartLevels = 3;
constexpr double kPartSize2Ratio = 0.5;

/// Whether splitting convex solid \p solid (MeshHierarchy::Node::convexSolid) leaves parts about
/// as large as itself: kPartLevels below it, the largest node still has kPartSize2Ratio of its
/// boxSize2. A capsule's or a cylinder's side is long strips end to end, so its subtree bounds
/// no tighter than its own box, and the traversal keeps it whole against another mesh's nodes,
/// meeting their leaves by GJK (settleConvexNodes). A solid of compact parts (a finely meshed
/// sphere, a box of three leaves) is split by size like any node: kept whole, it met every leaf
/// of a fine mesh within its box's reach by a GJK run where its own parts' boxes would have
/// dropped them (a UV sphere of 528 triangles against the CGAL man, mid range: 4.3 times the
/// time; a box against the man: twice), while the stick against the dragon gained 1.6-3.3 times.
bool partsAsLargeAsWhole(const std::vector<MeshHierarchy::Node>& nodes, std::int32_t solid) {
  std::int32_t i = solid;
  for (int level = 0; level < kPartLevels; ++level) {
    if (nodes[i].isLeaf()) return false;
    const std::int32_t left = nodes[i].left, right = nodes[i].right;
    i = boxSize2(nodes[left].box) >= boxSize2(nodes[right].box) ? left : right;
  }
  return boxSize2(nodes[i].box) >= kPartSize2Ratio * boxSize2(nodes[solid].box);
}

/// A leaf's mask with all its triangles live (bit k for triangle t0 + k).
constexpr std::uint8_t kAllLeafTriangles = 0xFF;
static_assert(MeshHierarchy::kLeafTriangles <= 8, "a leaf's live triangles are the bits of an 8-bit mask");

/// The bits a leaf's triangles occupy in a mask.
inline std::uint32_t leafBits(const MeshHierarchy::Node& leaf) { return (1u << (leaf.t1 - leaf.t0)) - 1u; }

/// The live triangles of a leaf of \p mesh (bit k: triangle order[t0 + k]) not proven farther
/// than \p bound from \p box, which is given in the mesh's own frame.
std::uint32_t trianglesNearBox(const Mesh& mesh, const std::uint32_t* order, const MeshHierarchy::Node& leaf,
                               std::uint32_t mask, const OrientedBox& box, double bound) {
  mask &= leafBits(leaf);
  for (std::uint32_t i = leaf.t0; i < leaf.t1; ++i) {
    const std::uint32_t bit = 1u << (i - leaf.t0);
    if ((mask & bit) == 0) continue;
    const std::uint32_t t = order[i];
    const Vec3 corners[3] = {mesh.corner(t, 0), mesh.corner(t, 1), mesh.corner(t, 2)};
    if (triangleFartherFromBox(corners, box, bound)) mask &= ~bit;
  }
  return mask;
}

/// How much larger (squared, in boxSize2) a leaf must be than the node it faces for its triangles
/// to be bounded one by one (worthNarrowing): twice the size. A node that small sees the leaf's
/// triangles at distances of its own size apart; larger nodes see them all alike. (Measured with
/// callgrind on bench_bands' scenes: 4 kept most of the gain on the planning problems; 1 cost the
/// mesh pairs more.)
constexpr double kNarrowSizeRatio2 = 4.0;

/// Whether a leaf facing \p other is bounded triangle by triangle (narrowLeaf) rather than by its
/// box alone: a folded leaf (MeshHierarchy::Node::folded: triangles that face different ways, a
/// box obstacle's corner or its two sides) much larger than the node it faces. A node near one
/// face of a fold is farther from the others by about the fold's size, which the leaf's box
/// hides, so the box bound alone leaves their triangle pairs to the exact test (the planning
/// problems' walls and obstacles, callgrind: 26-59 % fewer instructions per exact query on the
/// office, the bug trap and the cow doorway). A flat or gently curved leaf (a fine scanned mesh,
/// the capsule's strips) has triangles all about as near as its box: there the bounds cost
/// without dropping any (the stick against the dragon: +25 % when every leaf was narrowed).
inline bool worthNarrowing(const MeshHierarchy::Node& leaf, const MeshHierarchy::Node& other) {
  return leaf.folded && boxSize2(leaf.box) > kNarrowSizeRatio2 * boxSize2(other.box);
}

/// Narrows a leaf's live triangles (bit k: triangle order[t0 + k] of \p mesh) to those not proven
/// farther than \p bound from \p box (given in the mesh's own frame), each by its own lower bound
/// (triangleBoxLowerBound), and raises \p lower to the smallest bound of those left.
std::uint32_t narrowLeaf(const Mesh& mesh, const std::uint32_t* order, const MeshHierarchy::Node& leaf,
                         std::uint32_t mask, const OrientedBox& box, double bound, double& lower) {
  mask &= leafBits(leaf);
  double nearest = std::numeric_limits<double>::infinity();
  for (std::uint32_t i = leaf.t0; i < leaf.t1; ++i) {
    const std::uint32_t bit = 1u << (i - leaf.t0);
    if ((mask & bit) == 0) continue;
    const std::uint32_t t = order[i];
    const Vec3 corners[3] = {mesh.corner(t, 0), mesh.corner(t, 1), mesh.corner(t, 2)};
    const double l = triangleBoxLowerBound(corners, box, bound).lower;
    if (l > bound) {
      mask &= ~bit;
    } else {
      nearest = std::min(nearest, l);
    }
  }
  if (mask != 0) lower = std::max(lower, nearest);
  return mask;
}

}  // namespace

double Query::pruneBound() const {
  // Pairs proven farther than the returned value cannot change the answer; every caller adds the
  // roundoff allowance, so "proven farther than pruneBound() + roundoff_" means the true distance
  // exceeds pruneBound().
  switch (options_.mode) {
    case QueryMode::threshold: return options_.threshold;
    // Exact, and capped below the cap: skip()'s allowance, a pair at most the roundoff allowance
    // and the tie slack nearer than the best cannot change the answer beyond the promised accuracy.
    case QueryMode::cap: return std::min(exactDropFrom(), options_.cap);
    case QueryMode::tolerance:
      // skip()'s rule solved for the pair's lower bound L: L + max(abs, rel L) >= best, or what an
      // exact query drops, whichever drops more.
      return std::max(0.0, std::min({best_ - options_.absTolerance, best_ / (1.0 + options_.relTolerance),
                                     exactDropFrom()}));
    case QueryMode::exact: break;
  }
  return exactDropFrom();
}

bool Query::rootSpheresApart(DistanceResult& out) const {
  const OrientedBox& rootA = a_.hierarchy()->nodes()[0].box;
  const OrientedBox& rootB = b_.hierarchy()->nodes()[0].box;
  // traverseTrees' first test of a validity query, in the world frame: each centre placed by its
  // own pose is a few ulps of the largest coordinate involved off, which this allowance (the one
  // placeFrames sets, for the world's coordinates: a box centre lies within sqrt(3)
  // max|coordinate| of its mesh's origin) covers many times over.
  const double magnitude =
      std::sqrt(3.0) * (a_.maxAbsCoordinate() + b_.maxAbsCoordinate() + poseA_.translation().cwiseAbs().maxCoeff() +
                        poseB_.translation().cwiseAbs().maxCoeff());
  const double allowance = tolerance::kBoundSafetyUlps * tolerance::kEpsilon * magnitude;
  // Compared squared: a checker whose robot moves inside its environment's sphere fails this test
  // on every call, and should not pay a square root for it.
  const double reach = rootA.radius + rootB.radius + options_.threshold + allowance;
  if (!((poseA_ * rootA.center - poseB_ * rootB.center).squaredNorm() > reach * reach)) return false;
  // What run() answers when the traversal drops the roots: the first corners' distance as the
  // upper bound (a real distance, larger than the spheres' gap), the threshold as the lower.
  out = DistanceResult{};
  out.witnessA = poseA_ * a_.corner(0, 0);
  out.witnessB = poseB_ * b_.corner(0, 0);
  out.distance = out.upper = (out.witnessA - out.witnessB).norm();
  out.lower = options_.threshold;
  out.triangleA = out.triangleB = 0;
  out.status = DistanceStatus::aboveThreshold;
  out.counters.subMeshPairs = 1;
  out.counters.pairsRejectedByBounds = 1;
  return true;
}

void Query::traverseTrees() {
  const std::vector<MeshHierarchy::Node>& nodesA = treeA_->nodes();
  const std::vector<MeshHierarchy::Node>& nodesB = treeB_->nodes();
  // Pairs proven farther than `bound` (the limit plus the roundoff allowance, so that the true
  // distance of a dropped pair exceeds the limit) are dropped; it falls whenever a triangle pair improves the
  // global upper bound (sec. 6.2), except in threshold mode where it is D throughout.
  double limit = pruneBound();
  double bound = limit + roundoff_;
  // Every pair dropped was proven farther than the limit at the time: the smallest of those is a
  // lower bound for the result's interval (in threshold mode D itself, as the status promises).
  auto dropped = [&] { minSkippedLower_ = std::min(minSkippedLower_, limit); };

  using Pending = PendingNodePair;
  const Vec3 translationAB = -(rotationAB_ * translationBA_);  // A's frame -> B's frame
  // A validity (threshold) query ends at the first pair within D; the other modes lower an upper
  // bound until it is proven. The traversal treats the two differently in three places, each
  // explained where it is used: how leaves meet (refineLeaves), whether representative points
  // are offered (test), and the order pairs are taken in.
  const bool lowersUpperBound = options_.mode != QueryMode::threshold;
  // Queries that lower an upper bound take one from each pair of nodes they test: the distance
  // between the nodes' representative points (MeshHierarchy::Node). Without it, best first by
  // lower bound finds the closest triangles late, after most of the triangle tests, while the
  // proof of the minimum alone, told the answer, is a fraction of the work (bench_scene_counters,
  // mode known, counts both). Equal lower bounds are ordered by the mean of that distance and the
  // boxes' nearness. A validity query keeps nearness alone and offers no such points: it ends at
  // a pair within D, which two representative points seldom are.
  // Tests the pair (a, b) by its boxes. One of the two comes placed in the other mesh's frame:
  // placedB (b's box in A's frame) or placedA (a's box in B's frame), whichever node the split
  // left whole, so that both children of a split are tested against one placed box.
  // `parentLower` is the lower bound of the pair that was split into this one (0 for the roots):
  // the child's triangles are some of the parent's, so it is no nearer, and a query that lowers an
  // upper bound keeps the larger of that and its own boxes' bound. The parent's bound is often the
  // hull bound (GJK on the nodes' hulls, sec. 4), far tighter than the children's boxes: without
  // it the children of a pair whose hull bound fell just short were ordered and bounded by their
  // boxes alone, ran GJK again, and were opened down the same way. Instructions per exact query
  // (callgrind, 40 poses per band) near / mid / far: the blade against the bull -17 / -31 / -17 %,
  // the turbine against the blade -12 / -24 / -14 %, two cows +0 / -5 / -6 %, two camels
  // -1 / -12 / -5 %, with the same answers. Returns false when the pair was dropped, else fills
  // `out`.
  auto test = [&](std::int32_t a, std::int32_t b, int depth, std::uint8_t maskA, std::uint8_t maskB,
                  const OrientedBox* placedA, const OrientedBox* placedB, double parentLower, Pending& out) {
    ++counters_.subMeshPairs;
    counters_.maxDepth = std::max(counters_.maxDepth, depth);
    BoxPairBound boxes = placedB ? boxLowerBound(nodesA[a].box, *placedB, bound)
                                 : boxLowerBound(nodesB[b].box, *placedA, bound);
    if (boxes.apart) {
      ++counters_.pairsRejectedByBounds;
      dropped();
      return false;
    }
    // A folded leaf facing a node much smaller than itself: its live triangles, each bounded
    // against that node's box (worthNarrowing), may drop out of the pair, and the nearest one's
    // bound replaces the leaf box's. Each side in its own frame, the other box placed there. Only
    // for queries that lower an upper bound, where the bound orders the pairs: a validity query
    // prunes at D alone and paid 12-32 % more instructions for it (callgrind, bench_bands' near,
    // uniform and collision bands of the planning problems).
    if (lowersUpperBound && nodesA[a].isLeaf() && worthNarrowing(nodesA[a], nodesB[b])) {
      OrientedBox local;
      const OrientedBox& boxOfB = placedB ? *placedB : (local = placedBox(nodesB[b].box, rotationBA_, translationBA_));
      maskA = static_cast<std::uint8_t>(narrowLeaf(a_, orderA_, nodesA[a], maskA, boxOfB, bound, boxes.lower));
    }
    if (lowersUpperBound && maskA != 0 && nodesB[b].isLeaf() && worthNarrowing(nodesB[b], nodesA[a])) {
      OrientedBox local;
      const OrientedBox& boxOfA = placedA ? *placedA : (local = placedBox(nodesA[a].box, rotationAB_, translationAB));
      maskB = static_cast<std::uint8_t>(narrowLeaf(b_, orderB_, nodesB[b], maskB, boxOfA, bound, boxes.lower));
    }
    if (maskA == 0 || maskB == 0) {
      ++counters_.pairsRejectedByBounds;
      dropped();
      return false;
    }
    if (!lowersUpperBound) {
      out = Pending{a, b, static_cast<std::uint16_t>(depth), maskA, maskB, boxes.lower, boxes.nearness};
      return true;
    }
    // The two nodes' representative points: a real distance, so a candidate upper bound, and
    // with the boxes' nearness the pair's estimate for the order.
    const MeshHierarchy::Node& na = nodesA[a];
    const MeshHierarchy::Node& nb = nodesB[b];
    const Vec3& onA = na.repPoint;
    const Vec3 onB = toA(nb.repPoint);
    const double between = (onA - onB).norm();
    if (between < best_) {
      offer(onA, onB, between, na.repTriangle, false, nb.repTriangle, false);
      limit = pruneBound();
      bound = limit + roundoff_;
    }
    out = Pending{a, b, static_cast<std::uint16_t>(depth), maskA, maskB, std::max(boxes.lower, parentLower),
                  0.5 * (between + boxes.nearness)};
    return true;
  };
  // When a pair is taken (not when it is first tested: a best-first query drops many pairs
  // untaken, and the bound may have fallen meanwhile), a leaf facing a larger node, or the larger
  // of two leaves, has its live triangles tested against the other node's box (the smaller
  // leaf's own box is tight already, the larger one's may be fat: a floor and a wall triangle of
  // an environment fill a room corner). Each mesh's triangles are tested in their own frame,
  // against the other box placed there. Returns false when no triangle of a leaf is left.
  auto refineLeaves = [&](Pending& pair, const MeshHierarchy::Node& na, const MeshHierarchy::Node& nb) {
    // Two leaves meeting: queries that lower an upper bound refine both leaves' triangles against
    // the other's box, since every triangle pair left costs a separating-axis filter and often an
    // exact test; a validity query, which mostly ends at the first pair or proves the boxes apart,
    // refines the larger leaf only.
    const bool bothLeaves = na.isLeaf() && nb.isLeaf() && lowersUpperBound;
    const bool refineA = na.isLeaf() && (!nb.isLeaf() || boxSize2(na.box) > boxSize2(nb.box) || bothLeaves);
    const bool refineB = nb.isLeaf() && (!refineA || bothLeaves);
    if (refineA) {
      pair.maskA = static_cast<std::uint8_t>(trianglesNearBox(a_, orderA_, na, pair.maskA, placedBox(nb.box, rotationBA_, translationBA_), bound));
      if (pair.maskA == 0) return false;
    }
    if (refineB) {
      pair.maskB = static_cast<std::uint8_t>(trianglesNearBox(b_, orderB_, nb, pair.maskB, placedBox(na.box, rotationAB_, translationAB), bound));
      if (pair.maskB == 0) return false;
    }
    return true;
  };

  // The order pairs are taken in. A validity query goes depth first, nearer child first by
  // nearness alone (BoxPairBound): it mostly ends at the first triangle pair within D, or else
  // must visit every pair its boxes cannot drop, in any order. Queries that lower an upper bound
  // go best first: always the pending pair of smallest lower bound, ties by the estimate `test`
  // gives. Depth first finds the final upper bound late and so opens far more node pairs and
  // triangle pairs before it (bench_scene_counters counts both). Ties at 0, overlapping boxes,
  // go deeper first: two sheets overlapping in one plane tie everywhere, and by the estimate
  // alone were opened across the whole sheet before a first pair of leaves showed the distance 0
  // (an outside review, sheets of 80 000 and 65 000 triangles: 53 443 node pairs, 16 ms; adsd
  // distance --path tree on them: 11.6 ms before, 0.043 ms now). Meshes that cross have the same
  // ties: exact queries of a cow, a bunny and a camel crossing a copy of itself took 0.39-0.41 of
  // the time (adsd distance --path tree, 40 poses). Near contact the node pairs changed by at most
  // 3 % (bench_bands --counters, touching, near and mid bands of three mesh pairs and three
  // problems).
  auto takenBefore = [lowersUpperBound](const Pending& x, const Pending& y) {
    if (!lowersUpperBound) return x.nearness < y.nearness;
    if (x.lower != y.lower) return x.lower < y.lower;
    if (x.lower == 0.0 && x.depth != y.depth) return x.depth > y.depth;
    return x.nearness < y.nearness;
  };
  // A heap whose front is the pair to take next (best first), or a stack (depth first).
  std::vector<Pending>& pending = buf_.pendingNodePairs;
  pending.clear();
  auto later = [&](const Pending& x, const Pending& y) { return takenBefore(y, x); };
  auto defer = [&](const Pending& pair) {
    pending.push_back(pair);
    if (lowersUpperBound) std::push_heap(pending.begin(), pending.end(), later);
  };
  auto takeNext = [&] {
    if (lowersUpperBound) std::pop_heap(pending.begin(), pending.end(), later);
    const Pending next = pending.back();
    pending.pop_back();
    return next;
  };

  // A pair far apart for its size: the hulls' margin raises its lower bound,
  // and GJK's closest support points may lower the upper bound (hullBound). True when the pair
  // is then proven farther than the bound, so that it is dropped unopened.
  auto raiseByHullBound = [&](Pending& pair) {
    pair.lower = std::max(pair.lower, hullBound(pair.a, pair.b, bound));
    limit = pruneBound();
    bound = limit + roundoff_;
    return pair.lower > bound;
  };

  // Two closed convex components (MeshHierarchy::Node::convexSolid, the boxes of an environment
  // given as one mesh), or one and a leaf (convexPairToSettle below): GJK measures the pair's
  // distance and proves it (convexNodesBound). True
  // when the pair is then settled: proven farther than the bound, or measured with nothing in it
  // nearer than the global upper bound by more than the roundoff allowance.
  // Query::run tried two whole convex meshes already (settleConvexPair): GJK on the roots again
  // would only repeat its failure.
  const bool wholeMeshesTried = treeA_->onHullBoundary() && treeB_->onHullBoundary();
  auto settleConvexNodes = [&](Pending& pair) {
    const double lowerSafe = convexNodesBound(pair.a, pair.b, bound);
    limit = pruneBound();
    bound = limit + roundoff_;
    if (lowerSafe > bound) {
      dropped();
      return true;
    }
    return best_ - lowerSafe <= 2.0 * roundoff_;
  };

  // Whether pair q's node facing a convex solid (A's node when solidIsA is false) lies outside
  // the solid's box: the boxes apart, or that node's box centre outside the solid's box, except a
  // folded leaf whose box overlaps (an obstacle's inside corner, whose hull reaches into the
  // corner where the solid is). Only then is the solid kept whole against the node, and GJK tried
  // on the node's leaves (settleConvexNodes): GJK separates a convex solid from what lies outside
  // it, while a robot inside a room whose walls are one closed convex shell (the cow doorway's)
  // would be split down to its leaves against the whole shell, every GJK run failing (bench_bands,
  // cow doorway, near: 236 node pairs per query before, 68 700 when every solid was kept whole).
  auto outsideSolid = [&](const Pending& q, bool solidIsA) {
    if (q.lower > 0.0) return true;
    const MeshHierarchy::Node& solid = solidIsA ? nodesA[q.a] : nodesB[q.b];
    const MeshHierarchy::Node& other = solidIsA ? nodesB[q.b] : nodesA[q.a];
    if (other.folded) return false;
    const Vec3 centre = solidIsA ? toA(other.box.center) : Vec3(rotationAB_ * other.box.center + translationAB);
    const Vec3 local = solid.box.axes.transpose() * (centre - solid.box.center);
    return !(local.cwiseAbs().array() <= solid.box.half.array()).all();
  };
  // Whether pair q is two convex solids, or a convex solid and a leaf outside it, for
  // settleConvexNodes. A leaf's hull is not its surface, but where the leaf's near side is on its
  // hull (a flat or gently curved patch seen from outside), GJK's nearest points lie on a triangle
  // and the pair is settled unopened: a capsule against a scanned mesh never opens the capsule.
  auto convexPairToSettle = [&](const Pending& q) {
    const MeshHierarchy::Node& na = nodesA[q.a];
    const MeshHierarchy::Node& nb = nodesB[q.b];
    if (na.convexSolid && nb.convexSolid) return !(q.a == 0 && q.b == 0 && wholeMeshesTried);
    return (na.convexSolid && nb.isLeaf() && outsideSolid(q, true)) ||
           (nb.convexSolid && na.isLeaf() && outsideSolid(q, false));
  };
  // Whether a validity query bounds pair q by GJK on its hulls (hullBound): a convex solid whose
  // parts are as large as itself (partsAsLargeAsWhole: a capsule, a cylinder) and a leaf outside
  // it, the pairs it is kept whole for below. Split by size, such a solid's strips bound no
  // tighter than its own box, and a validity query near contact opened them against every leaf
  // the box reached: the stick against the dragon, near (bench_bands --scenes stick_dragon
  // --poses 40 --rounds 3, seeds 8-10): 29-43 us per query before, 4.5-11 with this, against
  // FCL's collide at 62-81 us in the same runs; median node pairs 437 before, 97 after. Compact
  // solids (the bug trap's round robot) and pairs of solids are left to the boxes: there proving
  // a pair apart near contact took up to ten GJK iterations, and in collision, where the hulls
  // overlap, every run failed (GJK on them too: the bug trap in collision and on uniform states
  // took 1.48 and 1.05 of FCL's time, against 0.56 and 0.44 without).
  auto convexPairToBound = [&](const Pending& q) {
    const MeshHierarchy::Node& na = nodesA[q.a];
    const MeshHierarchy::Node& nb = nodesB[q.b];
    return (na.convexSolid && nb.isLeaf() && partsAsLargeAsWhole(nodesA, q.a) && outsideSolid(q, true)) ||
           (nb.convexSolid && na.isLeaf() && partsAsLargeAsWhole(nodesB, q.b) && outsideSolid(q, false));
  };

  Pending p;
  bool have = false;
  if (lowersUpperBound) {
    const OrientedBox rootOfB = placedBox(nodesB[0].box, rotationBA_, translationBA_);
    have = test(0, 0, 0, kAllLeafTriangles, kAllLeafTriangles, nullptr, &rootOfB, 0.0, p);
  } else {
    // A validity query compares the roots' circumscribed spheres, then their boxes unless a
    // centre lies in the other's box (rootBoxesApart). Most of its callers ask about pairs a
    // broad phase could not drop, a robot inside the box of the environment it moves in, where
    // the boxes overlap and the full test would decide nothing (bench_bands on the planning
    // problems: up to 25 % more time with it). But a robot's links side by side, its fingers, or
    // meshes apart by about their size, have spheres that overlap and boxes that do not, and
    // without the boxes' test such a pair went down to its leaves: DRC-Hubo's fingers (dart-doc)
    // opened 190 node pairs where FCL's root test decided (0.16 us against 15).
    ++counters_.subMeshPairs;
    const double sphereGap = (toA(nodesB[0].box.center) - nodesA[0].box.center).norm() - nodesA[0].box.radius -
                             nodesB[0].box.radius;
    if (sphereGap > bound ||
        rootBoxesApart(nodesA[0].box, placedBox(nodesB[0].box, rotationBA_, translationBA_), bound)) {
      ++counters_.pairsRejectedByBounds;
      dropped();
    } else {
      p = Pending{0, 0, 0, kAllLeafTriangles, kAllLeafTriangles, 0.0, sphereGap};
      startFromWitnessHint();
      have = !done_;
    }
  }
  // The work a traversal may do before the query is handed to the paper's stages from scratch
  // (Query::run). Trees that cannot tell triangles apart make a traversal quadratic: 20 000
  // copies of one triangle, each corner moved by up to 1e-9, against a copy 1e-3 away opened 32
  // million node pairs (9.9 s) where the stages from scratch, whose GJK bound sees through the
  // stack, answered in 2.3 ms (an outside review). Far above what real scenes need: with half
  // this budget (4 per triangle, at least 1024) no query gave up in bench_bands --scenes all
  // (bands near to collision, and touching), on seven pairs of other CGAL meshes, or in bench_arms.
  const std::uint64_t budget = counters_.subMeshPairs +
      std::max<std::uint64_t>(kTraversalPairsPerTriangle * (a_.triangleCount() + b_.triangleCount()),
                              kTraversalPairsAtLeast);
  while (have && !done_) {
    if (counters_.subMeshPairs > budget) {
      counters_.treeAbandoned = 1;
      return;
    }
    if (p.lower > bound) {  // the bound fell below this pair's since it was deferred
      ++counters_.pairsRejectedByBounds;
      dropped();
      if (lowersUpperBound) {  // every pair still pending has a lower bound at least as large
        counters_.pairsRejectedByBounds += pending.size();
        return;
      }
    } else if (lowersUpperBound && convexPairToSettle(p) && settleConvexNodes(p)) {
      ++counters_.pairsRejectedByBounds;
    } else if (!lowersUpperBound && convexPairToBound(p) && hullBound(p.a, p.b, bound) > bound) {
      ++counters_.pairsRejectedByBounds;
      dropped();
    } else if (lowersUpperBound && worthHullBound(nodesA[p.a], nodesB[p.b], p.lower) &&
               raiseByHullBound(p)) {
      ++counters_.pairsRejectedByBounds;
      dropped();
    } else if (!refineLeaves(p, nodesA[p.a], nodesB[p.b])) {
      ++counters_.pairsRejectedByBounds;
      dropped();
    } else {
      const MeshHierarchy::Node& na = nodesA[p.a];
      const MeshHierarchy::Node& nb = nodesB[p.b];
      if (na.isLeaf() && nb.isLeaf()) {
        testLeafPair(na, p.maskA, nb, p.maskB, limit, bound);
      } else {
        ++counters_.pairsSplit;
        // The larger node is split, except that a query lowering an upper bound keeps a convex
        // solid whole against a group of components, whose children are components again, so
        // that the pairs below may meet as two solids, and any query keeps one whose parts are as
        // large as itself (partsAsLargeAsWhole) whole against a node of a non-convex part that
        // lies outside it, whose leaves it may meet as a solid (settleConvexNodes, or a validity
        // query's hull bound: convexPairToBound). The stick against the dragon,
        // exact (bench_bands --counters): 1242 / 1296 / 1074 node pairs per query near / mid /
        // far before, 242 / 147 / 74 with this. Where the node is inside the solid's box the
        // size rule stands (outsideSolid).
        auto keptWhole = [&](bool solidIsA) {
          const MeshHierarchy::Node& solid = solidIsA ? na : nb;
          const MeshHierarchy::Node& other = solidIsA ? nb : na;
          if (!solid.convexSolid || other.isLeaf()) return false;
          if (lowersUpperBound && other.span == MeshHierarchy::ComponentSpan::several) return true;
          return !other.convexSolid && partsAsLargeAsWhole(solidIsA ? nodesA : nodesB, solidIsA ? p.a : p.b) &&
                 outsideSolid(p, solidIsA);
        };
        bool splitA = !na.isLeaf() && (nb.isLeaf() || boxSize2(na.box) >= boxSize2(nb.box));
        if (keptWhole(false)) splitA = true;
        if (keptWhole(true)) splitA = false;
        Pending children[2];
        int count = 0;
        if (splitA) {
          const OrientedBox boxOfB = placedBox(nb.box, rotationBA_, translationBA_);
          count += test(na.left, p.b, p.depth + 1, kAllLeafTriangles, p.maskB, nullptr, &boxOfB, p.lower,
                        children[count]);
          count += test(na.right, p.b, p.depth + 1, kAllLeafTriangles, p.maskB, nullptr, &boxOfB, p.lower,
                        children[count]);
        } else {
          const OrientedBox boxOfA = placedBox(na.box, rotationAB_, translationAB);
          count += test(p.a, nb.left, p.depth + 1, p.maskA, kAllLeafTriangles, &boxOfA, nullptr, p.lower,
                        children[count]);
          count += test(p.a, nb.right, p.depth + 1, p.maskA, kAllLeafTriangles, &boxOfA, nullptr, p.lower,
                        children[count]);
        }
        if (count == 2 && takenBefore(children[1], children[0])) std::swap(children[0], children[1]);
        if (count == 2) defer(children[1]);
        // Go on with the nearer child at once (depth first always; best first unless a pending
        // pair comes before it): the order is the same as deferring it too, with one heap
        // operation less.
        if (count > 0 && (!lowersUpperBound || pending.empty() || !takenBefore(pending.front(), children[0]))) {
          p = children[0];
          continue;
        }
        if (count > 0) defer(children[0]);
      }
    }
    have = !pending.empty();
    if (have) p = takeNext();
  }
}

SupportPoint Query::nodeSupport(const Mesh& mesh, const MeshHierarchy& tree, std::int32_t node, const Vec3& d,
                                SupportPoint warm, double slack) {
  const std::vector<MeshHierarchy::Node>& nodes = tree.nodes();
  // Start from `warm`, a point of the node's (the last support point GJK found, or the node's
  // representative point): every box that cannot beat it is skipped unopened, and GJK's
  // directions change little from one iteration to the next.
  double bestValue = d.dot(warm.point);
  SupportPoint best = warm;
  // The farthest reach of a box left unopened for the slack (below: none yet).
  double unopenedReach = -std::numeric_limits<double>::infinity();
  // Boxes waiting to be opened, each with its reach along d, worked out once when its parent is
  // opened (half of the search's cost was the same reach worked out twice). Depth first with the
  // nearer child on top leaves at most one sibling per level waiting, and a tree has at most
  // MeshHierarchy::kMaxTreeLevels levels. Two plain arrays: a vector of {node, reach} pairs was
  // written field by field and read back whole, a store-forwarding stall on every push (perf
  // annotate: a fifth of the search's samples).
  std::int32_t waitingNode[MeshHierarchy::kMaxTreeLevels + 2];
  double waitingReach[MeshHierarchy::kMaxTreeLevels + 2];
  waitingNode[0] = node;
  waitingReach[0] = nodes[node].box.support(d);
  int waiting = 1;
  while (waiting > 0) {
    --waiting;
    if (waitingReach[waiting] <= bestValue) continue;  // nothing in this box beats the best vertex
    if (waitingReach[waiting] <= bestValue + slack) {  // nothing in it beats the best by more than the slack
      unopenedReach = std::max(unopenedReach, waitingReach[waiting]);
      continue;
    }
    const MeshHierarchy::Node& n = nodes[waitingNode[waiting]];
    if (n.isLeaf()) {
      std::uint32_t bestVertex = UINT32_MAX;
      for (std::uint32_t k = n.v0; k < n.v1; ++k) {
        const std::uint32_t v = tree.leafVertices()[k];
        const double value = d.dot(mesh.vertices()[v]);
        if (value > bestValue) {
          bestValue = value;
          bestVertex = v;
        }
      }
      if (bestVertex != UINT32_MAX) {
        best.point = mesh.vertices()[bestVertex];
        for (std::uint32_t k = n.t0; k < n.t1; ++k) {
          const TriangleIndices& t = mesh.triangles()[tree.order()[k]];
          if (t[0] == bestVertex || t[1] == bestVertex || t[2] == bestVertex) best.feature = tree.order()[k];
        }
      }
      continue;
    }
    // The child whose box reaches farther along d last, so it is taken first.
    const double left = nodes[n.left].box.support(d), right = nodes[n.right].box.support(d);
    const bool leftFirst = left >= right;
    const std::int32_t first = leftFirst ? n.left : n.right, second = leftFirst ? n.right : n.left;
    const double firstReach = leftFirst ? left : right, secondReach = leftFirst ? right : left;
    if (secondReach > bestValue) {
      waitingNode[waiting] = second;
      waitingReach[waiting++] = secondReach;
    }
    if (firstReach > bestValue) {
      waitingNode[waiting] = first;
      waitingReach[waiting++] = firstReach;
    }
  }
  best.reachBeyond = std::max(0.0, unopenedReach - bestValue);
  return best;
}

GjkResult Query::gjkOnNodes(std::int32_t a, std::int32_t b, const std::function<bool(double)>& stop,
                            double relativeGap, double hopelessBelow, double slackShare) {
  // Each side's last support point (in its own mesh frame) warms the next search.
  const MeshHierarchy::Node& na = treeA_->nodes()[a];
  const MeshHierarchy::Node& nb = treeB_->nodes()[b];
  SupportPoint lastA{na.repPoint, na.repTriangle, false}, lastB{nb.repPoint, nb.repTriangle, false};
  // The least distance between two points of the nodes met so far (the representative points,
  // then each iteration's support points): the hulls are no farther apart, so no support plane
  // can prove the pair farther than that, and supports found to within a share of the room
  // between it and hopelessBelow leave the margin able to pass hopelessBelow where the exact
  // supports' margin passes it by more than twice that share.
  double nearest = (na.repPoint - toA(nb.repPoint)).norm();
  auto slack = [&] { return hopelessBelow >= 0.0 ? slackShare * std::max(0.0, nearest - hopelessBelow) : 0.0; };
  auto supportOfA = [&](const Vec3& d) {
    lastA = nodeSupport(a_, *treeA_, a, d, lastA, slack());
    return lastA;
  };
  auto supportOfB = [&](const Vec3& dInA) {
    lastB = nodeSupport(b_, *treeB_, b, rotationAB_ * dInA, lastB, slack());
    SupportPoint s = lastB;
    s.point = toA(s.point);
    nearest = std::min(nearest, (lastA.point - s.point).norm());
    return s;
  };
  const GjkResult g =
      runGjk(supportOfA, supportOfB, na.box.center - toA(nb.box.center), stop, magnitude_, relativeGap, hopelessBelow);
  ++counters_.gjkCalls;
  counters_.gjkIterations += static_cast<std::uint64_t>(g.iterations);
  counters_.gjkMaxIterations = std::max(counters_.gjkMaxIterations, g.iterations);
  if (g.closest.distance < best_) offer(g.closest);  // support vertices: a real distance
  return g;
}

bool Query::holdsBestPair(std::int32_t a, std::int32_t b) const {
  // Features are triangles on the tree path, except a whole-mesh vertex scan's (settleConvexPair),
  // and a query finished on trees after its stages from scratch ran over their budget starts
  // from what those found.
  if (bestFeatureA_ < 0 || bestFeatureB_ < 0 || bestVertexA_ || bestVertexB_) return false;
  const auto ta = static_cast<std::size_t>(bestFeatureA_), tb = static_cast<std::size_t>(bestFeatureB_);
  if (ta >= a_.triangleCount() || tb >= b_.triangleCount()) return false;
  const MeshHierarchy::Node& na = treeA_->nodes()[a];
  const MeshHierarchy::Node& nb = treeB_->nodes()[b];
  const std::uint32_t pa = treeA_->positionInOrder()[ta], pb = treeB_->positionInOrder()[tb];
  return na.t0 <= pa && pa < na.t1 && nb.t0 <= pb && pb < nb.t1;
}

double Query::hullBound(std::int32_t a, std::int32_t b, double bound) {
  // A pair that holds the nearest triangle pair found so far has hulls no farther apart than
  // best_, so when the bound is best_ itself (an exact query's, but for the tie slack) no support
  // plane can prove the pair beyond it: GJK would be spent for nothing. Such pairs are the
  // ancestors of the answer's leaf pair once a near one is found, and on a sheet many GJK runs
  // are theirs (bench_bands --counters --seed 7, 20 poses, 3 scenes and 4 CGAL pairs: 0-10 % fewer
  // GJK runs per exact query mid range, 6-15 % far, up to 12 % more node pairs; exact / FCL in
  // three alternated runs of both binaries, median scene 0.96 of before, far 0.79-1.0, the blade
  // against the bull 0.87 mid range).
  if (best_ - bound <= tieSlack_ + roundoff_ && holdsBestPair(a, b)) return -std::numeric_limits<double>::infinity();
  int iterations = 0;
  auto enough = [&](double lowerSafe) { return lowerSafe > bound || ++iterations >= kHullBoundIterations; };
  // Once GJK's simplex comes within `bound` of the origin, the hulls are that near, no support
  // plane can prove the pair farther, and the iterations left would be spent for nothing: most
  // runs end so (bench_bands, mid and far bands: 60-75 % of the hull bounds drop nothing; with
  // this test 1.2-1.7 iterations per run instead of 1.7-2.3, 11-23 % less time per exact query).
  return gjkOnNodes(a, b, enough, tolerance::kGjkRelativeGap, bound, kHullBoundSupportSlack).lower - roundoff_;
}

void Query::testLeafPair(const MeshHierarchy::Node& na, std::uint32_t maskA, const MeshHierarchy::Node& nb,
                         std::uint32_t maskB, double& limit, double& bound) {
  // B's live triangles in A's frame once per leaf pair (a leaf holds at most kLeafTriangles).
  Vec3 cornersB[MeshHierarchy::kLeafTriangles][3];
  for (std::uint32_t j = nb.t0; j < nb.t1; ++j) {
    if ((maskB >> (j - nb.t0) & 1u) == 0) continue;
    for (int k = 0; k < 3; ++k) cornersB[j - nb.t0][k] = toA(b_.corner(orderB_[j], k));
  }
  for (std::uint32_t i = na.t0; i < na.t1; ++i) {
    if ((maskA >> (i - na.t0) & 1u) == 0) continue;
    const std::uint32_t ta = orderA_[i];
    const Vec3 cornersA[3] = {a_.corner(ta, 0), a_.corner(ta, 1), a_.corner(ta, 2)};
    for (std::uint32_t j = nb.t0; j < nb.t1; ++j) {
      if ((maskB >> (j - nb.t0) & 1u) == 0) continue;
      const Vec3* q = cornersB[j - nb.t0];
      if (trianglesFartherThan(cornersA, q, bound)) {
        minSkippedLower_ = std::min(minSkippedLower_, limit);
        continue;
      }
      // Only a distance below `bound` can change the answer, so the routine may leave out what its
      // cheap bounds put beyond it; a pair found wholly beyond it counts as filtered.
      const TrianglePairResult t =
          triangleDistanceBelow(cornersA[0], cornersA[1], cornersA[2], q[0], q[1], q[2], enoughDistance(), bound);
      ++counters_.trianglePairsTested;
      leftOutAbove(t.distance, bound, limit);
      offer(t.pointOnA, t.pointOnB, t.distance, ta, false, orderB_[j], false);
      if (done_) return;
      limit = pruneBound();
      bound = limit + roundoff_;
    }
  }
}

}  // namespace adsd::detail
