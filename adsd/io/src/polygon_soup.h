#pragma once
/// \file
/// \brief Polygons as a reader leaves them (points in double, in file order; corner lists of any
/// length), and the one way they become a Mesh, the same for every format read without assimp.

#include <cstdint>
#include <string>
#include <vector>

#include "adsd/mesh.h"

namespace adsd::io::detail {

struct PolygonSoup {
  std::vector<Vec3> points;
  /// Polygon p has corners corners[starts[p] ... starts[p + 1]) (so starts has one entry more).
  std::vector<std::uint32_t> corners;
  std::vector<std::uint64_t> starts{0};

  void addCorner(std::uint32_t point) { corners.push_back(point); }
  void closePolygon() { starts.push_back(corners.size()); }
  std::size_t polygonCount() const { return starts.size() - 1; }
};

/// \brief Throws InputError "PATH: vertex N ..." (N counted from 0 in file order) for a coordinate
/// that is not finite or lies beyond +-tolerance::kMaxCoordinate. Readers that know lines check as
/// they read instead, naming the line.
void requireRepresentablePoints(const PolygonSoup& soup, const std::string& path);

/// \brief The soup as a Mesh named \p path: polygons of three or more corners become triangles
/// (triangulatePolygon: fanned from their first corner when convex, as exporters write them, ear
/// clipped when not; a non-convex one of more than kMaxClippedCorners is refused), polygons of
/// one or two corners (points, lines) are dropped, points used by no triangle are dropped, and
/// points with bit-identical coordinates are shared, so that counts match what assimp made of the
/// same files. Then dropRepeatedTriangles. No coordinate is changed. Throws InputError naming
/// \p path when no triangle is left or a corner refers to no point.
Mesh meshFromSoup(PolygonSoup soup, const std::string& path);

/// \brief Removes from \p triangles (indices below \p vertexCount) those that add no point to the
/// surface: a repeat of an earlier triangle's three vertices in any order, and a triangle whose
/// three corners are one vertex that is a corner of another triangle. The first of each kind
/// stays, in file order. Every vertex used before is still used after.
void dropRepeatedTriangles(std::vector<TriangleIndices>& triangles, std::size_t vertexCount);

}  // namespace adsd::io::detail
