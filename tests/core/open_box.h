#pragma once
/// \file
/// \brief A test shape shared by the convex-pair suites: a box with one face left out.

#include <utility>
#include <vector>

#include "adsd/shapes.h"

namespace adsd::testing {

/// A cube of half side \p half with the two triangles of its +x face left out: convex in shape and
/// on its hull's boundary, but not closed (its hull is nearest where it has no triangle).
inline Mesh openBox(double half) {
  const Mesh closed = shapes::box(Vec3(half, half, half));
  std::vector<TriangleIndices> kept;
  for (std::size_t t = 0; t < closed.triangleCount(); ++t) {
    bool onPlusX = true;
    for (int k = 0; k < 3; ++k) onPlusX = onPlusX && closed.corner(t, k).x() > 0.5 * half;
    if (!onPlusX) kept.push_back(closed.triangles()[t]);
  }
  return Mesh(closed.vertices(), std::move(kept), "open box");
}

}  // namespace adsd::testing
