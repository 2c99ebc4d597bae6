#pragma once
/// \file
/// \brief Solid primitives (box, sphere, cylinder) as triangle meshes of a stated resolution that
/// contain the primitive: a pose found free against the mesh is free against the primitive.
///
/// Each mesh is in the primitive's own frame as MoveIt (shape_msgs/SolidPrimitive) and URDF define
/// it: centred at the origin, a cylinder's axis along z. Sizes are checked by the caller.

#include "adsd/mesh.h"

namespace adsd::planner {

/// Sides of a cylinder's prism (and the sphere's segments around its axis). With n sides the mesh
/// reaches out at most r (1 / cos(pi / n) - 1) beyond the surface: 0.48 % of the radius at 32,
/// 0.5 mm on a 10 cm cylinder. Chosen as the resolution at which that excess stays under a
/// millimetre for the objects of our scenes (radii up to 0.2 m) at 64 triangles a side wall.
constexpr int kPrimitiveSegments = 32;
/// Latitude bands of a sphere from pole to pole (each band spans pi / 16 of latitude).
constexpr int kSphereBands = 16;

/// \brief A box of side lengths \p size (x, y, z): 8 vertices, 12 triangles, exact.
Mesh boxMesh(const Vec3& size, const std::string& name);

/// \brief A cylinder of \p height along z and \p radius: a prism of kPrimitiveSegments sides
/// circumscribed about the cylinder (each side tangent to it), caps at z = +-height/2.
Mesh cylinderMesh(double height, double radius, const std::string& name);

/// \brief A sphere of \p radius: a UV sphere (kPrimitiveSegments around, kSphereBands from pole to
/// pole) scaled by 1 / (cos(pi / segments) cos(pi / (2 bands))) so that every face lies at least
/// \p radius from the centre (the polyhedron contains the ball; tests/arm_problems checks each
/// face's plane). It reaches out at most 1.7 % of the radius beyond the sphere.
Mesh sphereMesh(double radius, const std::string& name);

}  // namespace adsd::planner
