#pragma once
/// \file
/// \brief Our own procedural meshes: the shapes that tests, benchmarks and problems share.
///
/// Every generator is deterministic and returns a valid adsd::Mesh in its own frame (centred near
/// the origin unless stated). Parameters are lengths in scene units and segment counts. Every
/// shape except merge() is a closed, consistently wound surface with outward normals and no
/// zero-area triangle; a parameter out of range throws adsd::InputError naming it.

#include <cstdint>
#include <vector>

#include "adsd/mesh.h"

namespace adsd::shapes {

/// Axis-aligned box centred at the origin with the given half extents (12 triangles).
Mesh box(const Vec3& halfExtents);
/// Sphere of radius r (UV sphere, `segments` around, segments/2 rings).
Mesh sphere(double radius, int segments);
/// Torus around the z axis: ring radius R, tube radius r.
Mesh torus(double ringRadius, double tubeRadius, int ringSegments, int tubeSegments);
/// A closed tube of radius r swept along a (p, q) torus knot (p=2, q=3: the trefoil). The knot
/// lies on the torus of core radius 2*scale and tube radius scale (p, q coprime). For the trefoil
/// the strands come no closer than 1.66*scale and the centre line bends no tighter than radius
/// 1.43*scale, so the tube does not touch itself while tubeRadius < 0.8*scale.
Mesh knottedTube(double scale, double tubeRadius, int p, int q, int pathSegments, int tubeSegments);
/// A "C": a thick circular arc in the xy plane, swept square section (side `thickness`) centred
/// on the circle of radius `radius`. `openingAngle` (radians, in (0, 2 pi)) is the gap of the C,
/// centred on the +x axis; the arc covers the remaining 2 pi - openingAngle. Flat end faces.
Mesh cShape(double radius, double thickness, double openingAngle, int segments);
/// Capsule (a "stick") along the z axis: cylinder of half length h (>= 0) with hemispherical caps.
Mesh capsule(double radius, double halfLength, int segments);
/// A room: the inside surface of a box (walls, floor, ceiling) with wall thickness, as a closed
/// shell (inner and outer faces); `divisions` subdivides each wall so it has many triangles.
/// halfExtents are those of the cavity; the outer surface is wallThickness further out. The
/// inner surface faces into the cavity. 24 * divisions^2 triangles.
Mesh room(const Vec3& halfExtents, double wallThickness, int divisions);
/// Several meshes concatenated into one (vertex indices shifted), part i placed by poses[i]
/// (poses may be empty: all at identity).
Mesh merge(const std::vector<Mesh>& parts, const std::vector<Pose>& poses);

}  // namespace adsd::shapes
