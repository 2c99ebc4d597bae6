#pragma once
/// \file
/// \brief Deterministic random geometry for tests: the same numbers on every platform and
/// standard library (std::uniform_real_distribution is not specified bit-exactly, so it is not
/// used).

#include <cmath>
#include <cstdint>
#include <random>

#include "adsd/mesh.h"

namespace adsd::oracle {

class SeededRandom {
 public:
  explicit SeededRandom(std::uint64_t seed) : engine_(seed) {}

  /// Uniform in [0, 1): the top 53 bits of one 64-bit draw.
  double uniform() { return double(engine_() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  /// Uniform integer in [0, n).
  std::uint64_t below(std::uint64_t n) { return engine_() % n; }
  /// 10^uniform(lo, hi): log-uniform magnitudes.
  double logUniform(double log10Lo, double log10Hi) { return std::pow(10.0, uniform(log10Lo, log10Hi)); }
  Vec3 inCube(double halfSide) {
    return Vec3(uniform(-halfSide, halfSide), uniform(-halfSide, halfSide), uniform(-halfSide, halfSide));
  }
  /// Uniform on the unit sphere (rejection from the cube, then normalized).
  Vec3 unitVector() {
    for (;;) {
      const Vec3 v = inCube(1.0);
      const double n = v.squaredNorm();
      if (n > 1e-6 && n <= 1.0) return v / std::sqrt(n);
    }
  }
  /// Uniform random rotation (unit quaternion uniform on S^3, by rejection from the 4-cube).
  Eigen::Quaterniond rotation() {
    for (;;) {
      const Eigen::Vector4d v(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
      const double n = v.squaredNorm();
      if (n > 1e-6 && n <= 1.0) {
        const Eigen::Vector4d u = v / std::sqrt(n);
        return Eigen::Quaterniond(u[0], u[1], u[2], u[3]);
      }
    }
  }
  /// Rotation by an angle drawn uniformly from [0, maxAngle] about a uniform axis.
  Eigen::Quaterniond smallRotation(double maxAngle) {
    return Eigen::Quaterniond(Eigen::AngleAxisd(uniform(0.0, maxAngle), unitVector()));
  }
  std::mt19937_64& engine() { return engine_; }

 private:
  std::mt19937_64 engine_;
};

}  // namespace adsd::oracle
