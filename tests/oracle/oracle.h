#pragma once
/// \file
/// \brief The independent oracle that the core's answers are checked against (tests and the
/// stress tool only).
///
/// Written without looking at or calling the core's triangle routine, with different algorithms
/// and more precision:
/// - triangle-triangle distance: minimize |p - q|^2 over every pair of faces (vertex, edge,
///   interior) of the two triangles on the faces' affine hulls, in binary128, keep the feasible
///   minimizers, take the smallest (a KKT face enumeration, see triangle_distance_kkt.cpp);
/// - triangle-triangle intersection: exact orientation predicates (expansion arithmetic) on
///   double input, binary128 orientation on binary128 input;
/// - mesh-mesh distance: every triangle pair, poses applied in binary128, with only rigorous
///   lower-bound pruning.
///
/// Only the meshes' vertices and index triples are used from the core (adsd::Mesh, adsd::Pose).

#include <cstdint>

#include "adsd/mesh.h"
#include "quad_vector.h"

namespace adsd::oracle {

/// \brief Dimension of a face of a triangle: where on it a closest point lies.
enum class Feature : int { vertex = 0, edge = 1, interior = 2 };

const char* toString(Feature feature);

/// \brief Closest points of two triangles, in binary128.
struct TrianglePairDistance {
  Quad distance = 0;       ///< |pointOnA - pointOnB| in binary128
  double value = 0.0;      ///< distance rounded to double
  Quad3 pointOnA, pointOnB;  ///< in the triangles' common frame
  Feature featureA = Feature::vertex;  ///< face of A whose affine-hull minimizer won
  Feature featureB = Feature::vertex;  ///< face of B whose affine-hull minimizer won
};

/// \brief Minimum distance between triangles (a0, a1, a2) and (b0, b1, b2); any of them may be
/// degenerate (segment or point). Accurate to a few units of 1e-30 relative to the coordinates'
/// magnitude (see triangle_distance_kkt.cpp for the argument).
TrianglePairDistance triangleDistance(const Quad3& a0, const Quad3& a1, const Quad3& a2, const Quad3& b0,
                                      const Quad3& b1, const Quad3& b2);
/// \brief Same on double input (converted exactly).
TrianglePairDistance triangleDistance(const Vec3& a0, const Vec3& a1, const Vec3& a2, const Vec3& b0,
                                      const Vec3& b1, const Vec3& b2);

/// \brief Distance from point p to triangle (a0, a1, a2), binary128.
Quad pointTriangleDistance(const Quad3& p, const Quad3& a0, const Quad3& a1, const Quad3& a2);

/// \brief Whether the closed triangles (a0, a1, a2) and (b0, b1, b2) share a point, decided
/// EXACTLY on the given doubles (no tolerance; degenerate triangles, touching and coplanar cases
/// included). Valid while products of three coordinate differences neither overflow nor underflow
/// (|coordinates| within about 1e-90 ... 1e100).
bool trianglesIntersect(const Vec3& a0, const Vec3& a1, const Vec3& a2, const Vec3& b0, const Vec3& b1,
                        const Vec3& b2);
/// \brief The same decision on binary128 coordinates with binary128 orientation tests: not exact,
/// but a sign is wrong only when an orientation is within ~1e-32 (relative) of zero.
bool trianglesIntersect(const Quad3& a0, const Quad3& a1, const Quad3& a2, const Quad3& b0, const Quad3& b1,
                        const Quad3& b2);

/// \brief The corners of triangle t of \p mesh placed by \p pose, in binary128.
std::array<Quad3, 3> posedTriangle(const Mesh& mesh, const Pose& pose, std::size_t t);

/// \brief The accuracy every exact answer owes (issue 2): this times sceneDiagonal().
inline constexpr double kPromisedAccuracy = 1e-10;

/// \brief The diagonal of the box around both meshes as placed: the length the accuracy
/// promise is relative to.
inline double sceneDiagonal(const Mesh& a, const Pose& poseA, const Mesh& b, const Pose& poseB) {
  Eigen::AlignedBox3d box;
  for (const Vec3& v : a.vertices()) box.extend(poseA * v);
  for (const Vec3& v : b.vertices()) box.extend(poseB * v);
  return box.diagonal().norm();
}

/// \brief Brute-force mesh-mesh minimum distance.
struct MeshPairDistance {
  Quad distance = 0;
  double value = 0.0;          ///< distance rounded to double
  std::int64_t triangleA = -1;  ///< a triangle pair attaining the minimum
  std::int64_t triangleB = -1;
  Vec3 pointOnA = Vec3::Zero();  ///< closest points, world frame, rounded to double
  Vec3 pointOnB = Vec3::Zero();
  std::uint64_t trianglePairsEvaluated = 0;  ///< pairs the bounds could not prune
};

/// \brief Every triangle of A (placed by poseA) against every triangle of B (placed by poseB),
/// each pair either evaluated by triangleDistance() in binary128 or pruned by a lower bound that
/// provably exceeds the best distance found (bounding spheres and projection gaps computed in
/// double, with a slack that covers their rounding).
MeshPairDistance meshDistance(const Mesh& a, const Pose& poseA, const Mesh& b, const Pose& poseB);

/// \brief Whether any triangle of A (placed by poseA) meets any triangle of B (placed by poseB),
/// by trianglesIntersect() on binary128 posed corners (pairs a rigorous lower bound keeps apart
/// skipped).
bool meshesIntersect(const Mesh& a, const Pose& poseA, const Mesh& b, const Pose& poseB);

}  // namespace adsd::oracle
