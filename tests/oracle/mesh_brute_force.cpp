/// \file
/// \brief Mesh-mesh distance and intersection by considering every triangle pair.
///
/// A pair is skipped only when a lower bound on its distance, computed in double, exceeds the
/// best distance found so far by more than a slack that covers the bound's rounding. Everything
/// that decides the answer (poses, triangle distances) is binary128.

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

#include "oracle.h"

namespace adsd::oracle {

namespace {

/// A triangle placed in the world: binary128 corners plus double-precision bounds data.
struct PlacedTriangle {
  std::array<Quad3, 3> corners;
  std::array<Vec3, 3> approx;  ///< corners rounded to double
  Vec3 centre;                 ///< centroid of approx
  double radius;               ///< max |approx corner - centre|
  Vec3 normal;                 ///< unit normal of approx (zero if degenerate)
  std::array<Vec3, 3> edges;   ///< approx[k+1] - approx[k]
};

std::vector<PlacedTriangle> place(const Mesh& mesh, const Pose& pose) {
  std::vector<Quad3> vertices;
  vertices.reserve(mesh.vertices().size());
  for (const Vec3& v : mesh.vertices()) vertices.push_back(applyPose(pose, v));
  std::vector<PlacedTriangle> placed(mesh.triangleCount());
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    PlacedTriangle& p = placed[t];
    for (int k = 0; k < 3; ++k) {
      p.corners[k] = vertices[mesh.triangles()[t][k]];
      p.approx[k] = p.corners[k].toDouble();
    }
    p.centre = (p.approx[0] + p.approx[1] + p.approx[2]) / 3.0;
    p.radius = 0.0;
    for (int k = 0; k < 3; ++k) p.radius = std::max(p.radius, (p.approx[k] - p.centre).norm());
    for (int k = 0; k < 3; ++k) p.edges[k] = p.approx[(k + 1) % 3] - p.approx[k];
    const Vec3 n = (p.approx[1] - p.approx[0]).cross(p.approx[2] - p.approx[0]);
    const double length = n.norm();
    p.normal = length > 0.0 ? Vec3(n / length) : Vec3::Zero();
  }
  return placed;
}

/// Slack added to every double-precision lower bound, in length units: the bounds are sums of a
/// few products of coordinates of magnitude <= `magnitude`, each rounded with relative error
/// 2^-53 ~ 1.1e-16, plus the rounding of the binary128 corners to double (same size). A few
/// dozen roundings amount to < 1e-14 x magnitude; 1e-12 x magnitude is 100 times that.
double boundSlack(const std::vector<PlacedTriangle>& a, const std::vector<PlacedTriangle>& b) {
  double magnitude = 0.0;
  for (const auto* mesh : {&a, &b}) {
    for (const PlacedTriangle& t : *mesh) {
      for (const Vec3& v : t.approx) magnitude = std::max(magnitude, v.cwiseAbs().maxCoeff());
    }
  }
  return 1e-12 * magnitude + std::numeric_limits<double>::min();
}

/// Gap between the projections of the two triangles on the unit direction u (a lower bound on
/// their distance, since |p - q| >= |u . (p - q)| for every p, q); <= 0 if they overlap.
double projectionGap(const PlacedTriangle& s, const PlacedTriangle& t, const Vec3& u) {
  double sMin = std::numeric_limits<double>::infinity(), sMax = -sMin, tMin = sMin, tMax = -sMin;
  for (int k = 0; k < 3; ++k) {
    const double ps = u.dot(s.approx[k]), pt = u.dot(t.approx[k]);
    sMin = std::min(sMin, ps);
    sMax = std::max(sMax, ps);
    tMin = std::min(tMin, pt);
    tMax = std::max(tMax, pt);
  }
  return std::max(tMin - sMax, sMin - tMax);
}

/// A lower bound on the distance of two placed triangles (before the slack is subtracted): the
/// bounding spheres, then the projection gaps along the separating-axis candidates (both normals
/// and the nine edge-edge cross products, which include the direction of the closest pair in
/// the vertex-face and edge-edge cases, so the bound is usually tight) and the line of centres.
/// Each direction is normalized, i.e. unit up to rounding, which the slack covers.
double lowerBound(const PlacedTriangle& s, const PlacedTriangle& t, double prune) {
  const Vec3 between = t.centre - s.centre;
  const double centreDistance = between.norm();
  double bound = centreDistance - s.radius - t.radius;
  if (bound > prune) return bound;
  bound = std::max(bound, projectionGap(s, t, s.normal));
  bound = std::max(bound, projectionGap(s, t, t.normal));
  if (centreDistance > 0.0) bound = std::max(bound, projectionGap(s, t, between / centreDistance));
  for (int i = 0; i < 3 && bound <= prune; ++i) {
    for (int j = 0; j < 3; ++j) {
      const Vec3 axis = s.edges[i].cross(t.edges[j]);
      const double length = axis.norm();
      if (length > 0.0) bound = std::max(bound, projectionGap(s, t, axis / length));
    }
  }
  return bound;
}

/// B's triangles sorted by centre x: for a triangle s of A only the window
/// |centre_x(t) - centre_x(s)| <= reach can hold a triangle t within distance reach - r_s - r_t,
/// since the centre distance is at least the difference in x.
class SortedByCentreX {
 public:
  explicit SortedByCentreX(const std::vector<PlacedTriangle>& triangles) : order_(triangles.size()) {
    std::iota(order_.begin(), order_.end(), 0);
    std::sort(order_.begin(), order_.end(),
              [&](std::size_t i, std::size_t j) { return triangles[i].centre.x() < triangles[j].centre.x(); });
    for (std::size_t i : order_) {
      x_.push_back(triangles[i].centre.x());
      maxRadius_ = std::max(maxRadius_, triangles[i].radius);
    }
  }
  double maxRadius() const { return maxRadius_; }
  /// Calls visit(j) for every triangle j whose centre x lies within reach of x, in x order;
  /// stops early when visit returns false.
  template <class Visit>
  void forEachNear(double x, double reach, Visit&& visit) const {
    for (auto k = std::size_t(std::lower_bound(x_.begin(), x_.end(), x - reach) - x_.begin());
         k < x_.size() && x_[k] <= x + reach; ++k) {
      if (!visit(order_[k])) return;
    }
  }

 private:
  std::vector<std::size_t> order_;
  std::vector<double> x_;
  double maxRadius_ = 0.0;
};

}  // namespace

std::array<Quad3, 3> posedTriangle(const Mesh& mesh, const Pose& pose, std::size_t t) {
  return {applyPose(pose, mesh.corner(t, 0)), applyPose(pose, mesh.corner(t, 1)),
          applyPose(pose, mesh.corner(t, 2))};
}

MeshPairDistance meshDistance(const Mesh& a, const Pose& poseA, const Mesh& b, const Pose& poseB) {
  const std::vector<PlacedTriangle> placedA = place(a, poseA);
  const std::vector<PlacedTriangle> placedB = place(b, poseB);
  const double slack = boundSlack(placedA, placedB);

  const SortedByCentreX sortedB(placedB);

  MeshPairDistance result;
  Quad bestSquared = -1;
  double best = std::numeric_limits<double>::infinity();  // rounded up from bestSquared's root
  auto evaluate = [&](std::size_t i, std::size_t j) {
    const PlacedTriangle& s = placedA[i];
    const PlacedTriangle& t = placedB[j];
    ++result.trianglePairsEvaluated;
    const TrianglePairDistance d =
        triangleDistance(s.corners[0], s.corners[1], s.corners[2], t.corners[0], t.corners[1], t.corners[2]);
    const Quad squared = d.distance * d.distance;
    if (bestSquared < 0 || squared < bestSquared) {
      bestSquared = squared;
      result.distance = d.distance;
      result.triangleA = static_cast<std::int64_t>(i);
      result.triangleB = static_cast<std::int64_t>(j);
      result.pointOnA = d.pointOnA.toDouble();
      result.pointOnB = d.pointOnB.toDouble();
      best = std::nextafter(double(d.distance), std::numeric_limits<double>::infinity());
    }
  };

  // Seed: the pair of triangles with the closest centres (found with the sorted window, which
  // shrinks as closer centres turn up). Its distance is a valid upper bound to start pruning with.
  {
    double closest = std::numeric_limits<double>::infinity();
    std::size_t seedA = 0, seedB = 0;
    for (std::size_t i = 0; i < placedA.size(); ++i) {
      sortedB.forEachNear(placedA[i].centre.x(), closest, [&](std::size_t j) {
        const double centres = (placedB[j].centre - placedA[i].centre).norm();
        if (centres < closest) {
          closest = centres;
          seedA = i;
          seedB = j;
        }
        return true;
      });
    }
    evaluate(seedA, seedB);
  }

  for (std::size_t i = 0; i < placedA.size(); ++i) {
    const PlacedTriangle& s = placedA[i];
    sortedB.forEachNear(s.centre.x(), best + s.radius + sortedB.maxRadius() + slack, [&](std::size_t j) {
      if (lowerBound(s, placedB[j], best + slack) - slack <= best) evaluate(i, j);
      return true;
    });
  }
  result.value = double(result.distance);
  return result;
}

bool meshesIntersect(const Mesh& a, const Pose& poseA, const Mesh& b, const Pose& poseB) {
  const std::vector<PlacedTriangle> placedA = place(a, poseA);
  const std::vector<PlacedTriangle> placedB = place(b, poseB);
  const double slack = boundSlack(placedA, placedB);
  const SortedByCentreX sortedB(placedB);
  bool found = false;
  for (const PlacedTriangle& s : placedA) {
    sortedB.forEachNear(s.centre.x(), s.radius + sortedB.maxRadius() + slack, [&](std::size_t j) {
      const PlacedTriangle& t = placedB[j];
      if (lowerBound(s, t, slack) - slack > 0.0) return true;
      found = trianglesIntersect(s.corners[0], s.corners[1], s.corners[2], t.corners[0], t.corners[1], t.corners[2]);
      return !found;
    });
    if (found) return true;
  }
  return false;
}

}  // namespace adsd::oracle
