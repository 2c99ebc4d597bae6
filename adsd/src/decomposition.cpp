// Algorithm 1 (RecursiveMinDist) and stage three, the adaptive decomposition of sec. 6.

#include <algorithm>

#include "adsd/triangle_distance.h"
#include "query.h"

namespace adsd::detail {

namespace {

/// A child sub-mesh pair with its separating-axis bound along the split direction.
struct Child {
  std::uint32_t a0, a1, b0, b1;
  double lower;  // minB - maxA along the split direction (may be negative)
};

/// Extent of range [r0, r1) of `order` along the split direction, from per-triangle extents.
void extent(const std::vector<std::uint32_t>& order, std::uint32_t r0, std::uint32_t r1,
            const std::vector<double>& low, const std::vector<double>& high, double& lo, double& hi) {
  lo = std::numeric_limits<double>::infinity();
  hi = -lo;
  for (std::uint32_t i = r0; i < r1; ++i) {
    lo = std::min(lo, low[order[i]]);
    hi = std::max(hi, high[order[i]]);
  }
}

/// Halves [r0, r1) at the median of the triangles' centroids along the longest axis of their
/// box (the fallback when the support-plane cut is too thin, see kMinSplitFraction): compact
/// halves have tight hulls, which is what lets GJK separate them one level down.
std::uint32_t splitAtMedian(std::vector<std::uint32_t>& order, std::uint32_t r0, std::uint32_t r1, const Mesh& mesh) {
  Eigen::AlignedBox3d box;
  for (std::uint32_t i = r0; i < r1; ++i) {
    const std::uint32_t t = order[i];
    box.extend(mesh.corner(t, 0) + mesh.corner(t, 1) + mesh.corner(t, 2));
  }
  int axis = 0;
  box.sizes().maxCoeff(&axis);
  const std::uint32_t mid = r0 + (r1 - r0) / 2;
  std::nth_element(order.begin() + r0, order.begin() + mid, order.begin() + r1, [&](std::uint32_t s, std::uint32_t t) {
    return mesh.corner(s, 0)[axis] + mesh.corner(s, 1)[axis] + mesh.corner(s, 2)[axis] <
           mesh.corner(t, 0)[axis] + mesh.corner(t, 1)[axis] + mesh.corner(t, 2)[axis];
  });
  return mid;
}

/// Is a cut that leaves `part` of `total` triangles on one side worth keeping (kMinSplitFraction)?
bool worthKeeping(std::uint32_t part, std::uint32_t total) {
  return part >= 1 && part < total && part >= tolerance::kMinSplitFraction * total;
}

}  // namespace

void Query::testAllPairs(std::uint32_t a0, std::uint32_t a1, std::uint32_t b0, std::uint32_t b1) {
  for (std::uint32_t i = a0; i < a1 && !done_; ++i) {
    const std::uint32_t ta = buf_.orderA[i];
    const Vec3& p0 = a_.corner(ta, 0);
    const Vec3& p1 = a_.corner(ta, 1);
    const Vec3& p2 = a_.corner(ta, 2);
    for (std::uint32_t j = b0; j < b1 && !done_; ++j) {
      const std::uint32_t tb = buf_.orderB[j];
      const TrianglePairResult t = triangleDistance(p0, p1, p2, toA(b_.corner(tb, 0)), toA(b_.corner(tb, 1)),
                                                    toA(b_.corner(tb, 2)));
      ++counters_.trianglePairsTested;
      offer(t.pointOnA, t.pointOnB, t.distance, ta, false, tb, false);
    }
  }
}

void Query::visit(std::uint32_t a0, std::uint32_t a1, std::uint32_t b0, std::uint32_t b1, int depth,
                  const Vec3& hint) {
  if (done_) return;
  ++counters_.subMeshPairs;
  counters_.maxDepth = std::max(counters_.maxDepth, depth);
  const std::uint32_t nA = a1 - a0;
  const std::uint32_t nB = b1 - b0;
  // Sec. 6.1: a sub-mesh of one primitive ends the recursion with direct tests (here: any pair
  // small enough that direct tests are cheaper than GJK).
  if (static_cast<std::uint64_t>(nA) * nB <= static_cast<std::uint64_t>(tolerance::kDirectPairLimit)) {
    testAllPairs(a0, a1, b0, b1);
    return;
  }

  // Stage one (sec. 4): GJK on the hulls of the two sub-meshes.
  ++counters_.gjkCalls;
  const GjkResult g = runGjk([&](const Vec3& d) { return supportA(a0, a1, d); },
                             [&](const Vec3& d) { return supportB(b0, b1, d); }, hint,
                             [&](double lowerSafe) { return skip(lowerSafe); }, magnitude_);
  counters_.gjkIterations += g.iterations;
  counters_.gjkMaxIterations = std::max(counters_.gjkMaxIterations, g.iterations);
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
    ++counters_.pairsHashed;
    hashStage(a0, a1, b0, b1, g);
    return;
  }

  // Stage three (sec. 6.1): the hulls overlap. Split along the direction GJK ended on (the one of
  // least overlap): the plane through B's support point (n.x = minB) cuts A into the part wholly
  // before B begins and the rest; the plane through A's support point (n.x = maxA) cuts B into the
  // part wholly beyond A and the rest. The parts so cut off are separated from the other mesh by
  // construction, so three of the four child pairs have disjoint hulls.
  ++counters_.pairsSplit;
  const Vec3 n = g.direction;
  const Vec3 nInB = rotationAB_ * n;
  const double offsetB = n.dot(translationBA_);
  const std::vector<TriangleIndices>& trisA = a_.triangles();
  const std::vector<TriangleIndices>& trisB = b_.triangles();
  double maxA = -std::numeric_limits<double>::infinity();
  double minB = std::numeric_limits<double>::infinity();
  for (std::uint32_t i = a0; i < a1; ++i) {
    const std::uint32_t t = buf_.orderA[i];
    const double p0 = n.dot(a_.vertices()[trisA[t][0]]);
    const double p1 = n.dot(a_.vertices()[trisA[t][1]]);
    const double p2 = n.dot(a_.vertices()[trisA[t][2]]);
    buf_.lowA[t] = std::min({p0, p1, p2});
    buf_.highA[t] = std::max({p0, p1, p2});
    maxA = std::max(maxA, buf_.highA[t]);
  }
  for (std::uint32_t i = b0; i < b1; ++i) {
    const std::uint32_t t = buf_.orderB[i];
    const double p0 = nInB.dot(b_.vertices()[trisB[t][0]]) + offsetB;
    const double p1 = nInB.dot(b_.vertices()[trisB[t][1]]) + offsetB;
    const double p2 = nInB.dot(b_.vertices()[trisB[t][2]]) + offsetB;
    buf_.lowB[t] = std::min({p0, p1, p2});
    buf_.highB[t] = std::max({p0, p1, p2});
    minB = std::min(minB, buf_.lowB[t]);
  }

  // A: [a0, aCut) wholly below minB, [aCut, a1) the rest. One primitive is not split.
  std::uint32_t aCut = a0;
  if (nA > 1) {
    aCut = static_cast<std::uint32_t>(
        std::partition(buf_.orderA.begin() + a0, buf_.orderA.begin() + a1,
                       [&](std::uint32_t t) { return buf_.highA[t] < minB; }) -
        buf_.orderA.begin());
    if (!worthKeeping(aCut - a0, nA)) aCut = splitAtMedian(buf_.orderA, a0, a1, a_);
  }
  // B: [b0, bCut) the rest (nearer A), [bCut, b1) wholly beyond maxA.
  std::uint32_t bCut = b1;
  if (nB > 1) {
    bCut = static_cast<std::uint32_t>(
        std::partition(buf_.orderB.begin() + b0, buf_.orderB.begin() + b1,
                       [&](std::uint32_t t) { return !(buf_.lowB[t] > maxA); }) -
        buf_.orderB.begin());
    if (!worthKeeping(b1 - bCut, nB)) bCut = splitAtMedian(buf_.orderB, b0, b1, b_);
  }

  // The child pairs, each with its separating-axis bound along n, visited nearest first so that
  // the global upper bound falls early and prunes the rest (sec. 6.2).
  Child children[4];
  int count = 0;
  const std::uint32_t aRange[2][2] = {{aCut, a1}, {a0, aCut}};
  const std::uint32_t bRange[2][2] = {{b0, bCut}, {bCut, b1}};
  for (const auto& ra : aRange) {
    if (ra[0] == ra[1]) continue;
    double loA, hiA;
    extent(buf_.orderA, ra[0], ra[1], buf_.lowA, buf_.highA, loA, hiA);
    for (const auto& rb : bRange) {
      if (rb[0] == rb[1]) continue;
      double loB, hiB;
      extent(buf_.orderB, rb[0], rb[1], buf_.lowB, buf_.highB, loB, hiB);
      children[count++] = Child{ra[0], ra[1], rb[0], rb[1], loB - hiA};
    }
  }
  // Insertion sort of at most four (std::sort trips a false -Warray-bounds in GCC 12 here).
  for (int i = 1; i < count; ++i) {
    for (int j = i; j > 0 && children[j].lower < children[j - 1].lower; --j) std::swap(children[j], children[j - 1]);
  }
  for (int k = 0; k < count && !done_; ++k) {
    const Child& c = children[k];
    if (skip(c.lower - roundoff_)) {
      ++counters_.pairsRejectedByBounds;
      continue;
    }
    // Warm start: the child's GJK begins from the parent's direction (v = a - b = -n).
    visit(c.a0, c.a1, c.b0, c.b1, depth + 1, -n);
  }
}

}  // namespace adsd::detail
