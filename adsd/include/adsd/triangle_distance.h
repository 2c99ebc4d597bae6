#pragma once
/// \file
/// \brief Exact distance between two triangles in every feature combination.

#include "adsd/mesh.h"

namespace adsd {

/// \brief The closest pair of points of two triangles.
struct TrianglePairResult {
  double distance = 0.0;  ///< |pointOnA - pointOnB|; 0 when the triangles intersect or touch
  Vec3 pointOnA = Vec3::Zero();
  Vec3 pointOnB = Vec3::Zero();
};

/// \brief Minimum distance between triangles (a0, a1, a2) and (b0, b1, b2), all in one frame.
///
/// Handles vertex–face, edge–edge, parallel, coplanar, intersecting and zero-area (segment or
/// point) triangles. Every candidate it weighs is a distance between two actual points of the
/// triangles, so rounding can only make the answer slightly too large, never too small; the
/// witness points always lie on the triangles up to rounding.
TrianglePairResult triangleDistance(const Vec3& a0, const Vec3& a1, const Vec3& a2, const Vec3& b0,
                                    const Vec3& b1, const Vec3& b2);

/// \brief triangleDistance that may stop at the first candidate within \p enough: the result is
/// then a distance between two actual points of the triangles, at most \p enough (or 0, as
/// triangleDistance snaps touching triangles), not necessarily the minimum. When no candidate is
/// within it, the result is triangleDistance's. A validity query needs no more, as any pair
/// within its threshold decides it: intersecting triangles are then settled by the first edge
/// found crossing the other triangle, the candidates tried first. A negative \p enough never stops.
TrianglePairResult triangleDistanceUpTo(const Vec3& a0, const Vec3& a1, const Vec3& a2, const Vec3& b0,
                                        const Vec3& b1, const Vec3& b2, double enough);

/// \brief triangleDistanceUpTo that leaves out what cannot come below \p ceiling: candidates
/// (a corner against the other face, a pair of edges) whose plane, box or line bound already puts
/// them at or beyond it are not worked out. When the minimum is below \p ceiling (by more than
/// rounding, of order eps times the triangles' extent) the result is triangleDistanceUpTo's;
/// otherwise its distance is at least about \p ceiling, and infinite when every candidate was
/// left out. A traversal that needs only the pairs nearer than its best answer so far passes that
/// answer (with its roundoff slack) and skips most of the work on pairs that cannot improve it.
TrianglePairResult triangleDistanceBelow(const Vec3& a0, const Vec3& a1, const Vec3& a2, const Vec3& b0,
                                         const Vec3& b1, const Vec3& b2, double enough, double ceiling);

}  // namespace adsd
