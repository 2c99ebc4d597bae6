#include <algorithm>
#include <cmath>

#include "adsd/error.h"
#include "adsd/shapes.h"
#include "ring_sweep.h"

namespace adsd::shapes {

Mesh capsule(double radius, double halfLength, int segments) {
  detail::requirePositive("capsule", "radius", radius);
  if (!(std::isfinite(halfLength) && halfLength >= 0.0)) {
    throw InputError("shapes::capsule: halfLength must be finite and >= 0, got " + std::to_string(halfLength));
  }
  detail::requireAtLeast("capsule", "segments", segments, 4);
  // Each hemisphere gets a quarter of the azimuthal resolution in latitude bands, so the facets
  // stay roughly square; the cylinder between the two equators is one band.
  const int capBands = std::max(2, segments / 4);
  std::vector<std::vector<Vec3>> rings;
  auto addRing = [&](double z, double ringRadius) {
    std::vector<Vec3> ring;
    for (int k = 0; k < segments; ++k) {
      const double azimuth = 2.0 * M_PI * k / segments;
      ring.emplace_back(ringRadius * std::cos(azimuth), ringRadius * std::sin(azimuth), z);
    }
    rings.push_back(std::move(ring));
  };
  for (int i = 1; i <= capBands; ++i) {  // top cap, from near the north pole to the equator
    const double polar = 0.5 * M_PI * i / capBands;
    addRing(halfLength + radius * std::cos(polar), radius * std::sin(polar));
  }
  // A zero half length makes the two equators coincide: keep one, or the cylinder band would be
  // a ring of zero-area triangles.
  for (int i = halfLength > 0.0 ? 0 : 1; i < capBands; ++i) {  // bottom cap, equator to south pole
    const double polar = 0.5 * M_PI + 0.5 * M_PI * i / capBands;
    addRing(-halfLength + radius * std::cos(polar), radius * std::sin(polar));
  }
  return detail::orientOutward(detail::sweepRings(rings, false, {Vec3(0, 0, halfLength + radius)},
                                                  {Vec3(0, 0, -halfLength - radius)}, "capsule"));
}

}  // namespace adsd::shapes
