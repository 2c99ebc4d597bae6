#pragma once
/// \file
/// \brief An articulated robot read from a URDF file: a tree of links joined by revolute,
/// continuous, prismatic and fixed joints, each link with its collision geometry as one mesh in
/// the link's frame (issue 17).

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "adsd/mesh.h"
#include "adsd/planner/convex_solids.h"

namespace adsd::planner {

/// \brief The joint types an arm may have. Floating and planar joints are refused on reading:
/// their configuration is not one number.
enum class ArmJointType { revolute, continuous, prismatic, fixed };

/// \brief One joint, as URDF defines it: the child link's frame is
///   parentLinkFrame * origin * motion(q),
/// where motion(q) turns by q radians about \p axis (revolute, continuous) or moves q metres
/// along it (prismatic), and is the identity for a fixed joint.
struct ArmJoint {
  std::string name;
  ArmJointType type = ArmJointType::fixed;
  std::size_t parentLink = 0;  ///< index into ArmModel::links
  std::size_t childLink = 0;   ///< index into ArmModel::links
  Pose origin = Pose::Identity();   ///< joint frame in the parent link's frame (URDF <origin>)
  Vec3 axis = Vec3::UnitZ();        ///< unit vector, joint frame (URDF <axis>, normalized)
  double lower = 0.0;  ///< radians or metres; -pi for a continuous joint
  double upper = 0.0;  ///< radians or metres; +pi for a continuous joint
  /// Position of this joint in the joint vector, or -1 for a fixed, a locked and a mimic joint.
  int active = -1;
  /// A revolute or prismatic joint whose limits are equal (lower == upper, a joint a description
  /// locks) stands there always: it is no coordinate of the joint vector (OMPL cannot sample or
  /// interpolate a range of zero width), and this is its position. So is a mimic joint's whose
  /// leader is locked.
  bool locked = false;
  double lockedPosition = 0.0;
  /// A mimic joint (URDF <mimic joint= multiplier= offset=>, a gripper's second finger) is not in
  /// the joint vector: as in MoveIt, its position is
  ///   mimicMultiplier * q[mimicCoordinate] + mimicOffset,
  /// where coordinate mimicCoordinate is the joint it names, or the joint that one follows in
  /// turn (the multipliers and offsets composed). -1 for a joint that is not a mimic joint.
  int mimicCoordinate = -1;
  double mimicMultiplier = 1.0;
  double mimicOffset = 0.0;
  /// The name of the joint its <mimic> names, or empty (for messages).
  std::string mimics;
};

/// \brief Where MoveIt's default state puts \p joint (RevoluteJointModel's and
/// PrismaticJointModel's default positions): 0 where its limits allow, as a continuous joint's
/// always do, else the midpoint of its limits.
double defaultPosition(const ArmJoint& joint);

/// \brief One link: its name, the joint that carries it, and its collision geometry.
struct ArmLink {
  std::string name;
  /// Index into ArmModel::joints of the joint whose child this link is; -1 for the root.
  int parentJoint = -1;
  /// Every <collision> element of the link, merged into one mesh in the link's frame, or none
  /// when the link has no collision geometry (such a link is never checked). Visual geometry is
  /// never used.
  std::optional<Mesh> collision;
  /// The link's primitive <collision> elements (box, cylinder, sphere), each as a solid in the
  /// link's frame: an obstacle or another link wholly inside one is in collision, as it is for
  /// MoveIt, whose FCL shapes are solids (a link's mesh elements are surfaces, there and here).
  std::vector<ConvexSolid> solids;
};

/// \brief An articulated robot.
///
/// Links are stored depth first from the root, children in the order of their joints in the URDF
/// file, so a link's parent always comes before it. joints[k] is the joint whose child is
/// links[k + 1]. The joint vector holds one coordinate per non-fixed joint that is neither locked
/// nor a mimic joint, in that same order (depth first from the root, URDF order among siblings); jointIndex()
/// finds one by name, jointPosition() gives any joint's position from it.
/// Read-only once built, so any number of threads may use it.
struct ArmModel {
  std::string name;        ///< the URDF's robot name
  std::string sourceFile;  ///< the URDF file it was read from (for messages)
  std::vector<ArmLink> links;
  std::vector<ArmJoint> joints;
  /// activeJoints[i]: index into joints of joint-vector coordinate i.
  std::vector<std::size_t> activeJoints;

  std::size_t dof() const { return activeJoints.size(); }
  /// \brief The position of \p joint (radians or metres) at joint vector \p q: its coordinate, a
  /// mimic joint's multiple of its leader's, a locked joint's lockedPosition, 0 for a fixed joint.
  static double jointPosition(const ArmJoint& joint, const double* q) {
    if (joint.active >= 0) return q[joint.active];
    if (joint.mimicCoordinate >= 0) return joint.mimicMultiplier * q[joint.mimicCoordinate] + joint.mimicOffset;
    return joint.lockedPosition;
  }
  /// \brief The positions \p joint takes over the joint vectors within the limits, [low, high]:
  /// its own limits, or for a mimic joint its leader's scaled and offset (which may pass its own).
  std::pair<double, double> positionRange(const ArmJoint& joint) const;
  /// \brief Joint-vector coordinate of the joint named \p name; throws InputError when there is
  /// no such non-fixed joint.
  std::size_t jointIndex(const std::string& name) const;
  /// \brief Index of the link named \p name; throws InputError when there is none.
  std::size_t linkIndex(const std::string& name) const;
  /// \brief Builds every collision mesh's sub-mesh tree (Mesh::buildHierarchy), for checkers that
  /// query the same rigid links many times. Call before sharing the model.
  void buildHierarchies();
};

/// \brief Reads an arm from a URDF file (urdfdom).
///
/// Mesh file names are resolved as follows: `package://NAME/REST` against each directory DIR of
/// \p packageSearchPath in turn, first DIR/NAME/REST, then DIR/REST; `file://PATH` as PATH; any
/// other name as a path, relative to the URDF file's folder when it is relative. Meshes are read
/// with adsd::io::loadMesh and scaled by their `scale` attribute; box, cylinder and sphere
/// primitives become meshes (boxMesh, cylinderMesh, sphereMesh).
///
/// Throws adsd::InputError naming the file (and the link or joint) when the file does not parse,
/// has a joint cycle or several roots, a floating, planar or unknown joint, a revolute or
/// prismatic joint without finite limits (lower <= upper), or a mesh that cannot be found or read;
/// and for a <mimic> that names no movable joint, closes a cycle of mimic joints, has a multiplier
/// or offset that is not finite within 1e75, or would jump where a continuous leader's angle wraps
/// at +-pi (a prismatic follower, or a turning one whose multiplier is not a whole number).
ArmModel readUrdf(const std::string& urdfPath, const std::vector<std::string>& packageSearchPath = {});

/// \brief Holds every coordinate of \p model's joint vector whose joint is not named in \p planned
/// at its value in \p q (a joint vector of \p model as it stands): the joint becomes locked there
/// (ArmJoint::locked), as MoveIt holds the joints outside the planning group at the start state,
/// and the joint vector is renumbered to the joints left, their order kept. A mimic joint whose
/// leader is held is held at its leader's multiple. Call before sharing the model.
void holdJointsOutside(ArmModel& model, const std::vector<std::string>& planned, const std::vector<double>& q);

}  // namespace adsd::planner
