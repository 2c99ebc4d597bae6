#pragma once
/// \file
/// \brief An arm scene's primitive obstacles taken as solids: a link inside one is in collision,
/// as MoveIt has it, though no two surfaces meet.
///
/// The core measures between surfaces (docs/limitations.md): a robot link wholly inside a box
/// obstacle is as far from it as from its walls. MoveIt's primitives (boxes, cylinders, spheres)
/// are solids (FCL's shapes), its mesh objects surfaces (FCL's triangle trees), and so they are
/// here. Inside a primitive's mesh (closed, convex) is decided by its faces' planes. A connected
/// link mesh whose surface meets no obstacle's lies wholly inside or wholly outside each solid, so
/// one vertex of each of its connected components decides.

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "adsd/mesh.h"

namespace adsd::planner {

/// \brief A closed convex obstacle: the planes of its faces and its box, world frame.
struct ConvexSolid {
  std::string name;  ///< the object it belongs to (its mesh's name)
  Eigen::AlignedBox3d box;
  /// One per face with an area: unit normal n pointing out, offset d; inside where n.x < d.
  std::vector<Eigen::Vector4d> planes;
  /// \brief Whether \p p lies inside by more than \p slack from every face (on the surface, the
  /// distance query answers).
  bool containsStrictly(const Vec3& p, double slack) const;
};

/// \brief \p mesh as a solid, named after it, when it bounds one: closed and convex
/// (adsd::isClosedConvex, so at most MeshHierarchy::kConvexCheckVertices vertices, as every
/// primitive_meshes.h mesh is), and not flat (a face given in both windings is closed and convex
/// too, and holds nothing). Else nothing.
std::optional<ConvexSolid> convexSolidOf(const Mesh& mesh);

/// \brief One vertex of each connected component of \p mesh (a vertex of its first triangle).
std::vector<Vec3> vertexPerComponent(const Mesh& mesh);

}  // namespace adsd::planner
