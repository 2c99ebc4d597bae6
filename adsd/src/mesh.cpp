#include "adsd/mesh.h"

#include <algorithm>
#include <cmath>

#include "adsd/error.h"
#include "adsd/mesh_hierarchy.h"

namespace adsd {

namespace {

void requireFinite(const std::vector<Vec3>& vertices, const std::string& name) {
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    if (!vertices[i].allFinite()) {
      throw InputError(name + ": vertex " + std::to_string(i) + " has a non-finite coordinate");
    }
  }
}

}  // namespace

Mesh::Mesh(std::vector<Vec3> vertices, std::vector<TriangleIndices> triangles, std::string name)
    : vertices_(std::move(vertices)), triangles_(std::move(triangles)), name_(std::move(name)) {
  if (triangles_.empty()) throw InputError(name_ + ": the mesh has no triangles");
  if (triangles_.size() > UINT32_MAX) throw InputError(name_ + ": more than 2^32 - 1 triangles");
  requireFinite(vertices_, name_);
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      if (triangles_[t][k] >= vertices_.size()) {
        throw InputError(name_ + ": triangle " + std::to_string(t) + " refers to vertex " +
                         std::to_string(triangles_[t][k]) + " but there are only " +
                         std::to_string(vertices_.size()) + " vertices");
      }
    }
  }
  std::vector<bool> used(vertices_.size(), false);
  for (const TriangleIndices& t : triangles_) {
    for (std::uint32_t v : t) used[v] = true;
  }
  allVerticesReferenced_ = std::find(used.begin(), used.end(), false) == used.end();
  refreshVertexFacts();
}

void Mesh::refreshVertexFacts() {
  maxAbsCoordinate_ = 0.0;
  for (const Vec3& v : vertices_) maxAbsCoordinate_ = std::max(maxAbsCoordinate_, v.cwiseAbs().maxCoeff());
}

void Mesh::setVertices(const std::vector<Vec3>& vertices) {
  if (vertices.size() != vertices_.size()) {
    throw InputError(name_ + ": setVertices got " + std::to_string(vertices.size()) +
                     " vertices, the mesh has " + std::to_string(vertices_.size()));
  }
  requireFinite(vertices, name_);
  vertices_ = vertices;
  refreshVertexFacts();
  if (hierarchy_) {
    auto refitted = std::make_shared<MeshHierarchy>(*hierarchy_);
    refitted->refit(*this);
    hierarchy_ = std::move(refitted);
  }
}

void Mesh::buildHierarchy() { hierarchy_ = std::make_shared<const MeshHierarchy>(*this); }

Eigen::AlignedBox3d Mesh::bounds() const {
  Eigen::AlignedBox3d box;
  for (const TriangleIndices& t : triangles_) {
    for (std::uint32_t v : t) box.extend(vertices_[v]);
  }
  return box;
}

}  // namespace adsd
