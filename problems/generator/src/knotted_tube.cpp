#include <cmath>
#include <numeric>

#include "adsd/error.h"
#include "adsd/shapes.h"
#include "ring_sweep.h"

namespace adsd::shapes {

namespace {

/// The (p, q) torus knot on the torus of core radius 2 and tube radius 1, times `scale`:
/// it winds p times around the z axis and q times through the torus hole.
Vec3 knotPoint(double scale, int p, int q, double phi) {
  const double rho = 2.0 + std::cos(q * phi);
  return scale * Vec3(rho * std::cos(p * phi), rho * std::sin(p * phi), -std::sin(q * phi));
}

Vec3 knotTangent(int p, int q, double phi) {
  const double rho = 2.0 + std::cos(q * phi);
  const double rhoDot = -q * std::sin(q * phi);
  return Vec3(rhoDot * std::cos(p * phi) - rho * p * std::sin(p * phi),
              rhoDot * std::sin(p * phi) + rho * p * std::cos(p * phi), -q * std::cos(q * phi))
      .normalized();
}

/// Any unit vector perpendicular to the unit vector t.
Vec3 perpendicular(const Vec3& t) {
  const Vec3 helper = std::abs(t.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  return (helper - helper.dot(t) * t).normalized();
}

}  // namespace

Mesh knottedTube(double scale, double tubeRadius, int p, int q, int pathSegments, int tubeSegments) {
  detail::requirePositive("knottedTube", "scale", scale);
  detail::requirePositive("knottedTube", "tubeRadius", tubeRadius);
  detail::requireAtLeast("knottedTube", "p", p, 1);
  detail::requireAtLeast("knottedTube", "q", q, 1);
  if (std::gcd(p, q) != 1) {
    throw InputError("shapes::knottedTube: p and q must be coprime (got " + std::to_string(p) + ", " +
                     std::to_string(q) + "), otherwise the curve is a link, not a knot");
  }
  detail::requireAtLeast("knottedTube", "pathSegments", pathSegments, 3);
  detail::requireAtLeast("knottedTube", "tubeSegments", tubeSegments, 3);

  // Frame along the closed curve by parallel transport (project the previous normal onto the new
  // normal plane), which does not twist the tube the way the Frenet frame does at inflections.
  // Transport around the loop comes back rotated by the curve's holonomy angle; spreading the
  // opposite rotation evenly over the samples closes the seam without a visible kink.
  std::vector<double> phis(pathSegments);
  std::vector<Vec3> tangents(pathSegments), normals(pathSegments);
  for (int i = 0; i < pathSegments; ++i) {
    phis[i] = 2.0 * M_PI * i / pathSegments;
    tangents[i] = knotTangent(p, q, phis[i]);
  }
  normals[0] = perpendicular(tangents[0]);
  for (int i = 1; i < pathSegments; ++i) {
    normals[i] = (normals[i - 1] - normals[i - 1].dot(tangents[i]) * tangents[i]).normalized();
  }
  const Vec3 back = (normals.back() - normals.back().dot(tangents[0]) * tangents[0]).normalized();
  const double holonomy = std::atan2(normals[0].cross(back).dot(tangents[0]), normals[0].dot(back));

  std::vector<std::vector<Vec3>> rings;
  for (int i = 0; i < pathSegments; ++i) {
    const double untwist = -holonomy * i / pathSegments;
    const Vec3& t = tangents[i];
    const Vec3 n = std::cos(untwist) * normals[i] + std::sin(untwist) * t.cross(normals[i]);
    const Vec3 b = t.cross(n);
    const Vec3 centre = knotPoint(scale, p, q, phis[i]);
    std::vector<Vec3> ring;
    for (int k = 0; k < tubeSegments; ++k) {
      const double angle = 2.0 * M_PI * k / tubeSegments;
      ring.push_back(centre + tubeRadius * (std::cos(angle) * n + std::sin(angle) * b));
    }
    rings.push_back(std::move(ring));
  }
  return detail::orientOutward(detail::sweepRings(rings, true, {}, {}, "knottedTube"));
}

}  // namespace adsd::shapes
