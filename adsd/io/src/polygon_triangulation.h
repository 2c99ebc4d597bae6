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

/// The corner tests (a corner against an ear's triangle) ear clipping may spend on one file's
/// polygons, in all. Each face is bounded by kMaxClippedCorners, but a file of a hundred spirals
/// of 10 000 corners (1.1 MB, 44 million tests each) took 23 s to read, and ten times as many
/// would take four minutes; at about 4 ns a test, this budget is 2 s. Faces as CAD programs and
/// scanners write them, non-convex or not, take a few tests per corner.
inline constexpr std::uint64_t kClippingTestsPerFile = 500'000'000;

/// \brief What triangulatePolygon made of a polygon.
enum class PolygonKind {
  convex,      ///< fanned from its first corner (also a polygon with no area, nothing to clip)
  clipped,     ///< non-convex, triangulated by ear clipping
  tooLarge,    ///< non-convex with more than kMaxClippedCorners corners: no triangles given
  outOfTests,  ///< clipping it would pass the tests left to the file: no triangles given
};

/// \brief Triangles covering the polygon with corners \p corners (in order, three or more), as
/// triples of positions in \p corners, wound as the polygon is. A polygon whose corners all turn
/// the same way about its Newell normal is fanned from its first corner, exactly as before, so
/// convex faces (what exporters write) are unchanged. Otherwise the polygon is projected on the
/// plane across its normal and ears are clipped: a corner that turns the polygon's way and holds
/// no other corner in its triangle is cut off, until three remain. A polygon with no ear (one that
/// crosses itself) has its remaining corners fanned. \p testsLeft is the file's budget of corner
/// tests (kClippingTestsPerFile), lowered by those this polygon takes.
PolygonKind triangulatePolygon(const std::vector<Vec3>& corners, std::vector<std::array<std::uint32_t, 3>>& triangles,
                               std::uint64_t& testsLeft);

}  // namespace adsd::io::detail
