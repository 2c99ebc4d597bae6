/// \file
/// \brief Whether two closed triangles (possibly degenerate) share a point, from orientation
/// signs only, so that the decision is exact when the signs are.
///
/// Reduction: if two closed triangles meet, an extreme point of their (convex, compact)
/// intersection lies on the relative boundary of one of them (a point in both relative interiors
/// has a neighbourhood of the intersection that is a segment or a disc through it, so it is not
/// extreme). Hence they meet iff an edge of one meets the other triangle. For a degenerate
/// triangle the edges cover it, so the same holds.
///
/// Segment pq against triangle abc:
/// - abc degenerate (collinear corners): pq meets one of its three edges;
/// - p and q strictly on one side of abc's plane: no;
/// - both on the plane: a 2-D problem in a coordinate projection that is injective on the plane
///   (the dropped axis is one where abc's normal is nonzero);
/// - otherwise the line pq crosses the plane inside the segment, and it passes through the closed
///   triangle iff the three orientations (p, q, a, b), (p, q, b, c), (p, q, c, a) are not of
///   mixed strict sign.
/// Segment pq against segment rs: they must be coplanar (orient3d zero); then they meet iff their
/// projections meet in all three coordinate planes (at least one projection is injective on a
/// plane or line containing all four points, and meeting in 3-D implies meeting in every
/// projection).

#include "exact_orientation.h"
#include "oracle.h"

namespace adsd::oracle {

namespace {

/// Orientation signs and coordinates of one point type: exact on doubles, binary128 on Quad3.
struct ExactDoubles {
  using Point = Vec3;
  static int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    return exact::orient3d(a, b, c, d);
  }
  static int orient2d(const Vec3& a, const Vec3& b, const Vec3& c, int u, int v) {
    return exact::orient2d(a, b, c, u, v);
  }
  static double coordinate(const Vec3& p, int axis) { return p[axis]; }
};

struct QuadPrecision {
  using Point = Quad3;
  static int signOf(Quad x) { return (x > 0) - (x < 0); }
  static int orient3d(const Quad3& a, const Quad3& b, const Quad3& c, const Quad3& d) {
    return signOf(dot(a - d, cross(b - d, c - d)));
  }
  static int orient2d(const Quad3& a, const Quad3& b, const Quad3& c, int u, int v) {
    return signOf((a[u] - c[u]) * (b[v] - c[v]) - (a[v] - c[v]) * (b[u] - c[u]));
  }
  static Quad coordinate(const Quad3& p, int axis) { return p[axis]; }
};

template <class Arithmetic>
class IntersectionTests {
 public:
  using P = typename Arithmetic::Point;

  static bool triangles(const P (&a)[3], const P (&b)[3]) {
    for (int i = 0; i < 3; ++i) {
      if (segmentTriangle(a[i], a[(i + 1) % 3], b)) return true;
    }
    for (int i = 0; i < 3; ++i) {
      if (segmentTriangle(b[i], b[(i + 1) % 3], a)) return true;
    }
    return false;
  }

 private:
  /// An axis along which the triangle's normal is nonzero (dropping it projects the triangle's
  /// plane injectively), or -1 if the corners are collinear. The normal's component along axis k
  /// is the 2-D orientation in the plane of the other two axes.
  static int projectionAxis(const P (&t)[3]) {
    for (int axis = 2; axis >= 0; --axis) {
      if (Arithmetic::orient2d(t[0], t[1], t[2], (axis + 1) % 3, (axis + 2) % 3) != 0) return axis;
    }
    return -1;
  }

  static bool segmentTriangle(const P& p, const P& q, const P (&t)[3]) {
    const int axis = projectionAxis(t);
    if (axis < 0) {
      for (int i = 0; i < 3; ++i) {
        if (segmentSegment(p, q, t[i], t[(i + 1) % 3])) return true;
      }
      return false;
    }
    const int sideP = Arithmetic::orient3d(t[0], t[1], t[2], p);
    const int sideQ = Arithmetic::orient3d(t[0], t[1], t[2], q);
    if (sideP * sideQ > 0) return false;
    if (sideP == 0 && sideQ == 0) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      if (pointInTriangle2d(p, t, u, v) || pointInTriangle2d(q, t, u, v)) return true;
      for (int i = 0; i < 3; ++i) {
        if (segmentSegment2d(p, q, t[i], t[(i + 1) % 3], u, v)) return true;
      }
      return false;
    }
    const int s0 = Arithmetic::orient3d(p, q, t[0], t[1]);
    const int s1 = Arithmetic::orient3d(p, q, t[1], t[2]);
    const int s2 = Arithmetic::orient3d(p, q, t[2], t[0]);
    const bool somePositive = s0 > 0 || s1 > 0 || s2 > 0;
    const bool someNegative = s0 < 0 || s1 < 0 || s2 < 0;
    return !(somePositive && someNegative);
  }

  /// Closed, non-degenerate projected triangle.
  static bool pointInTriangle2d(const P& p, const P (&t)[3], int u, int v) {
    const int s0 = Arithmetic::orient2d(t[0], t[1], p, u, v);
    const int s1 = Arithmetic::orient2d(t[1], t[2], p, u, v);
    const int s2 = Arithmetic::orient2d(t[2], t[0], p, u, v);
    const bool somePositive = s0 > 0 || s1 > 0 || s2 > 0;
    const bool someNegative = s0 < 0 || s1 < 0 || s2 < 0;
    return !(somePositive && someNegative);
  }

  static bool segmentSegment(const P& p, const P& q, const P& r, const P& s) {
    if (Arithmetic::orient3d(p, q, r, s) != 0) return false;
    for (int axis = 0; axis < 3; ++axis) {
      if (!segmentSegment2d(p, q, r, s, (axis + 1) % 3, (axis + 2) % 3)) return false;
    }
    return true;
  }

  /// x lies in the axis-aligned box of r and s (in the (u, v) projection).
  static bool inBox2d(const P& x, const P& r, const P& s, int u, int v) {
    for (int axis : {u, v}) {
      const auto lo = std::min(Arithmetic::coordinate(r, axis), Arithmetic::coordinate(s, axis));
      const auto hi = std::max(Arithmetic::coordinate(r, axis), Arithmetic::coordinate(s, axis));
      const auto value = Arithmetic::coordinate(x, axis);
      if (value < lo || value > hi) return false;
    }
    return true;
  }

  /// Closed 2-D segments, either possibly a single point.
  static bool segmentSegment2d(const P& p, const P& q, const P& r, const P& s, int u, int v) {
    const int d1 = Arithmetic::orient2d(r, s, p, u, v);
    const int d2 = Arithmetic::orient2d(r, s, q, u, v);
    const int d3 = Arithmetic::orient2d(p, q, r, u, v);
    const int d4 = Arithmetic::orient2d(p, q, s, u, v);
    if (d1 * d2 < 0 && d3 * d4 < 0) return true;  // proper crossing
    // Otherwise they meet only if an endpoint of one lies on the other (collinear and in its box).
    return (d1 == 0 && inBox2d(p, r, s, u, v)) || (d2 == 0 && inBox2d(q, r, s, u, v)) ||
           (d3 == 0 && inBox2d(r, p, q, u, v)) || (d4 == 0 && inBox2d(s, p, q, u, v));
  }
};

}  // namespace

bool trianglesIntersect(const Vec3& a0, const Vec3& a1, const Vec3& a2, const Vec3& b0, const Vec3& b1,
                        const Vec3& b2) {
  const Vec3 a[3] = {a0, a1, a2};
  const Vec3 b[3] = {b0, b1, b2};
  return IntersectionTests<ExactDoubles>::triangles(a, b);
}

bool trianglesIntersect(const Quad3& a0, const Quad3& a1, const Quad3& a2, const Quad3& b0, const Quad3& b1,
                        const Quad3& b2) {
  const Quad3 a[3] = {a0, a1, a2};
  const Quad3 b[3] = {b0, b1, b2};
  return IntersectionTests<QuadPrecision>::triangles(a, b);
}

}  // namespace adsd::oracle
