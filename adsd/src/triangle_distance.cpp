#include "adsd/triangle_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "adsd/tolerances.h"

namespace adsd {

namespace {

using tolerance::kEpsilon;

/// Closest point to p on segment [a, b]; a zero-length segment is the point a.
Vec3 closestOnSegment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double len2 = ab.squaredNorm();
  if (len2 <= 0.0) return a;
  const double t = std::clamp((p - a).dot(ab) / len2, 0.0, 1.0);
  return a + t * ab;
}

/// a*b - c*d to about one ulp of the result (Kahan's algorithm with a fused multiply-add): the
/// rounding error of c*d is recovered exactly by the fma and added back. A plain a*b - c*d loses
/// everything when the two products nearly cancel, which is what they do in the normal of a sliver.
inline double differenceOfProducts(double a, double b, double c, double d) {
  const double cd = c * d;
  const double cdError = std::fma(-c, d, cd);
  return std::fma(a, b, -cd) + cdError;
}

/// u x v with every component accurate to about one ulp of itself, so its direction is right to
/// ~eps even when u and v are nearly parallel (a sliver's edges; issue 3). The naive product's
/// components carry errors of eps |u| |v|, which for a triangle whose smallest angle is ~1e-13
/// turns the normal by ~1 radian.
Vec3 accurateCross(const Vec3& u, const Vec3& v) {
  return Vec3(differenceOfProducts(u.y(), v.z(), u.z(), v.y()), differenceOfProducts(u.z(), v.x(), u.x(), v.z()),
              differenceOfProducts(u.x(), v.y(), u.y(), v.x()));
}

/// A triangle as the routine sees it: its first corner `origin` and the edge vectors `u`, `v` to
/// the other two, rounded once. The triangle meant from here on is exactly {origin + s u + t v}
/// (within eps of the input corners, which moves any distance by at most that), and every test
/// below uses these same numbers, so the normal, the inside tests and the projection describe one
/// triangle, not three slightly different ones.
struct Face {
  Vec3 origin;
  Vec3 u;
  Vec3 v;
  Vec3 normal;       ///< u x v, accurate (accurateCross); zero when the triangle has no interior
  double normal2;    ///< |normal|^2
  Vec3 boxLow;       ///< bounds of the corners relative to origin, grown by `slack`
  Vec3 boxHigh;

  Face(const Vec3& c0, const Vec3& c1, const Vec3& c2) : origin(c0), u(c1 - c0), v(c2 - c0) {
    normal = accurateCross(u, v);
    const double longest2 = std::max({u.squaredNorm(), v.squaredNorm(), (v - u).squaredNorm()});
    normal2 = normal.squaredNorm();
    // kDegenerateArea2: no interior to speak of; the triangle then acts as its three edges.
    if (normal2 <= tolerance::kDegenerateArea2 * longest2 * longest2) {
      normal = Vec3::Zero();
      normal2 = 0.0;
    }
    const double slack = tolerance::kContactSnapUlps * kEpsilon * std::max(u.cwiseAbs().maxCoeff(), v.cwiseAbs().maxCoeff());
    boxLow = u.cwiseMin(v).cwiseMin(Vec3::Zero()).array() - slack;
    boxHigh = u.cwiseMax(v).cwiseMax(Vec3::Zero()).array() + slack;
  }
  bool hasInterior() const { return normal2 > 0.0; }
  Vec3 corner(int i) const { return i == 0 ? origin : origin + (i == 1 ? u : v); }
};

/// Closest point to p on the face. The interior candidate, the foot of p on the plane, is taken
/// only when p lies inside all three edges (signs of triple products with the accurate normal; the
/// normal component of p drops out of them, so they are the signs of the foot without its
/// rounding) AND the foot lies in the corners' bounding box. The box is what keeps slivers honest:
/// near a sliver all three edge lines nearly coincide, so the signs can say "inside" for a point
/// far beyond a corner along them; such a foot leaves the box, and the edges answer instead.
Vec3 closestOnFace(const Vec3& p, const Face& f) {
  const Vec3 r = p - f.origin;
  if (f.hasInterior()) {
    const Vec3& n = f.normal;
    const bool inside = f.u.cross(r).dot(n) >= 0.0 && (f.v - f.u).cross(r - f.u).dot(n) >= 0.0 &&
                        r.cross(f.v).dot(n) >= 0.0;
    if (inside) {
      const Vec3 foot = r - (r.dot(n) / f.normal2) * n;
      // The foot carries the rounding of the subtraction, a few ulps of |r|, not of the face: a
      // point 0.74 above a 1 cm face in the plane y = const got a foot 3e-16 off the plane, out of
      // a box 5e-17 thick, and the edges answered 2e-6 too far (fandisk, a CAD mesh full of such
      // faces). A sliver's false "inside" leaves the box by far more than this.
      const double footSlack = tolerance::kContactSnapUlps * kEpsilon * r.cwiseAbs().maxCoeff();
      if ((foot.array() >= f.boxLow.array() - footSlack).all() &&
          (foot.array() <= f.boxHigh.array() + footSlack).all()) {
        return foot + f.origin;
      }
    }
  }
  const Vec3 c0 = f.origin, c1 = f.corner(1), c2 = f.corner(2);
  const Vec3 q01 = closestOnSegment(p, c0, c1);
  const Vec3 q12 = closestOnSegment(p, c1, c2);
  const Vec3 q20 = closestOnSegment(p, c2, c0);
  const double d01 = (p - q01).squaredNorm();
  const double d12 = (p - q12).squaredNorm();
  const double d20 = (p - q20).squaredNorm();
  if (d01 <= d12 && d01 <= d20) return q01;
  return d12 <= d20 ? q12 : q20;
}

/// Heights of three points over the face's plane, along its (unnormalized, accurate) normal: the
/// side each lies on, for the crossing test, and its distance from the plane times |normal|, for
/// the pruning test. Zero for a face without interior.
struct Heights {
  double h[3] = {0.0, 0.0, 0.0};
  Heights(const Vec3 p[3], const Face& f) {
    if (!f.hasInterior()) return;
    for (int i = 0; i < 3; ++i) h[i] = (p[i] - f.origin).dot(f.normal);
  }
};

/// Is every point of the face at least sqrt(limit2) from p (at \p height over its plane)? Proven
/// by the plane or by the corners' box: a cheap test that spares closestOnFace for the corners that
/// cannot give a nearer candidate. Rounding in the two bounds is of order eps times the triangles'
/// extent, far below the slack callers add to the limits they pass.
bool faceFartherThan(const Vec3& p, double height, const Face& f, double limit2) {
  // Squared, as offerEdgeEdge compares: a right side that overflows proves nothing, and neither
  // does one that underflows (a scene 1e-55 across puts this sixth power of lengths below the
  // smallest normal double, where 0 >= 0 proved every face farther: 73 % too far).
  const double reach2 = limit2 * f.normal2;
  if (f.hasInterior() && reach2 >= std::numeric_limits<double>::min() &&
      reach2 < std::numeric_limits<double>::infinity() && height * height >= reach2) {
    return true;
  }
  const Vec3 r = p - f.origin;
  const Vec3 outside = r - r.cwiseMax(f.boxLow).cwiseMin(f.boxHigh);
  return outside.squaredNorm() >= limit2;
}

/// Does segment [p, q] (at heights dp, dq over the face's plane) seem to meet the face, crossing
/// its plane? Decided by signs only: p and q on opposite sides of the plane (or one on it) and the
/// segment's line passing inside all three edges (equal signs of the three triple products). The
/// crossing point is returned in `hit`. Segments lying in the plane are left to the edge–edge and
/// vertex–face candidates, which realize their distance.
bool segmentPiercesFace(const Vec3& p, const Vec3& q, double dp, double dq, const Face& f, Vec3& hit) {
  if (!f.hasInterior()) return false;
  if ((dp > 0.0 && dq > 0.0) || (dp < 0.0 && dq < 0.0) || (dp == 0.0 && dq == 0.0)) return false;
  const Vec3 a = f.origin, b = f.corner(1), c = f.corner(2);
  const Vec3 pq = q - p;
  const double s0 = pq.dot((a - p).cross(b - p));
  const double s1 = pq.dot((b - p).cross(c - p));
  const double s2 = pq.dot((c - p).cross(a - p));
  const bool allNonNegative = s0 >= 0.0 && s1 >= 0.0 && s2 >= 0.0;
  const bool allNonPositive = s0 <= 0.0 && s1 <= 0.0 && s2 <= 0.0;
  if (!allNonNegative && !allNonPositive) return false;
  hit = p + (dp / (dp - dq)) * pq;
  return true;
}

struct Best {
  double distance2 = std::numeric_limits<double>::infinity();
  Vec3 onA = Vec3::Zero();
  Vec3 onB = Vec3::Zero();
  void offer(const Vec3& pa, const Vec3& pb) {
    const double d2 = (pa - pb).squaredNorm();
    if (d2 < distance2) {
      distance2 = d2;
      onA = pa;
      onB = pb;
    }
  }
};

/// The interior edge–edge candidate: the closest points of the two lines when both parameters
/// fall strictly inside the segments. The first parameter comes from the common perpendicular
/// m = d1 x d2 (|m|^2 so computed keeps relative accuracy ~eps/angle, where the normal equations'
/// determinant keeps only eps/angle^2). For nearly parallel edges it is still off by ~eps/angle
/// along the edges, so the pair is then re-projected, each point onto the other line: the offset
/// along the edges cancels and what is left is second order (issue 3's first documented failure;
/// test_triangle_distance's near-parallel family, seed 103, case 2808 was 80 % off without it).
/// Boundary minima are endpoint-to-segment pairs, covered by the vertex–face candidates.
void offerEdgeEdge(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2, double ceiling2, Best& best) {
  const Vec3 d1 = q1 - p1;
  const Vec3 d2 = q2 - p2;
  const Vec3 m = d1.cross(d2);
  const double m2 = m.squaredNorm();
  const double len1 = d1.squaredNorm();
  const double len2 = d2.squaredNorm();
  if (m2 <= tolerance::kParallelSine2 * len1 * len2 || m2 <= 0.0) return;
  const Vec3 r = p2 - p1;
  // Along m the two segments project to intervals, and their gap over |m| bounds the segments'
  // distance from below: edges already at least as far apart as the ceiling (or the best so far)
  // cannot matter. For the exact common perpendicular the intervals are the points r.m and 0 (the
  // lines' distance); the computed m is off by about eps |d1| |d2| per component, a large part of
  // it for nearly parallel edges, so the segments' own spans d1.m and d2.m are taken off (without
  // them issue 3's near-parallel family found the bound 1e-10 of the diagonal too high).
  // Compared squared, without a square root; a right side that overflows (coordinates near
  // kMaxCoordinate, or no limit yet) prunes nothing.
  const double gap = std::abs(r.dot(m)) - std::abs(d1.dot(m)) - std::abs(d2.dot(m));
  const double reach2 = std::min(ceiling2, best.distance2) * m2;
  if (gap > 0.0 && reach2 < std::numeric_limits<double>::infinity() && gap * gap >= reach2) return;
  double s = r.cross(d2).dot(m) / m2;
  if (s <= 0.0 || s >= 1.0) return;
  const double t = (p1 + s * d1 - p2).dot(d2) / len2;
  if (t <= 0.0 || t >= 1.0) return;
  s = (p2 + t * d2 - p1).dot(d1) / len1;
  if (s <= 0.0 || s >= 1.0) return;
  best.offer(p1 + s * d1, p2 + t * d2);
}

}  // namespace

// Candidates (every one a distance between two real points of the triangles, see the header):
// the minimum distance of two disjoint triangles is attained at a vertex of one and the face of
// the other, or between two edges; intersecting triangles have an edge of one crossing the other
// (or lie in one plane, where an edge–edge crossing or a contained vertex gives distance ~0).
TrianglePairResult triangleDistanceBelow(const Vec3& a0In, const Vec3& a1In, const Vec3& a2In, const Vec3& b0In,
                                         const Vec3& b1In, const Vec3& b2In, double enough, double ceiling) {
  // Work relative to a0: coordinates far from the origin (issue 3's large offsets) then lose
  // nothing in the differences that follow, as nearby doubles subtract exactly.
  const Vec3& origin = a0In;
  const Vec3 a[3] = {Vec3::Zero(), a1In - origin, a2In - origin};
  const Vec3 b[3] = {b0In - origin, b1In - origin, b2In - origin};
  const Face faceA(a[0], a[1], a[2]);
  const Face faceB(b[0], b[1], b[2]);
  double scale = 0.0;
  for (int i = 0; i < 3; ++i) scale = std::max({scale, a[i].cwiseAbs().maxCoeff(), b[i].cwiseAbs().maxCoeff()});
  // Distances up to this are contact: reported as 0 below.
  const double snap = tolerance::kContactSnapUlps * kEpsilon * scale;
  // A candidate within `enough` may end the search; so may one within `snap`, since a minimum
  // below it would be reported as 0 all the same.
  const double stop = enough < 0.0 ? -1.0 : std::max(enough, snap);
  const double stop2 = stop < 0.0 ? -1.0 : stop * stop;

  // Candidates proven no nearer than this are not worked out (squared; infinite: none pruned).
  const double ceiling2 = ceiling < std::numeric_limits<double>::infinity() ? ceiling * ceiling : ceiling;

  Best best;
  auto finish = [&] {
    TrianglePairResult result;
    result.distance = std::sqrt(best.distance2);
    result.pointOnA = best.onA + origin;
    result.pointOnB = best.onB + origin;
    if (result.distance <= snap) {
      result.distance = 0.0;
      result.pointOnB = result.pointOnA;
    }
    return result;
  };
  // An edge crossing the other triangle: the crossing point and its closest point on that
  // triangle form a candidate (of length ~0 when the crossing is real). Offered, not trusted:
  // for an edge lying in the other's plane the signs of the test are noise, and a false crossing
  // then only offers a real, longer distance.
  const Heights overB(a, faceB), overA(b, faceA);
  Vec3 hit;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (segmentPiercesFace(a[i], a[j], overB.h[i], overB.h[j], faceB, hit)) {
      best.offer(hit, closestOnFace(hit, faceB));
    }
    if (segmentPiercesFace(b[i], b[j], overA.h[i], overA.h[j], faceA, hit)) {
      best.offer(closestOnFace(hit, faceA), hit);
    }
    if (best.distance2 <= stop2) return finish();
  }

  for (int i = 0; i < 3; ++i) {
    if (!faceFartherThan(a[i], overB.h[i], faceB, std::min(ceiling2, best.distance2))) {
      best.offer(a[i], closestOnFace(a[i], faceB));
    }
    if (!faceFartherThan(b[i], overA.h[i], faceA, std::min(ceiling2, best.distance2))) {
      best.offer(closestOnFace(b[i], faceA), b[i]);
    }
  }
  if (best.distance2 <= stop2) return finish();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      offerEdgeEdge(a[i], a[(i + 1) % 3], b[j], b[(j + 1) % 3], ceiling2, best);
    }
  }
  return finish();
}

TrianglePairResult triangleDistanceUpTo(const Vec3& a0, const Vec3& a1, const Vec3& a2, const Vec3& b0, const Vec3& b1,
                                        const Vec3& b2, double enough) {
  return triangleDistanceBelow(a0, a1, a2, b0, b1, b2, enough, std::numeric_limits<double>::infinity());
}

TrianglePairResult triangleDistance(const Vec3& a0, const Vec3& a1, const Vec3& a2, const Vec3& b0, const Vec3& b1,
                                    const Vec3& b2) {
  return triangleDistanceUpTo(a0, a1, a2, b0, b1, b2, -1.0);
}

}  // namespace adsd
