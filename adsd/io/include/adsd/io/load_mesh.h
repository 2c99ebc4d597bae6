#pragma once
/// \file
/// \brief Reading meshes from files through assimp (OBJ, STL, PLY, OFF, COLLADA, ...).

#include <string>

#include "adsd/mesh.h"

namespace adsd::io {

/// \brief Loads every triangle of the file as one mesh.
///
/// Assimp triangulates polygons and joins identical vertices; each scene node's transform is
/// applied (so the mesh is in the file's root frame; a mesh used by several nodes appears once per
/// node); line and point primitives are dropped. COLLADA <unit> and <up_axis> are applied as
/// assimp does by default, as OMPL.app's loading does. Zero-area triangles are kept.
///
/// Throws adsd::InputError, one line starting with the path (and ":LINE" where a line is known),
/// for: a missing, unreadable, empty or non-regular file; a truncated binary STL or PLY; a file
/// assimp cannot parse; a scene with no triangles (only lines or points, say); a vertex index out
/// of range; a non-finite coordinate. OFF and PLY files are checked line by line first, because
/// assimp 5.2 hangs on, aborts on, or silently repairs some malformed ones (see src/*_check.cpp).
/// Running out of memory is reported the same way.
Mesh loadMesh(const std::string& path);

}  // namespace adsd::io
