#pragma once
/// \file
/// \brief Internal: a mesh from a sequence of rings (a swept section), shared by every swept shape.
///
/// Sphere, capsule, torus, knotted tube and C are all "rings of equally many points, consecutive
/// rings joined by quads": only the ring positions and how the two ends close differ.

#include <optional>
#include <string>
#include <vector>

#include "adsd/mesh.h"

namespace adsd::shapes::detail {

/// How an open sequence of rings is closed at one end.
struct RingCap {
  /// Apex of the fan that closes the end ring: a pole (sphere, capsule) or the centre of a flat
  /// end face (C). No value: the end stays open (never used for the closed shapes we make).
  std::optional<Vec3> apex;
};

/// \brief Joins `rings` (each with the same number of points, in the same angular order) by
/// quads split into two triangles. If \p closedLoop, the last ring is joined back to the first
/// (torus, knot); otherwise the two ends get the fans described by \p first and \p last.
///
/// The winding is made consistent by construction; the caller makes it outward with
/// orientOutward() once the surface is closed.
Mesh sweepRings(const std::vector<std::vector<Vec3>>& rings, bool closedLoop, const RingCap& first,
                const RingCap& last, const std::string& name);

/// \brief Signed volume enclosed by a closed, consistently wound mesh (divergence theorem:
/// the sum of the signed tetrahedra spanned by the origin and each triangle).
double signedVolume(const Mesh& mesh);

/// \brief Reverses every triangle if the signed volume is negative, so that a closed surface
/// made of one shell ends up with outward normals (counter-clockwise seen from outside).
Mesh orientOutward(Mesh mesh);

/// \brief Throws InputError naming \p shape and \p field unless \p value is finite and > 0.
void requirePositive(const char* shape, const char* field, double value);
/// \brief Throws InputError naming \p shape and \p field unless \p value >= \p minimum.
void requireAtLeast(const char* shape, const char* field, int value, int minimum);

}  // namespace adsd::shapes::detail
