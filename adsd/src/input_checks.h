#pragma once
/// \file
/// \brief What distance() checks of its poses and meshes on entry, so that it never answers a
/// question it cannot answer exactly (a scaled or sheared pose, an overflowing translation, a
/// scene so small that products of its lengths underflow).

#include "adsd/mesh.h"

namespace adsd::detail {

/// \brief Throws InputError "distance query: pose of mesh A|B ..." unless \p pose is finite, rigid
/// (rotation orthonormal within tolerance::kPoseOrthonormality, bottom row exactly 0 0 0 1) and
/// its translation within +-tolerance::kMaxCoordinate. \p which is "A" or "B".
void requireRigidPose(const Pose& pose, const char* which);

/// \brief Throws InputError "distance query: mesh '...' has no triangles" for a Mesh moved from
/// (a Mesh is otherwise never without triangles).
void requireTriangles(const Mesh& mesh);

/// \brief Throws InputError "distance query: the scene ..." when the meshes, as posed, span less
/// than tolerance::kMinSceneMagnitude (but more than nothing: meshes that are points at one place
/// are 0 apart, exactly), measured as the meshes' largest coordinates plus the poses' offset.
void requireResolvableScene(const Mesh& a, const Pose& poseA, const Mesh& b, const Pose& poseB);

}  // namespace adsd::detail
