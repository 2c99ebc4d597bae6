#pragma once
// Stage one (paper sec. 4): GJK on the convex hulls of two point sets given by support mappings,
// turned into the paper's lower and upper distance bounds.
//
// Frame: everything is in mesh A's frame. Sign convention: v is the point of CH(A) - CH(B)
// closest to the origin (so v = a - b points from B to A); n = -v / |v| is the unit direction from
// A towards B, and the bounds are measured along it.

#include <cmath>
#include <cstdint>
#include <limits>

#include "adsd/tolerances.h"
#include "signed_volumes.h"

namespace adsd::detail {

/// A support point: the point of a set farthest along a direction, eq. (4)-(5), with the feature
/// it came from (a triangle, or a vertex when whole-mesh scans run over the vertex array).
struct SupportPoint {
  Vec3 point = Vec3::Zero();
  std::uint32_t feature = 0;
  bool isVertex = false;
  /// How much farther than `point` the set may reach along the direction asked: 0 for an exact
  /// support; a search that stops early (Query::nodeSupport with a slack) returns a point of the
  /// set and the most that the parts it left unopened could add, so that the point's value plus
  /// `reachBeyond` still bounds the set's support from above, and the support planes' margin
  /// stays a lower bound.
  double reachBeyond = 0.0;
};

/// A pair of points, one on each mesh, and their distance: the candidates for upper bounds.
struct PointPair {
  double distance = std::numeric_limits<double>::infinity();
  SupportPoint a;
  SupportPoint b;
  void offer(const SupportPoint& pa, const SupportPoint& pb) {
    const double d = (pa.point - pb.point).norm();
    if (d < distance) {
      distance = d;
      a = pa;
      b = pb;
    }
  }
};

enum class GjkOutcome {
  separated,  ///< a positive lower bound was proven (the hulls are disjoint)
  skipped,    ///< the lower bound passed the caller's skip test before convergence
  overlapping ///< no separation proven: origin enclosed, reached, or no further progress
};

/// Why the loop stopped, for the record (the issue asks that the result say which test fired).
enum class GjkStop {
  converged, duplicateSupport, noProgress, iterationCap, originEnclosed, originReached, skipTest, hopeless
};

struct GjkResult {
  GjkOutcome outcome = GjkOutcome::overlapping;
  GjkStop stop = GjkStop::iterationCap;
  int iterations = 0;
  /// Direction of the best lower bound (unit, A towards B) and the support values along it:
  /// maxA = max over A of n.a, minB = min over B of n.b, lower = minB - maxA (may be negative:
  /// then it is the direction of least overlap, which guides the split of sec. 6.1).
  Vec3 direction = Vec3::UnitX();
  double maxA = 0.0;
  double minB = 0.0;
  double lower = -std::numeric_limits<double>::infinity();
  /// Closest pair among all support points met (every support pair of every iteration and all
  /// cross pairs of the final simplices): the paper's upper bound (sec. 4, Fig. 1).
  PointPair closest;
  /// The points of CH(A) and CH(B) that the last simplex's closest point v = onA - onB combines
  /// (its barycentric weights applied to each side's support points): where the hulls are
  /// nearest, when GJK converged. On convex meshes these lie on the surfaces (convex_pair.cpp).
  Vec3 onA = Vec3::Zero();
  Vec3 onB = Vec3::Zero();
};

/// \brief Runs GJK. supportA(d) returns A's point maximizing d.p, supportB(d) B's. `start` is the
/// first search vector (any non-zero guess of a - b). `skip(lower)` is asked after each iteration
/// whether the current lower bound already lets the caller drop this pair. `magnitude` is the
/// largest |coordinate| of either set (it scales the roundoff allowance kBoundSafetyUlps).
/// `relativeGap`: the loop stops once the lower bound is within this fraction of |v|; 0 runs it
/// to convergence (a repeated support point, or no more progress), for callers that need the
/// hulls' distance itself (convex_pair.cpp). `hopelessBelow`: the loop stops once the simplex is
/// that near the origin (|v| bounds the hulls' distance from above, so no later support plane can
/// prove them farther apart), for callers that only want to prove a pair beyond that distance.
template <class SupportA, class SupportB, class SkipTest>
GjkResult runGjk(const SupportA& supportA, const SupportB& supportB, Vec3 start, const SkipTest& skip,
                 double magnitude, double relativeGap = tolerance::kGjkRelativeGap,
                 double hopelessBelow = -std::numeric_limits<double>::infinity()) {
  const double roundoff = tolerance::kBoundSafetyUlps * tolerance::kEpsilon * magnitude;
  const double touch2 = tolerance::kGjkTouchRelative2 * magnitude * magnitude;
  GjkResult r;
  Vec3 v = start.squaredNorm() > 0.0 ? start : Vec3::UnitX();
  Vec3 w[4];
  SupportPoint sa[4], sb[4];
  double weight[4] = {1.0, 0.0, 0.0, 0.0};  // of the kept simplex's points, summing to 1
  int count = 0;

  for (r.iterations = 1; r.iterations <= tolerance::kGjkMaxIterations; ++r.iterations) {
    const double vNorm = v.norm();
    const Vec3 n = -v / vNorm;
    const SupportPoint a = supportA(n);
    const SupportPoint b = supportB(-n);
    r.closest.offer(a, b);

    // Separating-axis bound along n: every point of A has n.p <= maxA, every point of B n.q >= minB.
    const double maxA = n.dot(a.point) + a.reachBeyond;
    const double minB = n.dot(b.point) - b.reachBeyond;
    if (minB - maxA > r.lower) {
      r.lower = minB - maxA;
      r.direction = n;
      r.maxA = maxA;
      r.minB = minB;
    }
    if (skip(r.lower - roundoff)) {
      r.outcome = GjkOutcome::skipped;
      r.stop = GjkStop::skipTest;
      return r;
    }
    // Converged: |v| (the distance of the current simplices, an upper bound of the hull distance)
    // is within the relative gap of the lower bound.
    if (count > 0 && r.lower > roundoff && vNorm - r.lower <= relativeGap * vNorm) {
      r.stop = GjkStop::converged;
      break;
    }
    const Vec3 wNew = a.point - b.point;
    bool duplicate = false;
    for (int i = 0; i < count; ++i) duplicate = duplicate || (w[i] == wNew);
    if (duplicate) {
      r.stop = GjkStop::duplicateSupport;
      break;
    }
    w[count] = wNew;
    sa[count] = a;
    sb[count] = b;
    ++count;

    const SimplexSolution s = closestPointOfSimplex(w, count);
    // Keep only the points that carry the closest point (Caratheodory: at most 4, sec. 4).
    int kept = 0;
    for (int i = 0; i < count; ++i) {
      if (s.weight[i] > 0.0) {
        w[kept] = w[i];
        sa[kept] = sa[i];
        sb[kept] = sb[i];
        weight[kept] = s.weight[i];
        ++kept;
      }
    }
    if (kept == 0) weight[0] = 1.0;
    count = kept > 0 ? kept : 1;
    if (s.containsOrigin) {
      r.stop = GjkStop::originEnclosed;
      break;
    }
    if (s.closest.squaredNorm() <= touch2) {
      r.stop = GjkStop::originReached;
      break;
    }
    // GJK's distance must decrease strictly; rounding can stall it near convergence. (The first
    // search vector is a guess, not a point of the simplex, so the test starts at the second.)
    if (r.iterations > 1 && s.closest.norm() >= vNorm) {
      r.stop = GjkStop::noProgress;
      break;
    }
    v = s.closest;
    if (hopelessBelow >= 0.0 && v.squaredNorm() <= hopelessBelow * hopelessBelow) {
      r.stop = GjkStop::hopeless;
      break;
    }
  }
  if (r.iterations > tolerance::kGjkMaxIterations) r.iterations = tolerance::kGjkMaxIterations;

  // The paper's upper bound: all pairs of simplex points, A's against B's (Observation 1).
  double total = 0.0;
  for (int i = 0; i < count; ++i) {
    for (int j = 0; j < count; ++j) r.closest.offer(sa[i], sb[j]);
    r.onA += weight[i] * sa[i].point;
    r.onB += weight[i] * sb[i].point;
    total += weight[i];
  }
  if (total > 0.0) {
    r.onA /= total;
    r.onB /= total;
  }
  r.outcome = r.lower > roundoff ? GjkOutcome::separated : GjkOutcome::overlapping;
  return r;
}

}  // namespace adsd::detail
