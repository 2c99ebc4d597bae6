#include "adsd/mesh.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <utility>

#include "adsd/error.h"
#include "adsd/mesh_hierarchy.h"
#include "adsd/tolerances.h"

namespace adsd {

namespace {

/// Finite, and within tolerance::kMaxCoordinate: beyond it the core's squared quantities overflow
/// and a query would answer inf with status exact (tolerances.h says why that bound).
void requireRepresentable(const std::vector<Vec3>& vertices, const std::string& name) {
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const Vec3& v = vertices[i];
    if (!v.allFinite()) throw InputError(name + ": vertex " + std::to_string(i) + " has a non-finite coordinate");
    Eigen::Index axis = 0;
    if (v.cwiseAbs().maxCoeff(&axis) > tolerance::kMaxCoordinate) {
      // Shortest text that reads back as the same double: the coordinate as the user wrote it.
      char text[32];
      const std::string coordinate(text, std::to_chars(text, text + sizeof text, v(axis)).ptr);
      std::ostringstream what;
      what << name << ": vertex " << i << " has coordinate " << "xyz"[axis] << " = " << coordinate << ", beyond +-"
           << std::setprecision(3) << tolerance::kMaxCoordinate
           << ", where the distance computation's squared lengths would overflow";
      throw InputError(what.str());
    }
  }
}

}  // namespace

Mesh::Mesh(std::vector<Vec3> vertices, std::vector<TriangleIndices> triangles, std::string name)
    : vertices_(std::move(vertices)), triangles_(std::move(triangles)), name_(std::move(name)) {
  if (triangles_.empty()) throw InputError(name_ + ": the mesh has no triangles");
  if (triangles_.size() > UINT32_MAX) throw InputError(name_ + ": more than 2^32 - 1 triangles");
  requireRepresentable(vertices_, name_);
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
  // Over the vertices the triangles use, as every query's work is: the magnitude scales the
  // roundoff allowance, and one stray vertex no triangle uses, at 1e30 (a deleted vertex's
  // marker), made it swamp a unit-sized scene's distance (exact answers 2-4 times the true one,
  // a false "beyond the cap"), and let a scene too small to resolve past its refusal.
  const Eigen::AlignedBox3d box = bounds();
  maxAbsCoordinate_ = std::max(box.min().cwiseAbs().maxCoeff(), box.max().cwiseAbs().maxCoeff());
  diagonal_ = box.diagonal().norm();
}

void Mesh::setVertices(const std::vector<Vec3>& vertices) {
  if (vertices.size() != vertices_.size()) {
    throw InputError(name_ + ": setVertices got " + std::to_string(vertices.size()) +
                     " vertices, the mesh has " + std::to_string(vertices_.size()));
  }
  requireRepresentable(vertices, name_);
  // The old positions come back if the refit fails (it allocates): new vertices under the old
  // tree's boxes would be answered wrongly, without a word.
  std::vector<Vec3> previous = std::exchange(vertices_, vertices);
  refreshVertexFacts();
  if (hierarchy_) {
    try {
      auto refitted = std::make_shared<MeshHierarchy>(*hierarchy_);
      refitted->refit(*this);
      hierarchy_ = std::move(refitted);
    } catch (...) {
      vertices_ = std::move(previous);
      refreshVertexFacts();
      throw;
    }
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
