#include "ring_sweep.h"

#include <cmath>
#include <cstdint>

#include "adsd/error.h"

namespace adsd::shapes::detail {

Mesh sweepRings(const std::vector<std::vector<Vec3>>& rings, bool closedLoop, const RingCap& first,
                const RingCap& last, const std::string& name) {
  const std::size_t ringCount = rings.size();
  const std::size_t perRing = rings.front().size();
  std::vector<Vec3> vertices;
  vertices.reserve(ringCount * perRing + 2);
  for (const auto& ring : rings) vertices.insert(vertices.end(), ring.begin(), ring.end());
  auto at = [perRing](std::size_t ring, std::size_t k) {
    return static_cast<std::uint32_t>(ring * perRing + k % perRing);
  };

  std::vector<TriangleIndices> triangles;
  const std::size_t bands = closedLoop ? ringCount : ringCount - 1;
  for (std::size_t i = 0; i < bands; ++i) {
    const std::size_t next = (i + 1) % ringCount;
    for (std::size_t k = 0; k < perRing; ++k) {
      // The quad (i,k) (i,k+1) (next,k+1) (next,k), split along its diagonal. Every ring edge
      // k -> k+1 is walked forwards by the band after it and backwards by the band before it,
      // which is what makes the winding consistent across bands.
      triangles.push_back({at(i, k), at(i, k + 1), at(next, k + 1)});
      triangles.push_back({at(i, k), at(next, k + 1), at(next, k)});
    }
  }
  if (!closedLoop) {
    // The first ring's edges are walked k -> k+1 by the first band, so its fan walks them back;
    // the last ring's edges are walked k+1 -> k by the last band, so its fan walks them forwards.
    if (first.apex) {
      const auto apex = static_cast<std::uint32_t>(vertices.size());
      vertices.push_back(*first.apex);
      for (std::size_t k = 0; k < perRing; ++k) triangles.push_back({apex, at(0, k + 1), at(0, k)});
    }
    if (last.apex) {
      const auto apex = static_cast<std::uint32_t>(vertices.size());
      vertices.push_back(*last.apex);
      const std::size_t end = ringCount - 1;
      for (std::size_t k = 0; k < perRing; ++k) triangles.push_back({apex, at(end, k), at(end, k + 1)});
    }
  }
  return Mesh(std::move(vertices), std::move(triangles), name);
}

double signedVolume(const Mesh& mesh) {
  double sixTimesVolume = 0.0;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    sixTimesVolume += mesh.corner(t, 0).dot(mesh.corner(t, 1).cross(mesh.corner(t, 2)));
  }
  return sixTimesVolume / 6.0;
}

Mesh orientOutward(Mesh mesh) {
  if (signedVolume(mesh) >= 0.0) return mesh;
  std::vector<TriangleIndices> flipped = mesh.triangles();
  for (TriangleIndices& t : flipped) std::swap(t[1], t[2]);
  return Mesh(mesh.vertices(), std::move(flipped), mesh.name());
}

void requirePositive(const char* shape, const char* field, double value) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw InputError(std::string("shapes::") + shape + ": " + field + " must be finite and > 0, got " +
                     std::to_string(value));
  }
}

void requireAtLeast(const char* shape, const char* field, int value, int minimum) {
  if (value < minimum) {
    throw InputError(std::string("shapes::") + shape + ": " + field + " must be >= " +
                     std::to_string(minimum) + ", got " + std::to_string(value));
  }
}

}  // namespace adsd::shapes::detail
