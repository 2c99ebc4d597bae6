#pragma once
/// \file
/// \brief One stress case: two meshes, their poses, and where the case came from.

#include <array>
#include <cstdint>
#include <string>

#include "adsd/mesh.h"

namespace adsd::stress {

/// \brief Two meshes placed in the world, as a family generated them (or as a pinned regression
/// spells them out). Everything the checks need; the expected answer is NOT part of it: it comes
/// from the oracle every time.
struct StressCase {
  std::string family;       ///< name of the generating family ("pinned" for regressions)
  std::uint64_t seed = 0;   ///< the run's seed (--seed)
  std::uint64_t index = 0;  ///< case number within the family for that seed
  double scale = 1.0;       ///< the family's length unit for this case
  std::string variant;      ///< which branch of the family's generator made it (for reports)
  /// The generator built a volume overlap of at least 1e-3 x the shapes' size (a vertex of one
  /// mesh deep inside the other), so some triangle pair crosses with a margin far above rounding: the
  /// meshes intersect robustly and every answer must be exactly 0 (distance.h: "intersecting
  /// meshes give distance 0"), not merely within 1e-10 x the diagonal of it.
  bool penetrating = false;
  Mesh a, b;
  Pose poseA = Pose::Identity();
  Pose poseB = Pose::Identity();
};

/// \brief Bounding-box diagonal of both meshes placed in the world: the yardstick of every
/// accuracy figure (issues 2 and 3: errors are reported and bounded relative to it).
double sceneDiagonal(const StressCase& c);

/// \brief Largest |coordinate| of any placed vertex in the world frame, and of any vertex in its
/// mesh frame: what double rounding of world-frame output (witness points) scales with.
double worldMagnitude(const StressCase& c);

/// \brief The case spelled out as C++ (every double as a hex float, decimal in a comment), ready
/// to paste into a pinned regression test (see regressions_test.cpp for the form).
std::string caseAsCode(const StressCase& c);

/// \brief The pose with the given 3 x 4 matrix, row by row (rotation | translation), as
/// caseAsCode() prints it: exact, unlike a quaternion.
Pose poseFromRows(const std::array<double, 12>& rows);

/// \brief One line: family, seed, index, variant, scale, sizes.
std::string caseHeadline(const StressCase& c);

/// \brief Exact text of a double: "%a (%.17g)".
std::string exactNumber(double x);

}  // namespace adsd::stress
