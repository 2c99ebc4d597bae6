#pragma once
/// \file
/// \brief A triangle mesh in its own frame: vertex positions and index triples, nothing else.

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace adsd {

class MeshHierarchy;

/// The one vector type of the core (STYLE habit 9).
using Vec3 = Eigen::Vector3d;
/// A rigid pose: maps mesh (body-frame) coordinates to world coordinates, p_world = pose * p_mesh.
using Pose = Eigen::Isometry3d;
/// Three vertex indices into Mesh::vertices(); any orientation, any winding.
using TriangleIndices = std::array<std::uint32_t, 3>;

/// \brief A triangle soup with shared vertices: open or closed, convex or not, manifold or not.
///
/// The mesh is validated once on construction (finite coordinates within +-tolerance::kMaxCoordinate,
/// 1e75, beyond which the core's squared lengths would overflow; indices in range; at least one
/// triangle) and then only read by queries, so any number of threads may query it at once.
/// Zero-area triangles and repeated vertices are valid. No acceleration structure is built: the
/// paper's algorithm needs none (sec. 1), which is what makes deforming meshes cheap.
class Mesh {
 public:
  /// \brief Takes the vertices and triangles; throws InputError naming the first bad vertex or
  /// triangle. \p name appears in those messages (a file name, say).
  Mesh(std::vector<Vec3> vertices, std::vector<TriangleIndices> triangles, std::string name = "mesh");

  /// \brief Deforming meshes: new positions for the same vertices (same count, same triangles).
  /// Not thread-safe against concurrent queries of this mesh. Throws InputError on a non-finite
  /// coordinate, one beyond +-tolerance::kMaxCoordinate, or a count mismatch, leaving the mesh unchanged. A hierarchy, if built, is refit.
  void setVertices(const std::vector<Vec3>& vertices);

  /// \brief Rigid meshes queried many times: builds the sub-mesh tree that queries then reuse
  /// (adsd/mesh_hierarchy.h). Queries between two meshes that both have one use it; otherwise
  /// they run the paper's adaptive decomposition from scratch. Not thread-safe against concurrent
  /// queries of this mesh; call it before sharing the mesh.
  void buildHierarchy();
  /// \brief The tree, or null when none was built.
  const MeshHierarchy* hierarchy() const { return hierarchy_.get(); }

  const std::vector<Vec3>& vertices() const { return vertices_; }
  const std::vector<TriangleIndices>& triangles() const { return triangles_; }
  std::size_t triangleCount() const { return triangles_.size(); }
  const std::string& name() const { return name_; }

  /// \brief Corner k (0..2) of triangle t, in the mesh frame.
  const Vec3& corner(std::size_t t, int k) const { return vertices_[triangles_[t][static_cast<std::size_t>(k)]]; }

  /// \brief Axis-aligned bounds of the vertices referenced by triangles, in the mesh frame.
  Eigen::AlignedBox3d bounds() const;

  /// \brief Largest |coordinate| of the vertices referenced by triangles (mesh frame): the
  /// magnitude that scales roundoff. A vertex no triangle uses plays no part in any query.
  double maxAbsCoordinate() const { return maxAbsCoordinate_; }
  /// \brief The length of bounds()' diagonal, kept: queries scale their tie slack by it
  /// (tolerance::kTieSlack); at most sqrt(3) times the diagonal of a scene holding the mesh.
  double diagonal() const { return diagonal_; }
  /// \brief Whether every vertex belongs to some triangle, so that a support mapping over the
  /// whole mesh may scan the vertex array (each vertex once) instead of the triangles' corners.
  bool allVerticesReferenced() const { return allVerticesReferenced_; }

 private:
  void refreshVertexFacts();

  std::vector<Vec3> vertices_;
  std::vector<TriangleIndices> triangles_;
  std::string name_;
  double maxAbsCoordinate_ = 0.0;
  double diagonal_ = 0.0;
  bool allVerticesReferenced_ = false;
  // Shared between copies of a mesh (it is immutable); setVertices gives the mesh its own.
  std::shared_ptr<const MeshHierarchy> hierarchy_;
};

}  // namespace adsd
