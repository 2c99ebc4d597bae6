#include "input_checks.h"

#include <sstream>
#include <string>

#include "adsd/error.h"
#include "adsd/tolerances.h"

namespace adsd::detail {

void requireRigidPose(const Pose& pose, const char* which) {
  const std::string what = std::string("distance query: pose of mesh ") + which;
  const Eigen::Matrix4d& m = pose.matrix();
  if (!m.allFinite()) throw InputError(what + " has a non-finite entry");
  // Eigen keeps an Isometry3d's bottom row exact through products and inverses; anything else
  // came from writing matrix() directly, and a projective pose is not a placement of a mesh.
  if (m.row(3) != Eigen::RowVector4d(0, 0, 0, 1)) {
    std::ostringstream out;
    out << what << " has bottom row (" << m.row(3) << "), not (0 0 0 1): not a rigid motion";
    throw InputError(out.str());
  }
  // The core undoes a rotation by its transpose (query.h, frames): only right when R^T R = I.
  const Eigen::Matrix3d r = m.topLeftCorner<3, 3>();
  const double deviation = (r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (!(deviation <= tolerance::kPoseOrthonormality)) {
    std::ostringstream out;
    out.precision(3);
    out << what << " is not rigid: its rotation part R has |R^T R - I| up to " << deviation << " (allowed "
        << tolerance::kPoseOrthonormality << "); a scale or shear is not supported, and a rotation "
        << "must be orthonormal to double precision (build it from a unit quaternion)";
    throw InputError(out.str());
  }
  const double reach = m.topRightCorner<3, 1>().cwiseAbs().maxCoeff();
  if (reach > tolerance::kMaxCoordinate) {
    std::ostringstream out;
    out.precision(3);
    out << what << " has a translation entry of " << reach << ", beyond +-" << tolerance::kMaxCoordinate
        << ", where the distance computation's squared lengths would overflow";
    throw InputError(out.str());
  }
}

}  // namespace adsd::detail
