#pragma once
// Internal: a mesh's connected components, for the planner's scene code (the broad phase's parts,
// a link's one point per component). Not installed.

#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

#include "adsd/mesh.h"

namespace adsd::planner {

/// \brief The triangles of each connected component of \p mesh (triangles sharing a vertex index,
/// transitively), components in order of first appearance, triangles in index order.
inline std::vector<std::vector<std::size_t>> connectedComponents(const Mesh& mesh) {
  // Union-find over vertices: the corners of a triangle belong together.
  std::vector<std::uint32_t> parent(mesh.vertices().size());
  std::iota(parent.begin(), parent.end(), 0u);
  const auto root = [&parent](std::uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const TriangleIndices& t : mesh.triangles()) {
    for (int k = 1; k < 3; ++k) parent[root(t[k])] = root(t[0]);
  }
  std::vector<std::int64_t> componentOfRoot(parent.size(), -1);
  std::vector<std::vector<std::size_t>> components;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const std::uint32_t r = root(mesh.triangles()[t][0]);
    if (componentOfRoot[r] < 0) {
      componentOfRoot[r] = static_cast<std::int64_t>(components.size());
      components.emplace_back();
    }
    components[static_cast<std::size_t>(componentOfRoot[r])].push_back(t);
  }
  return components;
}

}  // namespace adsd::planner
