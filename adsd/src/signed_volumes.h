#pragma once
// The distance sub-algorithm of GJK: the point of a simplex (1 to 4 points) closest to the
// origin, by signed volumes (Montanari, Petrinic and Barbieri, "Improving the GJK algorithm for
// faster and more reliable distance queries between convex objects", ACM TOG 2017). Unlike
// Johnson's sub-algorithm it never divides by a volume that rounding may have made meaningless:
// each sub-simplex is entered only when the signs of its signed volumes say the origin projects
// outside the larger one.

#include "adsd/mesh.h"

namespace adsd::detail {

struct SimplexSolution {
  /// Barycentric weights of the closest point, one per input point (0 for points dropped).
  double weight[4] = {0.0, 0.0, 0.0, 0.0};
  /// The closest point itself (sum of weight[i] * point[i]).
  Vec3 closest = Vec3::Zero();
  /// True when the origin lies inside the tetrahedron (only for 4 points).
  bool containsOrigin = false;
};

/// \brief Closest point to the origin of the simplex spanned by points[0..count-1], count in 1..4.
SimplexSolution closestPointOfSimplex(const Vec3* points, int count);

}  // namespace adsd::detail
