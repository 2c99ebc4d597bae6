#include "adsd/shapes.h"

#include "adsd/error.h"

namespace adsd::shapes {

Mesh merge(const std::vector<Mesh>& parts, const std::vector<Pose>& poses) {
  if (parts.empty()) throw InputError("shapes::merge: no parts given");
  if (!poses.empty() && poses.size() != parts.size()) {
    throw InputError("shapes::merge: " + std::to_string(parts.size()) + " parts but " +
                     std::to_string(poses.size()) + " poses (give one per part, or none)");
  }
  std::vector<Vec3> vertices;
  std::vector<TriangleIndices> triangles;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const Pose pose = poses.empty() ? Pose::Identity() : poses[i];
    const auto offset = static_cast<std::uint32_t>(vertices.size());
    for (const Vec3& v : parts[i].vertices()) vertices.push_back(pose * v);
    for (const TriangleIndices& t : parts[i].triangles()) {
      triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    }
  }
  return Mesh(std::move(vertices), std::move(triangles), "merged");
}

}  // namespace adsd::shapes
