#include <cmath>

#include "adsd/error.h"
#include "adsd/shapes.h"
#include "ring_sweep.h"

namespace adsd::shapes {

Mesh cShape(double radius, double thickness, double openingAngle, int segments) {
  detail::requirePositive("cShape", "radius", radius);
  detail::requirePositive("cShape", "thickness", thickness);
  if (thickness >= 2.0 * radius) {
    detail::requirePositive("cShape", "2 * radius - thickness (the inner radius)", 2.0 * radius - thickness);
  }
  if (!(openingAngle > 0.0 && openingAngle < 2.0 * M_PI)) {
    throw InputError("shapes::cShape: openingAngle must lie in (0, 2 pi) radians, got " +
                     std::to_string(openingAngle));
  }
  detail::requireAtLeast("cShape", "segments", segments, 1);
  // The arc covers azimuths [opening/2, 2 pi - opening/2]: the gap (the mouth of the C) is centred
  // on the +x axis. The section is a thickness x thickness square centred on the arc of radius
  // `radius` in the xy plane; the two ends are closed by flat fans.
  const double inner = radius - 0.5 * thickness;
  const double outer = radius + 0.5 * thickness;
  const double halfHeight = 0.5 * thickness;
  const double start = 0.5 * openingAngle;
  const double sweep = 2.0 * M_PI - openingAngle;
  std::vector<std::vector<Vec3>> rings;
  for (int i = 0; i <= segments; ++i) {
    const double azimuth = start + sweep * i / segments;
    const Vec3 radial(std::cos(azimuth), std::sin(azimuth), 0.0);
    const Vec3 up(0, 0, 1);
    rings.push_back({inner * radial - halfHeight * up, outer * radial - halfHeight * up,
                     outer * radial + halfHeight * up, inner * radial + halfHeight * up});
  }
  auto centre = [&](double azimuth) { return Vec3(radius * std::cos(azimuth), radius * std::sin(azimuth), 0.0); };
  return detail::orientOutward(
      detail::sweepRings(rings, false, {centre(start)}, {centre(start + sweep)}, "cShape"));
}

}  // namespace adsd::shapes
