#pragma once
/// \file
/// \brief Exact signs of the orientation determinants on double coordinates, by expansion
/// arithmetic (Shewchuk 1997, "Adaptive precision floating-point arithmetic and fast robust
/// geometric predicates"): every product and sum is carried as an unevaluated sum of doubles
/// without any rounding, and the sign is read off the most significant component.
///
/// Exact while no partial product underflows or overflows: |coordinate differences| between
/// about 1e-90 and 1e100 (products of three of them stay inside the double range with room for the
/// 2^-106 error terms).

#include "adsd/mesh.h"

namespace adsd::oracle::exact {

/// \brief Sign (+1, 0, -1) of det[a - d; b - d; c - d]: zero iff a, b, c, d are coplanar.
int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// \brief Sign of (a - c) x (b - c) in the coordinate plane (u, v): the 2-D orientation of the
/// projections of a, b, c that drop the third axis. Zero iff the projections are collinear.
int orient2d(const Vec3& a, const Vec3& b, const Vec3& c, int u, int v);

}  // namespace adsd::oracle::exact
