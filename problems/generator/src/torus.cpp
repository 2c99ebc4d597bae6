#include <cmath>

#include "adsd/shapes.h"
#include "ring_sweep.h"

namespace adsd::shapes {

Mesh torus(double ringRadius, double tubeRadius, int ringSegments, int tubeSegments) {
  detail::requirePositive("torus", "ringRadius", ringRadius);
  detail::requirePositive("torus", "tubeRadius", tubeRadius);
  if (tubeRadius >= ringRadius) {
    detail::requirePositive("torus", "ringRadius - tubeRadius (the hole)", ringRadius - tubeRadius);
  }
  detail::requireAtLeast("torus", "ringSegments", ringSegments, 3);
  detail::requireAtLeast("torus", "tubeSegments", tubeSegments, 3);
  std::vector<std::vector<Vec3>> rings;
  for (int i = 0; i < ringSegments; ++i) {
    const double around = 2.0 * M_PI * i / ringSegments;
    const Vec3 radial(std::cos(around), std::sin(around), 0.0);
    std::vector<Vec3> ring;
    for (int k = 0; k < tubeSegments; ++k) {
      const double tube = 2.0 * M_PI * k / tubeSegments;
      ring.push_back((ringRadius + tubeRadius * std::cos(tube)) * radial +
                     Vec3(0, 0, tubeRadius * std::sin(tube)));
    }
    rings.push_back(std::move(ring));
  }
  return detail::orientOutward(detail::sweepRings(rings, true, {}, {}, "torus"));
}

}  // namespace adsd::shapes
