#include "exact_orientation.h"

#include <cmath>
#include <limits>
#include <vector>

namespace adsd::oracle::exact {

namespace {

constexpr double kUnitRoundoff = std::numeric_limits<double>::epsilon() / 2;  // 2^-53

/// A value held exactly as a sum of doubles that do not overlap, in increasing magnitude.
class Expansion {
 public:
  /// Adds b exactly (Shewchuk's GROW-EXPANSION with zero elimination).
  void add(double b) {
    double carry = b;
    std::size_t kept = 0;
    for (double component : terms_) {
      double sum, error;
      twoSum(carry, component, sum, error);
      carry = sum;
      if (error != 0.0) terms_[kept++] = error;
    }
    terms_.resize(kept);
    if (carry != 0.0) terms_.push_back(carry);
  }
  /// Adds sign * x * y * z exactly: x*y = p + e exactly (fma), then p*z and e*z likewise.
  void addProduct(double x, double y, double z, int sign) {
    const double p = x * y;
    const double e = std::fma(x, y, -p);
    for (double factor : {p, e}) {
      const double high = factor * z;
      const double low = std::fma(factor, z, -high);
      add(sign * high);
      add(sign * low);
    }
  }
  /// The sign of a non-overlapping expansion is that of its largest component.
  int sign() const {
    if (terms_.empty()) return 0;
    return terms_.back() > 0 ? 1 : -1;
  }

 private:
  /// Knuth's TwoSum: s + e == a + b exactly, for any ordering of magnitudes.
  static void twoSum(double a, double b, double& s, double& e) {
    s = a + b;
    const double bVirtual = s - a;
    const double aVirtual = s - bVirtual;
    e = (a - aVirtual) + (b - bVirtual);
  }
  std::vector<double> terms_;
};

/// A coordinate difference a - b held exactly as high + low.
struct ExactDifference {
  double high, low;
  ExactDifference(double a, double b) {
    high = a - b;
    const double bVirtual = a - high;
    const double aVirtual = high + bVirtual;
    low = (a - aVirtual) + (bVirtual - b);
  }
};

int signOf(double x) { return (x > 0) - (x < 0); }

}  // namespace

int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  // Fast path: the determinant in doubles with a forward error bound. Shewchuk's bound for this
  // evaluation order is (7 + 56 u) u * permanent; 16 u leaves a wide margin.
  const Vec3 ad = a - d, bd = b - d, cd = c - d;
  const double minor1 = bd.y() * cd.z() - bd.z() * cd.y();
  const double minor2 = cd.y() * ad.z() - cd.z() * ad.y();
  const double minor3 = ad.y() * bd.z() - ad.z() * bd.y();
  const double det = ad.x() * minor1 + bd.x() * minor2 + cd.x() * minor3;
  const double permanent = std::abs(ad.x()) * (std::abs(bd.y() * cd.z()) + std::abs(bd.z() * cd.y())) +
                           std::abs(bd.x()) * (std::abs(cd.y() * ad.z()) + std::abs(cd.z() * ad.y())) +
                           std::abs(cd.x()) * (std::abs(ad.y() * bd.z()) + std::abs(ad.z() * bd.y()));
  if (std::abs(det) > 16 * kUnitRoundoff * permanent) return signOf(det);

  // Exact path: the 6 signed products of the Leibniz formula over the exact differences.
  const ExactDifference u[3] = {{a.x(), d.x()}, {a.y(), d.y()}, {a.z(), d.z()}};
  const ExactDifference v[3] = {{b.x(), d.x()}, {b.y(), d.y()}, {b.z(), d.z()}};
  const ExactDifference w[3] = {{c.x(), d.x()}, {c.y(), d.y()}, {c.z(), d.z()}};
  static constexpr int kPermutations[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  static constexpr int kSigns[6] = {1, 1, 1, -1, -1, -1};
  Expansion sum;
  for (int p = 0; p < 6; ++p) {
    const ExactDifference& x = u[kPermutations[p][0]];
    const ExactDifference& y = v[kPermutations[p][1]];
    const ExactDifference& z = w[kPermutations[p][2]];
    for (double xi : {x.high, x.low}) {
      if (xi == 0.0) continue;
      for (double yi : {y.high, y.low}) {
        if (yi == 0.0) continue;
        for (double zi : {z.high, z.low}) {
          if (zi != 0.0) sum.addProduct(xi, yi, zi, kSigns[p]);
        }
      }
    }
  }
  return sum.sign();
}

int orient2d(const Vec3& a, const Vec3& b, const Vec3& c, int u, int v) {
  const double acu = a[u] - c[u], acv = a[v] - c[v], bcu = b[u] - c[u], bcv = b[v] - c[v];
  const double det = acu * bcv - acv * bcu;
  // Shewchuk's bound for this evaluation is (3 + 16 u) u * permanent; 8 u leaves a wide margin.
  const double permanent = std::abs(acu * bcv) + std::abs(acv * bcu);
  if (std::abs(det) > 8 * kUnitRoundoff * permanent) return signOf(det);

  const ExactDifference x1(a[u], c[u]), y1(a[v], c[v]), x2(b[u], c[u]), y2(b[v], c[v]);
  Expansion sum;
  for (double p : {x1.high, x1.low}) {
    for (double q : {y2.high, y2.low}) sum.addProduct(p, q, 1.0, 1);
  }
  for (double p : {y1.high, y1.low}) {
    for (double q : {x2.high, x2.low}) sum.addProduct(p, q, 1.0, -1);
  }
  return sum.sign();
}

}  // namespace adsd::oracle::exact
