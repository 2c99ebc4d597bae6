#include "adsd/mesh_hierarchy.h"

#include <algorithm>
#include <numeric>

namespace adsd {

MeshHierarchy::MeshHierarchy(const Mesh& mesh) {
  order_.resize(mesh.triangleCount());
  std::iota(order_.begin(), order_.end(), 0u);
  nodes_.reserve(2 * (mesh.triangleCount() / kLeafTriangles + 1));
  std::vector<std::uint32_t> marks(mesh.vertices().size(), UINT32_MAX);
  build(mesh, 0, static_cast<std::uint32_t>(mesh.triangleCount()), marks);
}

std::int32_t MeshHierarchy::build(const Mesh& mesh, std::uint32_t t0, std::uint32_t t1,
                                  std::vector<std::uint32_t>& marks) {
  const std::int32_t index = static_cast<std::int32_t>(nodes_.size());
  nodes_.emplace_back();
  Node node;
  node.t0 = t0;
  node.t1 = t1;
  Eigen::AlignedBox3d centroids;
  for (std::uint32_t i = t0; i < t1; ++i) {
    const std::uint32_t t = order_[i];
    for (int k = 0; k < 3; ++k) node.box.extend(mesh.corner(t, k));
    centroids.extend(mesh.corner(t, 0) + mesh.corner(t, 1) + mesh.corner(t, 2));
  }
  if (t1 - t0 <= kLeafTriangles) {
    node.v0 = static_cast<std::uint32_t>(leafVertices_.size());
    for (std::uint32_t i = t0; i < t1; ++i) {
      for (std::uint32_t v : mesh.triangles()[order_[i]]) {
        if (marks[v] != static_cast<std::uint32_t>(index)) {
          marks[v] = static_cast<std::uint32_t>(index);
          leafVertices_.push_back(v);
        }
      }
    }
    node.v1 = static_cast<std::uint32_t>(leafVertices_.size());
    nodes_[index] = node;
    return index;
  }
  int axis = 0;
  centroids.sizes().maxCoeff(&axis);
  const std::uint32_t mid = t0 + (t1 - t0) / 2;
  std::nth_element(order_.begin() + t0, order_.begin() + mid, order_.begin() + t1, [&](std::uint32_t s, std::uint32_t t) {
    return mesh.corner(s, 0)[axis] + mesh.corner(s, 1)[axis] + mesh.corner(s, 2)[axis] <
           mesh.corner(t, 0)[axis] + mesh.corner(t, 1)[axis] + mesh.corner(t, 2)[axis];
  });
  node.left = build(mesh, t0, mid, marks);
  node.right = build(mesh, mid, t1, marks);
  nodes_[index] = node;
  return index;
}

void MeshHierarchy::refit(const Mesh& mesh) {
  // Children come after their parent in nodes_, so a backward sweep sees children first.
  for (std::size_t i = nodes_.size(); i-- > 0;) {
    Node& n = nodes_[i];
    n.box.setEmpty();
    if (n.isLeaf()) {
      for (std::uint32_t k = n.v0; k < n.v1; ++k) n.box.extend(mesh.vertices()[leafVertices_[k]]);
    } else {
      n.box = nodes_[n.left].box.merged(nodes_[n.right].box);
    }
  }
}

std::size_t MeshHierarchy::bytes() const {
  return sizeof(*this) + nodes_.capacity() * sizeof(Node) + order_.capacity() * sizeof(std::uint32_t) +
         leafVertices_.capacity() * sizeof(std::uint32_t);
}

}  // namespace adsd
