#pragma once
/// \file
/// \brief A smooth time-varying displacement field for the deforming scenes (the paper's
/// deforming teddies, sec. 7: the same mesh, new vertex positions every frame, nothing rebuilt).

#include <cmath>
#include <vector>

#include "adsd/mesh.h"

namespace adsd::bench {

/// \brief d(p, t) = amplitude · (sin(k₀·p + ω t + φ₀), sin(k₁·p + ω t + φ₁), sin(k₂·p + ω t + φ₂)):
/// each coordinate a travelling plane wave, so the field is smooth in space (wavelength 2π/|kᵢ|)
/// and time (period 2π/ω), bounded by amplitude·√3, and the surface bends without tearing.
struct SmoothDeformation {
  double amplitude = 0.0;     ///< length units: largest displacement per coordinate
  Vec3 waveVector[3] = {Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ()};  ///< 1 / length units
  double angularFrequency = 0.0;  ///< radians per unit of t
  double phase[3] = {0.0, 0.0, 0.0};

  /// \brief Writes the displaced \p rest vertices at time \p t into \p out (resized to match).
  void apply(const std::vector<Vec3>& rest, double t, std::vector<Vec3>& out) const {
    out.resize(rest.size());
    const double wt = angularFrequency * t;
    for (std::size_t i = 0; i < rest.size(); ++i) {
      const Vec3& p = rest[i];
      out[i] = p + amplitude * Vec3(std::sin(waveVector[0].dot(p) + wt + phase[0]),
                                    std::sin(waveVector[1].dot(p) + wt + phase[1]),
                                    std::sin(waveVector[2].dot(p) + wt + phase[2]));
    }
  }
};

}  // namespace adsd::bench
