#pragma once
/// \file
/// \brief How the benchmarks place their scenes' poses: with FCL's distance and hull test, so
/// that the scenes do not depend on the code under test (bench/scenes/distance_scenes.h asks the
/// caller for both).

#include <algorithm>

#include "fcl_models.h"
#include "scenes/distance_scenes.h"

namespace adsd::bench {

/// \brief FCL's distance (prebuilt OBBRSS) and convex-hull overlap test for meshes \p a and \p b.
inline Placement fclPlacement(const Mesh& a, const Mesh& b) {
  auto modelA = buildObbrss(a.vertices(), fclTriangles(a));
  auto modelB = buildObbrss(b.vertices(), fclTriangles(b));
  auto hullA = fclHull(a);
  auto hullB = fclHull(b);
  return {[=](const Pose& pa, const Pose& pb) {
            return std::max(0.0, fclDistance(*modelA, pa, *modelB, pb).min_distance);
          },
          [=](const Pose& pa, const Pose& pb) { return fclHullsOverlap(*hullA, pa, *hullB, pb); }};
}

}  // namespace adsd::bench
