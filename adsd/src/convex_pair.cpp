// Two small convex meshes (MeshHierarchy::onHullBoundary: a box robot against box obstacles, the
// parts a planner's checker queries one by one), or two tree nodes that are closed convex
// components of their meshes (MeshHierarchy::Node::convexSolid: the boxes of an environment
// given as one mesh, met by the traversal): GJK on their vertices (paper sec. 4) run to
// convergence gives the hulls' distance, with a lower bound along the last direction (the
// support planes' gap, eq. 4-5) and the hulls' nearest points. Both meshes lie on their hulls'
// boundaries, so when the hulls are apart those points lie on the surfaces: the triangle pair
// carrying them measures the answer, and the lower bound proves that no pair is nearer. Where
// the proof fails (hulls that touch: contact, or one mesh inside the other; a bound the roundoff
// leaves short), the traversal answers as before, starting from the upper bound found here.

#include <cstdint>
#include <limits>

#include "adsd/triangle_distance.h"
#include "query.h"

namespace adsd::detail {

namespace {

/// Squared distance from \p p to triangle (a, b, c): the closest point by the region of the
/// triangle's plane that p's foot falls in (vertex, edge or face; Ericson, Real-Time Collision
/// Detection, sec. 5.1.5). Zero-area triangles fall into a vertex or edge region; a zero-length
/// edge is taken at its first end.
double pointTriangleDistance2(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return ap.squaredNorm();
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return bp.squaredNorm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return d1 > d3 ? (ap - (d1 / (d1 - d3)) * ab).squaredNorm() : ap.squaredNorm();
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return cp.squaredNorm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return d2 > d6 ? (ap - (d2 / (d2 - d6)) * ac).squaredNorm() : ap.squaredNorm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {
    const double along = (d4 - d3) + (d5 - d6);
    return along > 0.0 ? (bp - ((d4 - d3) / along) * (c - b)).squaredNorm() : bp.squaredNorm();
  }
  const double denominator = va + vb + vc;
  if (!(denominator > 0.0)) return ap.squaredNorm();  // degenerate: the regions above missed it
  return (ap - (vb / denominator) * ab - (vc / denominator) * ac).squaredNorm();
}

/// The triangle nearest to \p p (mesh frame) among triangles order[t0, t1) of \p mesh (all of
/// them, by index, when \p order is null), \p p being a point on their hull in its support plane
/// along \p d (the vertices' largest d.x is \p reach). Only triangles with a corner within \p slack
/// of that plane are measured: a triangle that holds p has one there (it lies in the plane, or
/// meets it at p's edge or vertex), and on a round mesh they are a handful.
std::uint32_t nearestTriangle(const Mesh& mesh, const std::uint32_t* order, std::uint32_t t0, std::uint32_t t1,
                              const Vec3& p, const Vec3& d, double reach, double slack) {
  std::uint32_t nearest = order ? order[t0] : t0;
  double nearest2 = std::numeric_limits<double>::infinity();
  const double plane = reach - slack;
  for (std::uint32_t i = t0; i < t1; ++i) {
    const std::uint32_t t = order ? order[i] : i;
    const Vec3 a = mesh.corner(t, 0), b = mesh.corner(t, 1), c = mesh.corner(t, 2);
    if (d.dot(a) < plane && d.dot(b) < plane && d.dot(c) < plane) continue;
    const double d2 = pointTriangleDistance2(p, a, b, c);
    if (d2 < nearest2) {
      nearest2 = d2;
      nearest = t;
    }
  }
  return nearest;
}

/// Support mapping (eq. 4-5) over all of a small mesh's vertices: the one maximizing d.x.
std::uint32_t supportVertex(const std::vector<Vec3>& vertices, const Vec3& d) {
  std::uint32_t best = 0;
  double bestValue = -std::numeric_limits<double>::infinity();
  for (std::uint32_t v = 0; v < vertices.size(); ++v) {
    const double value = d.dot(vertices[v]);
    if (value > bestValue) {
      bestValue = value;
      best = v;
    }
  }
  return best;
}

}  // namespace

bool Query::settleConvexPair() {
  const std::vector<Vec3>& verticesA = a_.vertices();
  const std::vector<Vec3>& verticesB = b_.vertices();
  auto supportOfA = [&](const Vec3& d) {
    const std::uint32_t v = supportVertex(verticesA, d);
    return SupportPoint{verticesA[v], v, true};
  };
  auto supportOfB = [&](const Vec3& dInA) {
    const std::uint32_t v = supportVertex(verticesB, rotationAB_ * dInA);
    return SupportPoint{toA(verticesB[v]), v, true};
  };
  // The mode's own rule may drop the pair before convergence: a lower bound beyond a cap, or
  // within a tolerance of the upper bound already known.
  auto dropped = [&](double lowerSafe) { return skip(lowerSafe); };
  // The roots' box centres: Mesh::bounds() would scan every triangle on every query (3 % of a
  // DRC-Hubo planning run, whose finger links are convex hulls of 650-1300 triangles).
  const Vec3 start = treeA_->nodes()[0].box.center - toA(treeB_->nodes()[0].box.center);
  const GjkResult g = runGjk(supportOfA, supportOfB, start, dropped, magnitude_, 0.0);
  ++counters_.gjkCalls;
  counters_.gjkIterations += static_cast<std::uint64_t>(g.iterations);
  counters_.gjkMaxIterations = std::max(counters_.gjkMaxIterations, g.iterations);
  if (g.outcome == GjkOutcome::skipped) return true;
  offer(g.closest);  // support vertices: a real distance, whatever follows
  if (g.outcome != GjkOutcome::separated) return false;  // the hulls touch: contact, or one inside
  // The hulls' nearest points lie on both surfaces (each mesh is its hull's boundary), so the
  // triangles nearest to them carry them, and their distance is the hulls' up to roundoff.
  measureAtHullPoints(g, nullptr, 0, static_cast<std::uint32_t>(a_.triangleCount()), nullptr, 0,
                      static_cast<std::uint32_t>(b_.triangleCount()));
  // Every point of either mesh lies within its hull, so no triangle pair is nearer than the
  // support planes' gap g.lower, up to the roundoff of the dot products behind it (the same
  // allowance the traversal's bounds carry). The answer is then the pair just measured.
  return best_ - g.lower <= roundoff_ || skip(g.lower - roundoff_);
}

void Query::measureAtHullPoints(const GjkResult& g, const std::uint32_t* orderA, std::uint32_t a0, std::uint32_t a1,
                                const std::uint32_t* orderB, std::uint32_t b0, std::uint32_t b1) {
  // g.direction points from A towards B: A's support plane along it, B's along its opposite (in
  // B's frame). The slack covers the roundoff of the supports and of GJK's last direction. B's
  // reach towards A in its own frame follows from GJK's minB (= min over B of n.(R b + t)).
  const double slack = 1e-9 * magnitude_ + roundoff_;
  const Vec3 towardsB = g.direction, towardsAInB = -(rotationAB_ * g.direction);
  const double reachB = g.direction.dot(translationBA_) - g.minB;
  const std::uint32_t triangleA = nearestTriangle(a_, orderA, a0, a1, g.onA, towardsB, g.maxA, slack);
  const std::uint32_t triangleB =
      nearestTriangle(b_, orderB, b0, b1, rotationAB_ * (g.onB - translationBA_), towardsAInB, reachB, slack);
  const TrianglePairResult t = triangleDistance(a_.corner(triangleA, 0), a_.corner(triangleA, 1),
                                                a_.corner(triangleA, 2), toA(b_.corner(triangleB, 0)),
                                                toA(b_.corner(triangleB, 1)), toA(b_.corner(triangleB, 2)));
  ++counters_.trianglePairsTested;
  offer(t.pointOnA, t.pointOnB, t.distance, triangleA, false, triangleB, false);
}

double Query::convexNodesBound(std::int32_t a, std::int32_t b, double bound) {
  // To convergence, unless the pair is proven farther than the bound on the way.
  const GjkResult g = gjkOnNodes(a, b, [&](double lowerSafe) { return lowerSafe > bound; }, 0.0);
  if (g.outcome == GjkOutcome::skipped) return g.lower - roundoff_;
  if (g.outcome != GjkOutcome::separated) return -std::numeric_limits<double>::infinity();  // the solids touch
  // The hulls' nearest points lie on both nodes' surfaces (each is its hull's boundary), so the
  // triangles of the nodes nearest to them carry them.
  const MeshHierarchy::Node& na = treeA_->nodes()[a];
  const MeshHierarchy::Node& nb = treeB_->nodes()[b];
  measureAtHullPoints(g, orderA_, na.t0, na.t1, orderB_, nb.t0, nb.t1);
  return g.lower - roundoff_;
}

}  // namespace adsd::detail
