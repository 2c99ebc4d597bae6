#pragma once
/// \file
/// \brief The oracle's number type: IEEE binary128 (__float128, 113-bit significand, unit
/// roundoff 2^-113 ~ 9.6e-35) through libquadmath, and a minimal 3-vector of it.
///
/// Eigen is not used here on purpose: the oracle shares no arithmetic code with the core.

#include <quadmath.h>

#include <array>
#include <string>

#include "adsd/mesh.h"

namespace adsd::oracle {

using Quad = __float128;

/// \brief A point or vector with binary128 coordinates.
struct Quad3 {
  std::array<Quad, 3> c{};

  Quad3() = default;
  Quad3(Quad x, Quad y, Quad z) : c{x, y, z} {}
  /// Exact: every double is a binary128 value.
  explicit Quad3(const Vec3& v) : c{v.x(), v.y(), v.z()} {}

  Quad operator[](int i) const { return c[i]; }
  Quad& operator[](int i) { return c[i]; }
  /// Rounded to nearest double per coordinate.
  Vec3 toDouble() const { return Vec3(double(c[0]), double(c[1]), double(c[2])); }
};

inline Quad3 operator+(const Quad3& a, const Quad3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Quad3 operator-(const Quad3& a, const Quad3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Quad3 operator*(Quad s, const Quad3& a) { return {s * a[0], s * a[1], s * a[2]}; }
inline Quad dot(const Quad3& a, const Quad3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Quad3 cross(const Quad3& a, const Quad3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline Quad squaredNorm(const Quad3& a) { return dot(a, a); }
inline Quad norm(const Quad3& a) { return sqrtq(dot(a, a)); }
inline Quad absQ(Quad x) { return x < 0 ? -x : x; }

/// \brief p_world = R p + t with R and t taken exactly from the double pose and every product and
/// sum rounded once in binary128 (relative error ~1e-34 instead of double's ~1e-16).
inline Quad3 applyPose(const Pose& pose, const Vec3& p) {
  const auto& m = pose.matrix();
  Quad3 out;
  for (int r = 0; r < 3; ++r) {
    out[r] = Quad(m(r, 0)) * Quad(p.x()) + Quad(m(r, 1)) * Quad(p.y()) + Quad(m(r, 2)) * Quad(p.z()) + Quad(m(r, 3));
  }
  return out;
}

/// \brief Decimal text of a binary128 value with all its digits (for failure messages).
inline std::string toString(Quad x) {
  char buffer[64];
  quadmath_snprintf(buffer, sizeof buffer, "%.36Qg", x);
  return buffer;
}

}  // namespace adsd::oracle
