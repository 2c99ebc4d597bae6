#pragma once
/// \file
/// \brief Internal: the surface of an axis-aligned box with each face cut into a grid, shared by
/// box() and room().

#include "adsd/mesh.h"

namespace adsd::shapes::detail {

/// \brief Surface of the box [-h, h] with every face cut into divisions x divisions squares
/// (2 triangles each). Vertices on edges and corners are shared between faces, so the surface is
/// closed; triangles are wound counter-clockwise seen from outside (outward normals).
Mesh boxSurface(const Vec3& halfExtents, int divisions, const std::string& name);

}  // namespace adsd::shapes::detail
