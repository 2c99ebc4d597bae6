#pragma once
/// \file
/// \brief What distance() checks of its poses on entry, so that it never answers a question it
/// cannot answer exactly (a scaled or sheared pose, an overflowing translation).

#include "adsd/mesh.h"

namespace adsd::detail {

/// \brief Throws InputError "distance query: pose of mesh A|B ..." unless \p pose is finite, rigid
/// (rotation orthonormal within tolerance::kPoseOrthonormality, bottom row exactly 0 0 0 1) and
/// its translation within +-tolerance::kMaxCoordinate. \p which is "A" or "B".
void requireRigidPose(const Pose& pose, const char* which);

}  // namespace adsd::detail
