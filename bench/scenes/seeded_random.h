#pragma once
/// \file
/// \brief A fixed-seed random source whose sequence is the same on every compiler and library
/// (std::uniform_real_distribution is not specified bit for bit, so benchmarks that must pick the
/// same poses everywhere draw from this instead).

#include <cmath>
#include <cstdint>

#include "adsd/mesh.h"

namespace adsd::bench {

/// \brief SplitMix64 (Steele, Lea, Flood 2014): tiny, fast, and good enough to scatter poses.
class SeededRandom {
 public:
  explicit SeededRandom(std::uint64_t seed) : state_(seed) {}

  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }

  /// Uniform in [0, 1): the top 53 bits scaled by 2^-53.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

  /// Uniformly distributed rotation (Shoemake's subgroup algorithm, Graphics Gems III).
  Eigen::Quaterniond rotation() {
    const double u1 = uniform(), u2 = 2.0 * M_PI * uniform(), u3 = 2.0 * M_PI * uniform();
    const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
    return Eigen::Quaterniond(b * std::cos(u3), a * std::sin(u2), a * std::cos(u2), b * std::sin(u3));
  }

  /// Uniformly distributed unit vector (a normalized rotation of the x axis).
  Vec3 direction() { return rotation() * Vec3::UnitX(); }

 private:
  std::uint64_t state_;
};

}  // namespace adsd::bench
