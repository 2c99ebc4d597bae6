// Algorithm 1 (RecursiveMinDist) and stage three, the adaptive decomposition of sec. 6.

#include <algorithm>
#include <cmath>

#include "adsd/triangle_distance.h"
#include "query.h"

namespace adsd::detail {

namespace {

/// A child sub-mesh pair with its separating-axis bound along the split direction.
struct Child {
  std::uint32_t a, b;  // indices into the split halves
  double lower;        // minB - maxA along the split direction (may be negative)
};

/// Halves order[t0, t1) at the median of the triangles' centroids along the longest axis of their
/// box (the fallback when the support-plane cut is too thin, see kMinSplitFraction): compact
/// halves have tight hulls, which is what lets GJK separate them one level down.
std::uint32_t splitAtMedian(std::vector<std::uint32_t>& order, std::uint32_t t0, std::uint32_t t1, const Mesh& mesh) {
  Eigen::AlignedBox3d box;
  for (std::uint32_t i = t0; i < t1; ++i) {
    const std::uint32_t t = order[i];
    box.extend(mesh.corner(t, 0) + mesh.corner(t, 1) + mesh.corner(t, 2));
  }
  int axis = 0;
  box.sizes().maxCoeff(&axis);
  const std::uint32_t mid = t0 + (t1 - t0) / 2;
  std::nth_element(order.begin() + t0, order.begin() + mid, order.begin() + t1, [&](std::uint32_t s, std::uint32_t t) {
    return mesh.corner(s, 0)[axis] + mesh.corner(s, 1)[axis] + mesh.corner(s, 2)[axis] <
           mesh.corner(t, 0)[axis] + mesh.corner(t, 1)[axis] + mesh.corner(t, 2)[axis];
  });
  return mid;
}

/// Adds a child pair to children[0, count), kept sorted by lower bound (nearest first).
void insertNearestFirst(Child* children, int& count, const Child& c) {
  int k = count++;
  for (; k > 0 && c.lower < children[k - 1].lower; --k) children[k] = children[k - 1];
  children[k] = c;
}

/// Is a cut that leaves `part` of `total` triangles on one side worth keeping (kMinSplitFraction)?
bool worthKeeping(std::uint32_t part, std::uint32_t total) {
  return part >= 1 && part < total && part >= tolerance::kMinSplitFraction * total;
}

/// Lowest and highest projection of a triangle's corners (per-vertex projections precomputed).
inline void cornerRange(const TriangleIndices& t, const std::vector<double>& projection, double& lo, double& hi) {
  const double p0 = projection[t[0]], p1 = projection[t[1]], p2 = projection[t[2]];
  lo = std::min({p0, p1, p2});
  hi = std::max({p0, p1, p2});
}

}  // namespace

void Query::testAllPairs(const SubMesh& a, const SubMesh& b) {
  for (std::uint32_t i = a.t0; i < a.t1 && !done_; ++i) {
    const std::uint32_t ta = orderA_[i];
    const Vec3& p0 = a_.corner(ta, 0);
    const Vec3& p1 = a_.corner(ta, 1);
    const Vec3& p2 = a_.corner(ta, 2);
    const Vec3 loA = p0.cwiseMin(p1).cwiseMin(p2);
    const Vec3 hiA = p0.cwiseMax(p1).cwiseMax(p2);
    for (std::uint32_t j = b.t0; j < b.t1 && !done_; ++j) {
      const std::uint32_t tb = orderB_[j];
      const Vec3 q0 = toA(b_.corner(tb, 0));
      const Vec3 q1 = toA(b_.corner(tb, 1));
      const Vec3 q2 = toA(b_.corner(tb, 2));
      // The boxes' gap first: a pair that cannot matter costs no exact test. (Not before some
      // pair has been measured: a query must end with a real distance, never an infinite one;
      // tests/stress ThresholdModeNeverAnswersAnInfiniteDistance.)
      const Vec3 gap = (q0.cwiseMin(q1).cwiseMin(q2) - hiA).cwiseMax(loA - q0.cwiseMax(q1).cwiseMax(q2)).cwiseMax(0.0);
      charge(tolerance::kWorkBoxTest);
      if (std::isfinite(best_) && skip(gap.norm() - roundoff_)) continue;
      charge(tolerance::kWorkTrianglePair);
      const double limit = pruneBound();
      const double ceiling = triangleCeiling(limit);
      const TrianglePairResult t = triangleDistanceBelow(p0, p1, p2, q0, q1, q2, enoughDistance(), ceiling);
      ++counters_.trianglePairsTested;
      leftOutAbove(t.distance, ceiling, limit);
      offer(t.pointOnA, t.pointOnB, t.distance, ta, false, tb, false);
    }
  }
}

void Query::visit(const SubMesh& a, const SubMesh& b, int depth, const Vec3& hint) {
  if (done_) return;
  ++counters_.subMeshPairs;
  counters_.maxDepth = std::max(counters_.maxDepth, depth);
  const std::uint32_t nA = a.triangles();
  const std::uint32_t nB = b.triangles();
  // Sec. 6.1: a sub-mesh of one primitive ends the recursion with direct tests (here: any pair
  // small enough that direct tests are cheaper than GJK).
  if (static_cast<std::uint64_t>(nA) * nB <= static_cast<std::uint64_t>(tolerance::kDirectPairLimit)) {
    testAllPairs(a, b);
    return;
  }

  // Stage one (sec. 4): GJK on the hulls of the two sub-meshes.
  ++counters_.gjkCalls;
  const GjkResult g = runGjk([&](const Vec3& d) { return supportA(a, d); }, [&](const Vec3& d) { return supportB(b, d); },
                             hint, [&](double lowerSafe) { return skip(lowerSafe); }, magnitude_);
  counters_.gjkIterations += g.iterations;
  counters_.gjkMaxIterations = std::max(counters_.gjkMaxIterations, g.iterations);
  charge(tolerance::kWorkSupportVertex * static_cast<std::uint64_t>(g.iterations) *
         (static_cast<std::uint64_t>(a.v1 - a.v0) + (b.v1 - b.v0)));
  // Observation 1: the support points lie on the meshes, so their distance bounds the answer.
  offer(g.closest);
  if (done_) return;
  if (g.outcome == GjkOutcome::skipped) {
    ++counters_.pairsRejectedByBounds;
    return;
  }
  if (g.outcome == GjkOutcome::separated) {
    // Sec. 6.2, third rule: a pair whose lower bound exceeds the global upper bound is skipped.
    if (skip(g.lower - roundoff_)) {
      ++counters_.pairsRejectedByBounds;
      return;
    }
    // Sec. 5: a separated pair goes to the hashing stage, unless the grid would cull too little
    // for its size (hashStage declines): then it is split as an overlapping pair would be.
    if (hashStage(a, b, g)) {
      ++counters_.pairsHashed;
      return;
    }
  }
  ++counters_.pairsSplit;
  splitAdaptively(a, b, depth, g.direction);
}

void Query::splitAdaptively(const SubMesh& a, const SubMesh& b, int depth, const Vec3& n) {
  const std::uint32_t nA = a.triangles();
  const std::uint32_t nB = b.triangles();
  // Stage three (sec. 6.1): the hulls overlap. Split along the direction GJK ended on (the one of
  // least overlap): the plane through B's support point (n.x = minB) cuts A into the part wholly
  // before B begins and the rest; the plane through A's support point (n.x = maxA) cuts B into the
  // part wholly beyond A and the rest. The parts so cut off are separated from the other mesh by
  // construction, so three of the four child pairs have disjoint hulls.
  charge(tolerance::kWorkTrianglePass * (nA + nB));
  projectA(a, n);
  projectB(b, n);
  double maxA = -std::numeric_limits<double>::infinity();
  double minB = std::numeric_limits<double>::infinity();
  for (std::uint32_t i = a.t0; i < a.t1; ++i) {
    const std::uint32_t t = buf_.orderA[i];
    cornerRange(a_.triangles()[t], buf_.projectionA, buf_.lowA[t], buf_.highA[t]);
    maxA = std::max(maxA, buf_.highA[t]);
  }
  for (std::uint32_t i = b.t0; i < b.t1; ++i) {
    const std::uint32_t t = buf_.orderB[i];
    cornerRange(b_.triangles()[t], buf_.projectionB, buf_.lowB[t], buf_.highB[t]);
    minB = std::min(minB, buf_.lowB[t]);
  }

  // A: [t0, aCut) wholly below minB (far from B), [aCut, t1) the rest. One primitive stays whole.
  std::uint32_t aCut = a.t0;
  if (nA > 1) {
    aCut = static_cast<std::uint32_t>(std::partition(buf_.orderA.begin() + a.t0, buf_.orderA.begin() + a.t1,
                                                     [&](std::uint32_t t) { return buf_.highA[t] < minB; }) -
                                      buf_.orderA.begin());
    if (!worthKeeping(aCut - a.t0, nA)) aCut = splitAtMedian(buf_.orderA, a.t0, a.t1, a_);
  }
  // B: [t0, bCut) the rest (near A), [bCut, t1) wholly beyond maxA (far from A).
  std::uint32_t bCut = b.t1;
  if (nB > 1) {
    bCut = static_cast<std::uint32_t>(std::partition(buf_.orderB.begin() + b.t0, buf_.orderB.begin() + b.t1,
                                                     [&](std::uint32_t t) { return !(buf_.lowB[t] > maxA); }) -
                                      buf_.orderB.begin());
    if (!worthKeeping(b.t1 - bCut, nB)) bCut = splitAtMedian(buf_.orderB, b.t0, b.t1, b_);
  }

  // The halves with their vertex lists (on the stacks until this visit returns) and their extent
  // along n (from the per-triangle ranges; after a median split these are still valid).
  const std::size_t stackA = buf_.verticesA.size();
  const std::size_t stackB = buf_.verticesB.size();
  SubMesh halvesA[2];
  SubMesh halvesB[2];
  double hiA[2], loB[2];
  int countA = 0, countB = 0;
  const std::uint32_t aRanges[2][2] = {{aCut, a.t1}, {a.t0, aCut}};
  const std::uint32_t bRanges[2][2] = {{b.t0, bCut}, {bCut, b.t1}};
  for (const auto& r : aRanges) {
    if (r[0] == r[1]) continue;
    if (r[0] == a.t0 && r[1] == a.t1) {
      halvesA[countA] = a;  // not split: reuse the parent's list
    } else {
      halvesA[countA] = collectVertices(a_, buf_.orderA, r[0], r[1], buf_.verticesA, buf_.vertexMarkA, ++buf_.mark);
    }
    double hi = -std::numeric_limits<double>::infinity();
    for (std::uint32_t i = r[0]; i < r[1]; ++i) hi = std::max(hi, buf_.highA[buf_.orderA[i]]);
    hiA[countA++] = hi;
  }
  for (const auto& r : bRanges) {
    if (r[0] == r[1]) continue;
    if (r[0] == b.t0 && r[1] == b.t1) {
      halvesB[countB] = b;
    } else {
      halvesB[countB] = collectVertices(b_, buf_.orderB, r[0], r[1], buf_.verticesB, buf_.vertexMarkB, ++buf_.mark);
    }
    double lo = std::numeric_limits<double>::infinity();
    for (std::uint32_t i = r[0]; i < r[1]; ++i) lo = std::min(lo, buf_.lowB[buf_.orderB[i]]);
    loB[countB++] = lo;
  }

  // The child pairs, visited nearest first (by their separating-axis bound along n) so that the
  // global upper bound falls early and prunes the rest (sec. 6.2).
  Child children[4];
  int count = 0;
  for (int i = 0; i < countA; ++i) {
    for (int j = 0; j < countB; ++j) {
      insertNearestFirst(children, count, Child{static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j), loB[j] - hiA[i]});
    }
  }
  for (int k = 0; k < count && !done_; ++k) {
    const Child& c = children[k];
    if (skip(c.lower - roundoff_)) {
      ++counters_.pairsRejectedByBounds;
      continue;
    }
    // Warm start: the child's GJK begins from the parent's direction (v = a - b = -n).
    visit(halvesA[c.a], halvesB[c.b], depth + 1, -n);
  }
  buf_.verticesA.resize(stackA);
  buf_.verticesB.resize(stackB);
}

}  // namespace adsd::detail
