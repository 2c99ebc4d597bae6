#include "input_checks.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "adsd/error.h"
#include "adsd/tolerances.h"

namespace adsd::detail {

namespace {

/// The checks of requireRigidPose in the fewest operations, for the common case where they all
/// pass: this runs twice on every query, and a validity query decided at the roots' spheres
/// costs a few hundred nanoseconds in all. Finiteness is checked first and on its own: std::max
/// may pass over a NaN (InputBoundary.NonRigidPosesAreRefused has a NaN the maxima below missed).
/// When this is false, requireRigidPose finds which check failed.
bool isRigidFast(const Eigen::Matrix4d& m) {
  if (!m.allFinite()) return false;
  if (m(3, 0) != 0.0 || m(3, 1) != 0.0 || m(3, 2) != 0.0 || m(3, 3) != 1.0) return false;
  const Eigen::Vector3d c0 = m.block<3, 1>(0, 0), c1 = m.block<3, 1>(0, 1), c2 = m.block<3, 1>(0, 2);
  // R^T R - I, entry by entry: the columns' squared lengths less 1 and their dot products.
  const double deviation = std::max({std::abs(c0.squaredNorm() - 1.0), std::abs(c1.squaredNorm() - 1.0),
                                     std::abs(c2.squaredNorm() - 1.0), std::abs(c0.dot(c1)), std::abs(c0.dot(c2)),
                                     std::abs(c1.dot(c2))});
  const double reach = std::max({std::abs(m(0, 3)), std::abs(m(1, 3)), std::abs(m(2, 3))});
  return deviation <= tolerance::kPoseOrthonormality && reach <= tolerance::kMaxCoordinate;
}

}  // namespace

void requireRigidPose(const Pose& pose, const char* which) {
  if (isRigidFast(pose.matrix())) return;
  // Something failed: the checks again, one by one, for the message that names it.
  const auto what = [which] { return std::string("distance query: pose of mesh ") + which; };
  const Eigen::Matrix4d& m = pose.matrix();
  if (!m.allFinite()) throw InputError(what() + " has a non-finite entry");
  // Eigen keeps an Isometry3d's bottom row exact through products and inverses; anything else
  // came from writing matrix() directly, and a projective pose is not a placement of a mesh.
  if (m.row(3) != Eigen::RowVector4d(0, 0, 0, 1)) {
    std::ostringstream out;
    out << what() << " has bottom row (" << m.row(3) << "), not (0 0 0 1): not a rigid motion";
    throw InputError(out.str());
  }
  // The core places B in A's frame by undoing A's rotation: a pose that is no rotation has no
  // distance to keep.
  const Eigen::Matrix3d r = m.topLeftCorner<3, 3>();
  const double deviation = (r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (!(deviation <= tolerance::kPoseOrthonormality)) {
    std::ostringstream out;
    out.precision(3);
    out << what() << " is not rigid: its rotation part R has |R^T R - I| up to " << deviation << " (allowed "
        << tolerance::kPoseOrthonormality << "); a scale or shear is not supported, and a rotation "
        << "must be orthonormal to double precision (build it from a unit quaternion)";
    throw InputError(out.str());
  }
  const double reach = m.topRightCorner<3, 1>().cwiseAbs().maxCoeff();
  if (reach > tolerance::kMaxCoordinate) {
    std::ostringstream out;
    out.precision(3);
    out << what() << " has a translation entry of " << reach << ", beyond +-" << tolerance::kMaxCoordinate
        << ", where the distance computation's squared lengths would overflow";
    throw InputError(out.str());
  }
}

void requireTriangles(const Mesh& mesh) {
  // A Mesh is built with triangles or refused; only one moved from has none, and a query on it
  // read past its empty arrays (an outside review: a segmentation fault).
  if (mesh.triangleCount() == 0) {
    throw InputError("distance query: mesh '" + mesh.name() + "' has no triangles (a Mesh moved from?)");
  }
}

void requireResolvableScene(const Mesh& a, const Pose& poseA, const Mesh& b, const Pose& poseB) {
  const double extent = a.maxAbsCoordinate() + b.maxAbsCoordinate() +
                        (poseA.translation() - poseB.translation()).cwiseAbs().maxCoeff();
  if (extent > 0.0 && extent < tolerance::kMinSceneMagnitude) {
    std::ostringstream out;
    out.precision(3);
    out << "distance query: the scene of meshes '" << a.name() << "' and '" << b.name() << "' spans only " << extent
        << " (below " << tolerance::kMinSceneMagnitude << "), where products of its lengths underflow; "
        << "scale the meshes up (the distance scales with them)";
    throw InputError(out.str());
  }
}

}  // namespace adsd::detail
