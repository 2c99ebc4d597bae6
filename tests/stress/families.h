#pragma once
/// \file
/// \brief The named case families of the stress suite (issue 3, item 2), at the triangle level
/// (two one-triangle meshes) and at the mesh level (small meshes, both query paths).
///
/// A family is a generator of cases parameterized by a random stream (from the seed) and a scale
/// (the length unit of the case). The suite draws each case's scale log-uniformly from the
/// family's range (1e-6 ... 1e6 unless the family is about absolute size), so every family is
/// also run at every scale; --scale pins it.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "random_geometry.h"
#include "stress_case.h"

namespace adsd::stress {

using oracle::SeededRandom;

/// \brief What a family's sample must contain to be doing its job (STYLE habit 10: check that the
/// random sample really hit the intended mix). Fractions of the family's cases, judged by the
/// oracle, not by the code under test.
struct ExpectedMix {
  double contact = 0.0;  ///< at least this fraction with oracle distance 0 or an exact intersection
  double near = 0.0;     ///< at least this fraction with 0 < oracle distance <= 1e-6 x diagonal
  double apart = 0.0;    ///< at least this fraction with oracle distance > 1e-6 x diagonal
};

/// \brief The geometry one generator call produces (the suite adds family, seed, index, scale).
struct Generated {
  Mesh a, b;
  Pose poseA = Pose::Identity();
  Pose poseB = Pose::Identity();
  std::string variant;
  bool penetrating = false;  ///< see StressCase::penetrating
};

struct Family {
  std::string name;     ///< "tri/..." or "mesh/..."
  std::string covers;   ///< one line: what geometry, which item of issue 3
  double log10ScaleLo = -6.0, log10ScaleHi = 6.0;  ///< default scale range (log10 of length units)
  ExpectedMix mix;
  std::function<Generated(SeededRandom&, double scale)> generate;
};

/// \brief Every family, triangle level first.
const std::vector<Family>& families();
/// \brief The family called \p name, or null.
const Family* findFamily(const std::string& name);

/// \brief Case \p index of \p family for \p seed: deterministic (independent of threads and of
/// the other families), so that any case can be regenerated from its name, seed and index.
/// \p fixedScale > 0 pins the scale instead of drawing it from the family's range.
StressCase generateCase(const Family& family, std::uint64_t seed, std::uint64_t index, double fixedScale = 0.0);

// The two halves of the registry (triangle_families.cpp, mesh_families.cpp).
std::vector<Family> triangleFamilies();
std::vector<Family> meshFamilies();

}  // namespace adsd::stress
