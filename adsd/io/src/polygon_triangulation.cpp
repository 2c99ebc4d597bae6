#include "polygon_triangulation.h"

#include <algorithm>
#include <cmath>

namespace adsd::io::detail {

namespace {

/// A corner whose turn, against the polygon's normal, is below this fraction of the product of
/// the lengths involved counts as turning the other way: collinear corners, and their rounding,
/// leave a polygon convex.
constexpr double kTurnTolerance = 1e-12;

struct Point2 {
  double x, y;
};

double cross(const Point2& o, const Point2& a, const Point2& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

/// Whether \p p lies in the counter-clockwise triangle (a, b, c) or on its boundary.
bool inTriangle(const Point2& p, const Point2& a, const Point2& b, const Point2& c) {
  return cross(a, b, p) >= 0.0 && cross(b, c, p) >= 0.0 && cross(c, a, p) >= 0.0;
}

bool same(const Point2& p, const Point2& q) { return p.x == q.x && p.y == q.y; }

void fan(const std::vector<std::uint32_t>& order, std::vector<std::array<std::uint32_t, 3>>& triangles) {
  for (std::size_t k = 2; k < order.size(); ++k) triangles.push_back({order[0], order[k - 1], order[k]});
}

}  // namespace

PolygonKind triangulatePolygon(const std::vector<Vec3>& corners, std::vector<std::array<std::uint32_t, 3>>& triangles,
                               std::uint64_t& testsLeft) {
  const std::size_t n = corners.size();
  std::vector<std::uint32_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = static_cast<std::uint32_t>(i);
  // Newell's normal, twice the polygon's vector area, from the first corner (small numbers).
  Vec3 normal = Vec3::Zero();
  for (std::size_t i = 1; i + 1 < n; ++i) normal += (corners[i] - corners[0]).cross(corners[i + 1] - corners[0]);
  const double area2 = normal.norm();
  if (n == 3 || !(area2 > 0.0)) {
    fan(order, triangles);
    return PolygonKind::convex;
  }
  bool convex = true;
  for (std::size_t i = 0; i < n && convex; ++i) {
    const Vec3 in = corners[i] - corners[(i + n - 1) % n];
    const Vec3 out = corners[(i + 1) % n] - corners[i];
    convex = in.cross(out).dot(normal) >= -kTurnTolerance * in.norm() * out.norm() * area2;
  }
  if (convex) {
    fan(order, triangles);
    return PolygonKind::convex;
  }
  if (n > kMaxClippedCorners) return PolygonKind::tooLarge;

  // The plane across the normal, with axes u, v such that u x v is the unit normal: the polygon
  // then winds counter-clockwise in (u, v).
  const Vec3 unit = normal / area2;
  Eigen::Index smallest;
  unit.cwiseAbs().minCoeff(&smallest);
  const Vec3 u = unit.cross(Vec3::Unit(smallest)).normalized();
  const Vec3 v = unit.cross(u);
  std::vector<Point2> p(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 d = corners[i] - corners[0];
    p[i] = {d.dot(u), d.dot(v)};
  }
  // The corners left, as a ring.
  std::vector<std::uint32_t> previous(n), next(n);
  for (std::size_t i = 0; i < n; ++i) {
    previous[i] = static_cast<std::uint32_t>((i + n - 1) % n);
    next[i] = static_cast<std::uint32_t>((i + 1) % n);
  }
  std::uint64_t tests = 0;
  auto isEar = [&](std::uint32_t i) {
    const std::uint32_t a = previous[i], c = next[i];
    if (!(cross(p[a], p[i], p[c]) > 0.0)) return false;  // turns the other way, or not at all
    for (std::uint32_t j = next[c]; j != a; j = next[j]) {
      ++tests;
      if (same(p[j], p[a]) || same(p[j], p[i]) || same(p[j], p[c])) continue;
      if (inTriangle(p[j], p[a], p[i], p[c])) return false;
    }
    return true;
  };
  std::size_t left = n;
  std::uint32_t i = 0;
  std::size_t tried = 0;  // corners tried since the last ear
  while (left > 3) {
    // Counted per corner tried, each at most `left` tests: a few more than the budget at worst.
    if (tests > testsLeft) {
      testsLeft = 0;
      return PolygonKind::outOfTests;
    }
    if (isEar(i)) {
      triangles.push_back({previous[i], i, next[i]});
      next[previous[i]] = next[i];
      previous[next[i]] = previous[i];
      i = previous[i];
      --left;
      tried = 0;
      continue;
    }
    if (++tried > left) {  // no ear: the polygon crosses itself; fan what is left
      std::vector<std::uint32_t> rest;
      for (std::size_t k = 0; k < left; ++k, i = next[i]) rest.push_back(i);
      fan(rest, triangles);
      testsLeft -= std::min(tests, testsLeft);
      return PolygonKind::clipped;
    }
    i = next[i];
  }
  triangles.push_back({previous[i], i, next[i]});
  testsLeft -= std::min(tests, testsLeft);
  return PolygonKind::clipped;
}

}  // namespace adsd::io::detail
