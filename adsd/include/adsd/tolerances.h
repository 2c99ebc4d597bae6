#pragma once
/// \file
/// \brief Every tolerance of the core in one place, each with its unit, scale and reason
/// (STYLE habit 3). Values are relative to a named length scale unless stated.

#include <cstdint>
#include <limits>

namespace adsd::tolerance {

/// Unit roundoff of double (dimensionless), the yardstick of everything below.
inline constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

/// Triangle routine: a computed distance at or below this many units of roundoff of the local
/// coordinate scale (largest coordinate after moving the origin to the first corner of triangle A)
/// is indistinguishable from contact and reported as exactly 0. About 3.6e-15 relative: far below
/// the 1e-10 x diagonal accuracy we promise, above what a crossing edge's interpolated point lies
/// off the other plane (a few ulps; test_triangle_distance's crossing pairs must give exactly 0).
/// The same number of ulps of a face's edge vectors, and of the point's offset from the face,
/// grows the corner box that a point's foot must lie in to count as interior (triangle_distance.cpp,
/// closestOnFace): the foot carries a few ulps of rounding, and a foot on an edge, or on a face with
/// a constant coordinate, must not be refused for it.
inline constexpr double kContactSnapUlps = 16.0;

/// Triangle routine: two edge directions count as parallel when |d1 x d2|^2 <= this x |d1|^2 |d2|^2
/// (i.e. the angle is below ~1e-15 rad). The interior edge–edge candidate is then skipped: the
/// endpoints' candidates are within angle x length of it, below roundoff.
inline constexpr double kParallelSine2 = 1e-30;

/// Triangle routine: a triangle is treated as a segment or point (no interior) when
/// |n|^2 <= this x (longest edge)^4, n the unnormalized normal (sine of the smallest angle ~1e-15).
inline constexpr double kDegenerateArea2 = 1e-30;

/// Bounds: every GJK lower bound used for pruning or for sizing the hash grid is lowered by this
/// many units of roundoff of the coordinate magnitude M (largest |coordinate| of either mesh in
/// mesh A's frame). A dot product of coordinates of size M carries an error of about 3 eps M, a
/// difference of two such about 6 eps M; 64 leaves a factor of ten. Without it a lower bound that
/// rounds high could prune the true closest pair (tested by the near-contact and large-offset
/// stress families).
inline constexpr double kBoundSafetyUlps = 64.0;

/// Exact and capped queries: pairs tied with the best distance found are not opened. A pair that
/// can be nearer than the best by no more than a tie slack is dropped; the slack is the roundoff
/// allowance (kBoundSafetyUlps eps M), ten times what rounds a tied pair's bound below the best,
/// but at most this fraction of the larger mesh's bounding-box diagonal (Mesh::diagonal, at most
/// sqrt(3) times the scene's), a sixth of the 1e-10 x diagonal accuracy promised (distance.h),
/// where M outgrows the meshes. Without it, tied pairs were opened because their bounds rounded a
/// few ulps either way: a box of 43 200 triangles resting flat 1e-3 above a plate of 180 000
/// (every bottom triangle at the same distance from the plate) took 20 ms and 104 000 node pairs
/// with trees, against 0.07 ms tilted by 0.05 rad (an outside review).
inline constexpr double kTieSlack = 1e-11;

/// Input range: the largest |coordinate| a Mesh accepts (mesh frame, length units) and the largest
/// |translation| entry a pose may carry. The highest power of a length that the core forms is the
/// fourth: |e1 x e2|^2 of two edges or of two difference vectors (the triangle routine's degenerate
/// and parallel tests, the signed volumes' face normals). In mesh A's frame, where the query works,
/// A's vertices lie within sqrt(3) x 1e75 of the origin and B's within
/// sqrt(3) x 1e75 + |t_B - t_A| <= 3 sqrt(3) x 1e75, so a difference is below 7e75 and its fourth
/// power below 2.5e303: more than 1e4 below DBL_MAX (1.8e308), room for the sums and small factors
/// around it. Above this, squared distances overflow and a query would answer inf
/// or NaN with status exact, so Mesh and distance() refuse such input with an InputError instead.
/// No real model comes near it: it is a bound on units and offsets gone wrong, not on scenes.
inline constexpr double kMaxCoordinate = 1e75;

/// The smallest scene distance() answers: the meshes' largest coordinates plus the poses' offset
/// (requireResolvableScene). The core forms up to sixth powers of lengths, which go subnormal
/// below about 1e-51 and vanish below 1e-54: an outside review measured 30 % too far at 1e-80 and
/// 0 for meshes 3e-166 apart. At 1e-40 they are 1e-240, far from it. Like kMaxCoordinate, a bound
/// on units gone wrong (the Planck length is 1.6e-35 m), not on scenes.
inline constexpr double kMinSceneMagnitude = 1e-40;

/// Poses: the rotation part R of a pose must satisfy |(R^T R - I)_ij| <= this for every entry
/// (dimensionless). A rotation off by d stretches lengths by up to about d, a relative error of d
/// in the distance, which must stay below the 1e-10 x diagonal we promise (the core inverts such
/// a rotation as a matrix: kRotationInverseByTranspose). Rotations built in double from a unit
/// quaternion or an angle-axis pair are within a few 1e-16; a pose rounded to float (about 1e-7)
/// or carrying a scale or a shear is refused (a shear was answered wrongly by the tree path before
/// this check, issue 16; tests/stress/input_boundary_test.cpp pins the refusal).
inline constexpr double kPoseOrthonormality = 1e-10;

/// A pose's rotation within this of orthonormal (max |R^T R - I|, dimensionless) is inverted by
/// its transpose: off by d, the transpose moves a point p by d x |p|, below the 64 eps M roundoff
/// the bounds allow. One farther off, up to kPoseOrthonormality, is inverted as a matrix
/// (Query::placeFrames), so that a mesh far from its frame's origin is placed where its pose says.
inline constexpr double kRotationInverseByTranspose = 16 * kEpsilon;

/// GJK: iteration cap. Polytope GJK converges in far fewer steps in practice; the cap only
/// guarantees termination. Hitting it is harmless here: an unproven separation is split (sec. 6).
inline constexpr int kGjkMaxIterations = 64;

/// GJK: stop when the gap between the hull distance |v| and the best lower bound is below this
/// fraction of |v| (dimensionless). The lower bound only sizes the slab (eq. 1) and the cells
/// (eq. 3), where a 1e-3 looser bound costs nothing measurable, while the last digits cost
/// iterations.
inline constexpr double kGjkRelativeGap = 1e-3;

/// GJK: |v|^2 at or below this x M^2 counts as the origin being reached (hulls touch or overlap).
inline constexpr double kGjkTouchRelative2 = 1e-28;

/// Splitting (sec. 6.1): the support-plane split is kept when the part it cuts off holds at least
/// this fraction of the sub-mesh's triangles; otherwise the sub-mesh is halved at the median along
/// the same direction, which bounds the recursion depth by log_{1/(1-f)} n.
inline constexpr double kMinSplitFraction = 1.0 / 8.0;

/// Sub-mesh pairs with at most this many triangle pairs are tested directly, without GJK: a few
/// triangle tests cost less than a GJK run (sec. 6.1 stops at one primitive; this is the same
/// rule, a little earlier).
inline constexpr int kDirectPairLimit = 16;

/// Hashing (sec. 5): slab pairs up to this count are tested all against all (with a box bound
/// first): building the hash costs more than it saves below it.
inline constexpr int kHashMinPairs = 256;

/// Hashing: a separated sub-mesh pair whose grid would still meet each slab triangle with more
/// than this many candidates on average (bounds far apart for the pair's size: hulls nearly
/// touching while the surfaces are far apart, as a long thin sheet beside a finned disc) is split
/// and recursed on instead (beyond the paper, which splits only overlapping hulls): its halves'
/// GJK bounds drop most of it. The CGAL blade against the turbine 10 apart: 1.7 s hashed whole.
inline constexpr double kHashCandidatesPerTriangle = 128.0;

/// Hashing: a triangle whose box covers more cells than this is not hashed but tested against
/// every triangle of the other slab (with a box bound): keeps the table linear in size.
inline constexpr int kMaxCellsPerTriangle = 64;

/// Hashing: a slab triangle larger than this many times the slab's mean triangle is left out of
/// the mean that sizes the cells (spatial_hash.cpp): a few giant triangles among small ones would
/// otherwise make one cell hold every small triangle.
inline constexpr double kOutlierTriangleSize = 8.0;

/// Hashing: a stage whose upper bound has fallen to a quarter of its reach starts again with the
/// new bound (spatial_hash.cpp) only while at least this many B triangles are left to test:
/// rebuilding the grid costs a pass over both slabs.
inline constexpr std::size_t kHashRestartTriangles = 16;

/// A query from scratch whose work passes this many units (about a nanosecond each on the
/// machine the weights below were measured on) per triangle of both meshes, and at least
/// kScratchWorkAtLeast, is finished on trees built for it: about twice what building both trees
/// costs (2.0 us a triangle for dragon_res4 and the bunny, 2.1 for two cows: `adsd distance
/// --path tree` prints the build time). Such a query then costs about three builds and a query
/// on the trees, where from scratch alone it could cost 15 builds (dragon_res4 against the bunny:
/// 0.44 s, 953 031 triangle pairs). Twice rather than once: queries from scratch of one or two
/// builds are common where every part of one surface lies near the other (two parallel wavy
/// sheets: 111 ms against a 67 ms build, an outside review), and there the trees give up too
/// (treeAbandoned), so that with a budget of one build the query paid the budget, the build, the
/// traversal's budget and the whole pass from scratch again (3.3 times).
inline constexpr std::uint64_t kScratchWorkPerTriangle = 4000;
inline constexpr std::uint64_t kScratchWorkAtLeast = 1000000;
/// The cost model's weights, in the same units: an exact triangle-pair test, a box test that
/// may spare one, a vertex scanned by a support search, a triangle projected and sorted by a
/// split or gathered into a slab.
inline constexpr std::uint64_t kWorkTrianglePair = 300;
inline constexpr std::uint64_t kWorkBoxTest = 8;
inline constexpr std::uint64_t kWorkSupportVertex = 2;
inline constexpr std::uint64_t kWorkTrianglePass = 10;

/// Hashing: cells per axis at most (cell size grows to respect it), so cell indices fit easily in
/// 32 bits whatever the ratio of scene size to cell size.
inline constexpr double kMaxCellsPerAxis = 1 << 20;

}  // namespace adsd::tolerance
