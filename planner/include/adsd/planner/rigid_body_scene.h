#pragma once
/// \file
/// \brief What a rigid-body planning problem is made of: robot meshes, environment meshes, and
/// whether the robot moves in SE(2) or SE(3).

#include <cstddef>
#include <limits>
#include <vector>

#include <Eigen/Geometry>

#include "adsd/mesh.h"

namespace adsd::planner {

/// \brief The configuration space of the robot.
enum class RigidBodySpace {
  se2,  ///< x, y, yaw: the robot moves in the plane z = 0, rotating about z (checked in 3D).
  se3,  ///< x, y, z and a rotation.
};

/// \brief A robot of one or more meshes (all in the robot's body frame, moving together) and an
/// environment of one or more meshes (in the world frame, never moving).
///
/// Read-only once built, so any number of threads may query it.
struct RigidBodyScene {
  std::vector<Mesh> robot;
  std::vector<Mesh> environment;
  RigidBodySpace space = RigidBodySpace::se3;
};

/// \brief Largest distance of a robot vertex from the body-frame origin: the radius that turns a
/// rotation angle into a bound on how far any robot point moves (issue 4, certified motion).
double robotRadius(const RigidBodyScene& scene);

/// \brief Axis-aligned box of every environment vertex, world frame.
Eigen::AlignedBox3d environmentBounds(const RigidBodyScene& scene);

/// \brief Length of the diagonal of the box holding the environment and the robot's reach
/// (environment box widened by the robot radius): the scene's length scale for tolerances.
double sceneScale(const RigidBodyScene& scene);

/// Most parts splitIntoParts() makes (count): the broad phase bounds every robot part against
/// every environment part on each query (a ball–box and a box–box distance, far cheaper than a
/// distance query), so a few hundred parts cost little while letting it skip most of a large scene.
inline constexpr std::size_t kMaxEnvironmentParts = 256;

/// Pieces of at most this many triangles are not cut further (count): cutting cannot make a piece
/// smaller than its largest triangle, and a handful of triangles is one cheap query anyway.
inline constexpr std::size_t kMinPieceTriangles = 8;

/// Environment pieces are cut down to a box diagonal of at most this multiple of the robot's
/// diameter (dimensionless). An environment that surrounds the robot (a room, a maze, a closed
/// box) has a convex hull that holds it, so the distance query's hull bounds (paper, Section 3)
/// cannot separate them and it must split both meshes on every query; pieces of about the robot's
/// size are separated by their boxes or hulls at once, and the broad phase skips the far ones.
inline constexpr double kPieceDiagonalPerRobotDiameter = 1.0;

/// \brief Splits \p mesh into parts for the checkers' broad phase: its connected components
/// (triangles sharing a vertex index), each cut (median splits of its triangles' centroids) into
/// pieces whose boxes have a diagonal of at most \p maxPieceDiagonal, except small convex ones
/// too thin to hold the robot (adsd::isClosedConvex, no wider than \p maxPieceDiagonal across a
/// face: a box obstacle, a wall), which stay whole, and components of such solids touching
/// (joined at shared corners), which are split into them along the edges where they meet; when there are more than
/// \p maxParts pieces, spatially neighbouring pieces are grouped into \p maxParts parts. Every
/// triangle ends up in exactly one part, so the distance to the parts' union is the distance to
/// the mesh.
std::vector<Mesh> splitIntoParts(const Mesh& mesh, std::size_t maxParts = kMaxEnvironmentParts,
                                 double maxPieceDiagonal = std::numeric_limits<double>::infinity());

/// \brief The name of the mesh a part of splitIntoParts() came from: \p partName less its
/// " part N" (a mesh it did not split keeps its own name).
std::string nameBeforeSplit(const std::string& partName);

/// \brief splitIntoParts() with pieces sized to the scene's robot (kPieceDiagonalPerRobotDiameter).
std::vector<Mesh> splitForRobot(const Mesh& environment, const std::vector<Mesh>& robot);

/// \brief Re-centres a robot mesh the OMPL.app way: subtracts the mean of its vertices, with the
/// z component of that mean kept at zero for SE(2) problems (shared/OMPLAPP-CFG.md).
Mesh recentreRobot(const Mesh& robot, RigidBodySpace space);

}  // namespace adsd::planner
