#pragma once
/// \file
/// \brief Closed convex obstacles taken as solids: a link inside one is in collision, as MoveIt
/// (FCL's primitives) has it, though no two surfaces meet.
///
/// The core measures between surfaces (docs/limitations.md): a robot link wholly inside a box
/// obstacle is as far from it as from its walls. An arm scene's primitives (boxes, cylinders,
/// spheres) are solids in MoveIt, and so are, here, the closed convex parts of its mesh objects:
/// for them, inside is decided by the faces' planes. A connected link mesh whose surface meets no
/// obstacle's lies wholly inside or wholly outside each solid, so one vertex of each of its
/// connected components decides.

#include <cstdint>
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

/// \brief The connected components of \p mesh (triangles sharing a vertex) that are closed and
/// convex (adsd::isClosedConvex on each), as solids named after the mesh.
std::vector<ConvexSolid> convexSolidsOf(const Mesh& mesh);

/// \brief One vertex of each connected component of \p mesh (a vertex of its first triangle).
std::vector<Vec3> vertexPerComponent(const Mesh& mesh);

}  // namespace adsd::planner
