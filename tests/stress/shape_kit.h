#pragma once
/// \file
/// \brief Building blocks of the stress families: meshes with exactly known coordinates (grid
/// boxes, plates, prisms), mesh rewrites (transform, offset, permutation, repeated vertices), a
/// pick of small closed shapes, and placements that bring two meshes to a chosen gap.
///
/// Exactness matters here: a family that promises "exactly touching" or "exactly parallel" builds
/// its coordinates so that double rounding cannot break the promise (dyadic values, shared
/// doubles, rotations with entries 0 and +-1); everything else is whatever the doubles turn out to
/// be, and the oracle is the judge.

#include <array>
#include <string>
#include <vector>

#include "adsd/mesh.h"
#include "random_geometry.h"

namespace adsd::stress {

using oracle::SeededRandom;

/// \brief A mesh of one triangle.
Mesh triangleMesh(const Vec3& p0, const Vec3& p1, const Vec3& p2, const std::string& name = "triangle");

/// \brief Axis-aligned box [lo, hi] with every face cut into divisions x divisions squares
/// (12 divisions^2 triangles). Face coordinates are exactly lo and hi; inner grid lines are
/// lo + (hi - lo) k / divisions (exact for dyadic lo, hi and a power-of-two divisions).
Mesh gridBox(const Vec3& lo, const Vec3& hi, int divisions);

/// \brief A flat open grid origin + (i / nu) u + (j / nv) v, 2 nu nv triangles, all coplanar.
Mesh plate(const Vec3& origin, const Vec3& u, const Vec3& v, int nu, int nv);

/// \brief Closed prism around the z axis: a regular polygon of `sides` corners on the circle of
/// `radius`, z from 0 to `length` in `rings` equal sections (so each side line carries rings + 1
/// collinear vertices), capped by fans.
Mesh polygonPrism(double radius, int sides, double length, int rings);

/// \brief Every vertex mapped by \p transform (rounded in double), triangles kept.
Mesh transformedMesh(const Mesh& mesh, const Pose& transform);
/// \brief Every vertex + offset (rounded in double).
Mesh offsetMesh(const Mesh& mesh, const Vec3& offset);
/// \brief Two meshes as one (B's indices shifted).
Mesh mergedMesh(const Mesh& a, const Mesh& b, const std::string& name);

/// \brief The same surface with the vertex array shuffled, the triangles shuffled and the corners
/// of every triangle in one of their 6 orders (the two windings included).
Mesh permutedMesh(const Mesh& mesh, SeededRandom& random);

/// \brief The same surface where every vertex is stored `copies` times and each triangle corner
/// refers to one of the copies at random (duplicate support points for GJK).
Mesh withRepeatedVertices(const Mesh& mesh, int copies, SeededRandom& random);

/// \brief A rotation whose matrix has entries 0 and +-1 only (one of the 48 symmetries of the
/// cube, reflections excluded): applying it is exact in double.
Eigen::Matrix3d axisRotation(SeededRandom& random);

/// \brief A small closed shape of about `size` across, centred near the origin, picked at random:
/// box, grid box, sphere, capsule, torus, C-shape, knotted tube, prism. `convexOnly` leaves out
/// the torus, C and knot. \p name receives what was picked.
Mesh randomShape(SeededRandom& random, double size, bool convexOnly, std::string* name);

/// \brief A uniformly random point of triangle t of \p mesh placed by \p pose (world frame),
/// kept at least `margin` (barycentric) away from the triangle's edges, and the triangle's unit
/// normal by its winding (world frame; zero for a zero-area triangle).
struct SurfacePoint {
  Vec3 point;
  Vec3 normal;
  std::size_t triangle;
};
SurfacePoint randomSurfacePoint(const Mesh& mesh, const Pose& pose, SeededRandom& random, double margin = 0.0);

/// \brief The pose that turns mesh \p b by \p rotation and then translates it so that its vertex
/// farthest along -direction (its support point towards -direction) lands on \p target. For a
/// convex B this leaves all of B on the +direction side of the plane through target.
Pose placeSupportAt(const Mesh& b, const Eigen::Matrix3d& rotation, const Vec3& direction, const Vec3& target);

/// \brief Multiple of 2^-bits in [-1, 1]: sums and differences of such values with moderate
/// integers are exact in double.
double dyadic(SeededRandom& random, int bits = 10);

/// \brief Any unit vector perpendicular to the unit vector d.
Vec3 perpendicularTo(const Vec3& d, SeededRandom& random);

/// \brief 2^round(log2(x)): a scale that keeps dyadic coordinates exact.
double powerOfTwoNear(double x);

}  // namespace adsd::stress
