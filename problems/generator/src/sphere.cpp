#include <cmath>

#include "adsd/shapes.h"
#include "ring_sweep.h"

namespace adsd::shapes {

Mesh sphere(double radius, int segments) {
  detail::requirePositive("sphere", "radius", radius);
  detail::requireAtLeast("sphere", "segments", segments, 4);
  // Latitude rings between the poles: segments/2 bands from pole to pole, the two bands touching
  // a pole closed by fans to the pole vertex.
  const int bands = segments / 2;
  std::vector<std::vector<Vec3>> rings;
  for (int i = 1; i < bands; ++i) {
    const double polar = M_PI * i / bands;
    std::vector<Vec3> ring;
    for (int k = 0; k < segments; ++k) {
      const double azimuth = 2.0 * M_PI * k / segments;
      ring.emplace_back(radius * std::sin(polar) * std::cos(azimuth),
                        radius * std::sin(polar) * std::sin(azimuth), radius * std::cos(polar));
    }
    rings.push_back(std::move(ring));
  }
  return detail::orientOutward(detail::sweepRings(rings, false, {Vec3(0, 0, radius)},
                                                  {Vec3(0, 0, -radius)}, "sphere"));
}

}  // namespace adsd::shapes
