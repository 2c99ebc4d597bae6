#pragma once
/// \file
/// \brief Triangles for one polygon of a mesh file: a fan for a convex polygon, ear clipping for a
/// non-convex one (an L-shaped face fanned from its first corner covers its own notch).

#include <array>
#include <cstdint>
#include <vector>

#include "adsd/mesh.h"

namespace adsd::io::detail {

/// Non-convex polygons with more corners than this are refused rather than clipped: ear clipping
/// takes time quadratic in the corners (a polygon of 10 000 takes about 0.1 s).
inline constexpr std::size_t kMaxClippedCorners = 10000;

/// \brief What triangulatePolygon made of a polygon.
enum class PolygonKind {
  convex,      ///< fanned from its first corner (also a polygon with no area, nothing to clip)
  clipped,     ///< non-convex, triangulated by ear clipping
  tooLarge,    ///< non-convex with more than kMaxClippedCorners corners: no triangles given
};

/// \brief Triangles covering the polygon with corners \p corners (in order, three or more), as
/// triples of positions in \p corners, wound as the polygon is. A polygon whose corners all turn
/// the same way about its Newell normal is fanned from its first corner, exactly as before, so
/// convex faces (what exporters write) are unchanged. Otherwise the polygon is projected on the
/// plane across its normal and ears are clipped: a corner that turns the polygon's way and holds
/// no other corner in its triangle is cut off, until three remain. A polygon with no ear (one that
/// crosses itself) has its remaining corners fanned.
PolygonKind triangulatePolygon(const std::vector<Vec3>& corners, std::vector<std::array<std::uint32_t, 3>>& triangles);

}  // namespace adsd::io::detail
