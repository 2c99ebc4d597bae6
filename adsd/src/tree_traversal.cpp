// Queries between two rigid meshes with sub-mesh trees: a depth-first traversal of node pairs,
// nearest first, each pair dropped by the cheapest sound test that proves it cannot matter.
//
// The paper's stages exist to find and cull without preprocessing (sec. 4-6). With trees built
// once, the boxes already hold what GJK and the hash grid would work out per query, so neither
// runs here: a node pair is dropped when its boxes are proven farther apart than the current
// bound (sec. 6.2's rejection rule: for exact queries the global upper bound, for validity
// queries the threshold D), or else the larger node is split. Leaves' triangles are tested
// against the other node's box and against each other's (filters that only ever prove
// "farther"), and only the pairs no filter separates reach the exact triangle distance. A
// validity query stops at the first triangle pair within D.
//
// Today distance.cpp sends validity queries here. The traversal answers every mode (pruneBound
// holds each mode's rule). Exact queries sent here measured faster than on the trees'
// GJK-and-hashing path on 10 of 11 scenes of bench_scenes (ours ÷ FCL prebuilt 0.43-1.7 against
// 0.73-4.2, same day), but still descend that path: test_mesh_distance expects every tree
// scene's exact queries to reach the hashing stage.

#include <algorithm>

#include "adsd/triangle_distance.h"
#include "box_separation.h"
#include "query.h"
#include "triangle_box_separation.h"
#include "triangle_separation.h"

namespace adsd::detail {

namespace {

/// Node pairs waiting on the traversal stack at most. Each pop pushes at most two pairs and the
/// trees are median-split (depth <= 32 for 2^32 triangles), so the stack never holds more than
/// depthA + depthB + 2 entries.
constexpr int kTraversalStackSize = 160;

/// How large a box is, for choosing which node of a pair to split: the larger one, as halving
/// a small robot part against a room-sized node only multiplies the pairs.
inline double boxSize2(const OrientedBox& box) { return box.half.squaredNorm(); }

/// A leaf's mask with all its triangles live (bit k for triangle t0 + k).
constexpr std::uint32_t kAllLeafTriangles = ~0u;
static_assert(MeshHierarchy::kLeafTriangles < 32, "a leaf's live triangles are the bits of a 32-bit mask");

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

}  // namespace

double Query::pruneBound() const {
  // Pairs proven farther than the returned value cannot change the answer; every caller adds the
  // roundoff allowance, so "proven farther than pruneBound() + roundoff_" means the true distance
  // exceeds pruneBound().
  switch (options_.mode) {
    case QueryMode::threshold: return options_.threshold;
    case QueryMode::cap: return std::min(best_, options_.cap);
    case QueryMode::tolerance:
      // skip()'s rule solved for the pair's lower bound L: L + max(abs, rel L) >= best.
      return std::max(0.0, std::min(best_ - options_.absTolerance, best_ / (1.0 + options_.relTolerance)));
    case QueryMode::exact: break;
  }
  return best_;
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

  // A pair of nodes still to decide, with the lower bound found for it (the order's key, checked
  // again when popped: the bound may have fallen meanwhile). When a node is a leaf, its mask says
  // which of its triangles are not yet proven farther than the bound from the other node (bit k:
  // triangle t0 + k): a triangle far from a box is far from everything the box holds.
  struct Pending {
    std::int32_t a, b;
    int depth;
    std::uint32_t maskA, maskB;
    double lower;
    double nearness;  // BoxPairBound::nearness: which child goes first
  };
  Pending stack[kTraversalStackSize];
  int top = 0;
  const Vec3 translationAB = -(rotationAB_ * translationBA_);  // A's frame -> B's frame
  // Two leaves meeting: queries that lower an upper bound refine both leaves' triangles against
  // the other's box, since every triangle pair left costs an 11-axis filter and often an exact
  // test (bench_scene_counters, bug trap exact: ~8 % less time); a validity query, which mostly
  // ends at the first pair or proves the boxes apart, refines the larger leaf only.
  const bool refineBothLeaves = options_.mode != QueryMode::threshold;
  // Tests the pair (a, b). One of the two boxes comes placed in the other mesh's frame: placedB
  // (b's box in A's frame) or placedA (a's box in B's frame), whichever node the split left whole,
  // so that both children of a split are tested against one placed box. Returns false when the
  // pair was dropped, else fills `out`.
  auto test = [&](std::int32_t a, std::int32_t b, int depth, std::uint32_t maskA, std::uint32_t maskB,
                  const OrientedBox* placedA, const OrientedBox* placedB, Pending& out) {
    ++counters_.subMeshPairs;
    counters_.maxDepth = std::max(counters_.maxDepth, depth);
    const MeshHierarchy::Node& na = nodesA[a];
    const MeshHierarchy::Node& nb = nodesB[b];
    const BoxPairBound boxes =
        placedB ? boxLowerBound(na.box, *placedB, bound) : boxLowerBound(nb.box, *placedA, bound);
    if (boxes.lower > bound) {
      ++counters_.pairsRejectedByBounds;
      dropped();
      return false;
    }
    // A leaf facing a larger node, or the larger of two leaves: its triangles against the other
    // box (the smaller leaf's own box is tight already, the larger one's may be fat: a floor and a
    // wall triangle of an environment fill a room corner). Each mesh's triangles are tested in
    // their own frame, against the other node's box placed there.
    const bool bothLeaves = na.isLeaf() && nb.isLeaf() && refineBothLeaves;
    const bool refineA = na.isLeaf() && (!nb.isLeaf() || boxSize2(na.box) > boxSize2(nb.box) || bothLeaves);
    const bool refineB = nb.isLeaf() && (!refineA || bothLeaves);
    if (refineA) {
      const OrientedBox boxOfB = placedB ? *placedB : placedBox(nb.box, rotationBA_, translationBA_);
      maskA = trianglesNearBox(a_, orderA_, na, maskA, boxOfB, bound);
      if (maskA == 0) {
        ++counters_.pairsRejectedByBounds;
        dropped();
        return false;
      }
    }
    if (refineB) {
      const OrientedBox boxOfA = placedA ? *placedA : placedBox(na.box, rotationAB_, translationAB);
      maskB = trianglesNearBox(b_, orderB_, nb, maskB, boxOfA, bound);
      if (maskB == 0) {
        ++counters_.pairsRejectedByBounds;
        dropped();
        return false;
      }
    }
    out = Pending{a, b, depth, maskA, maskB, boxes.lower, boxes.nearness};
    return true;
  };
  // Pushes the pairs that survive, the nearer last so that it is popped first: the upper bound
  // falls fastest that way, and a validity query's proof comes sooner. "Nearer": for queries that
  // lower an upper bound, the smaller lower bound (ties, common among overlapping boxes, by
  // nearness): on bench_scene_counters' bug trap a 1 % tolerance query then took ~25 % less time;
  // for validity queries nearness alone (BoxPairBound).
  const bool byLower = options_.mode != QueryMode::threshold;
  auto pushNearestLast = [&](int count, Pending* candidates) {
    if (count == 2) {
      const bool firstNearer = byLower ? (candidates[0].lower < candidates[1].lower ||
                                          (candidates[0].lower == candidates[1].lower &&
                                           candidates[0].nearness < candidates[1].nearness))
                                       : candidates[0].nearness < candidates[1].nearness;
      if (firstNearer) std::swap(candidates[0], candidates[1]);
    }
    for (int k = 0; k < count; ++k) stack[top++] = candidates[k];
  };

  Pending root;
  const OrientedBox rootOfB = placedBox(nodesB[0].box, rotationBA_, translationBA_);
  if (test(0, 0, 0, kAllLeafTriangles, kAllLeafTriangles, nullptr, &rootOfB, root)) stack[top++] = root;
  while (top > 0 && !done_) {
    const Pending p = stack[--top];
    if (p.lower > bound) {  // the bound fell below this pair's since it was pushed
      ++counters_.pairsRejectedByBounds;
      dropped();
      continue;
    }
    const MeshHierarchy::Node& na = nodesA[p.a];
    const MeshHierarchy::Node& nb = nodesB[p.b];
    if (na.isLeaf() && nb.isLeaf()) {
      testLeafPair(na, p.maskA, nb, p.maskB, limit, bound);
      continue;
    }
    ++counters_.pairsSplit;
    const bool splitA = !na.isLeaf() && (nb.isLeaf() || boxSize2(na.box) >= boxSize2(nb.box));
    Pending children[2];
    int count = 0;
    if (splitA) {
      const OrientedBox boxOfB = placedBox(nb.box, rotationBA_, translationBA_);
      count += test(na.left, p.b, p.depth + 1, kAllLeafTriangles, p.maskB, nullptr, &boxOfB, children[count]);
      count += test(na.right, p.b, p.depth + 1, kAllLeafTriangles, p.maskB, nullptr, &boxOfB, children[count]);
    } else {
      const OrientedBox boxOfA = placedBox(na.box, rotationAB_, translationAB);
      count += test(p.a, nb.left, p.depth + 1, p.maskA, kAllLeafTriangles, &boxOfA, nullptr, children[count]);
      count += test(p.a, nb.right, p.depth + 1, p.maskA, kAllLeafTriangles, &boxOfA, nullptr, children[count]);
    }
    pushNearestLast(count, children);
  }
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
      const TrianglePairResult t =
          triangleDistanceUpTo(cornersA[0], cornersA[1], cornersA[2], q[0], q[1], q[2], enoughDistance());
      ++counters_.trianglePairsTested;
      offer(t.pointOnA, t.pointOnB, t.distance, ta, false, orderB_[j], false);
      if (done_) return;
      limit = pruneBound();
      bound = limit + roundoff_;
    }
  }
}

}  // namespace adsd::detail
