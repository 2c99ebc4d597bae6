#pragma once
/// \file
/// \brief URDF's box, cylinder and sphere primitives as triangle meshes of a stated resolution,
/// each containing the primitive (so a distance to the mesh never exceeds the distance to it).

#include <string>

#include "adsd/mesh.h"

namespace adsd::planner {

/// \brief Segments around the circle of a cylinder primitive (count). The polygon is
/// circumscribed (its edges touch the circle), so the mesh contains the cylinder and a distance
/// from it is never larger than the true primitive's; it is smaller by at most
/// r (1 / cos(pi / 32) - 1) = 0.0048 r.
inline constexpr int kCylinderSegments = 32;
/// Segments around a sphere primitive's equator (count) and rings from pole to pole (count): a
/// latitude-longitude sphere, scaled so that every triangle's plane is at least r from the centre:
/// the mesh contains the sphere, and its distances are at most 1 % of r below the sphere's
/// (sphereMesh, tests/arm).
inline constexpr int kSphereSegments = 32;
inline constexpr int kSphereRings = 16;

/// \brief Box of the given full sizes (metres), centred on the origin: 8 vertices, 12 triangles.
Mesh boxMesh(const Vec3& size, const std::string& name = "box");
/// \brief Cylinder of radius \p radius along z from -length/2 to +length/2, circumscribed with
/// kCylinderSegments sides.
Mesh cylinderMesh(double radius, double length, const std::string& name = "cylinder");
/// \brief Sphere of radius \p radius centred on the origin, containing it (kSphereSegments,
/// kSphereRings).
Mesh sphereMesh(double radius, const std::string& name = "sphere");

}  // namespace adsd::planner
