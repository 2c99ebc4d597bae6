#pragma once
/// \file
/// \brief The mesh–mesh distance query: the paper's RecursiveMinDist (Algorithm 1).
///
/// One input (two meshes, two poses, options) in, one result out (STYLE habit 1). The caller owns
/// the scratch memory, one per thread, so that queries allocate nothing once warm and many threads
/// can query the same meshes at once without locks.
///
/// Accuracy. "Exact up to rounding" means: every distance, bound and decision of a query is right
/// within 1e-10 x the scene's bounding-box diagonal + tolerance::kBoundSafetyUlps x eps x M, where
/// M is the magnitude of the numbers the query works with: sqrt(3) x (largest |coordinate| of A's
/// vertices that triangles use, in A's frame, + the same of B) + |translation of B's pose -
/// translation of A's| (Mesh::maxAbsCoordinate). The query works in
/// mesh A's frame; B's vertices taken into it round at ulp(M), so when mesh frames lie far from
/// their geometry (coordinates 1e8 x the scene, posed back next to each other) the second term is
/// what bounds the error (and the inputs themselves carry no more digits than that). Offsets
/// carried alike by both poses keep M at the scene's own size. Measured by tests/stress against a
/// binary128 oracle (families mesh/offset-* for the second term).

#include <cstdint>
#include <limits>
#include <memory>

#include "adsd/mesh.h"

namespace adsd {

/// \brief What a query is asked to decide.
enum class QueryMode {
  /// The minimum distance, exact up to rounding (the result's interval is [d, d]).
  exact,
  /// An interval [lower, upper] containing the distance with upper - lower within
  /// max(absTolerance, relTolerance * upper). Prunes sub-mesh and triangle pairs that cannot
  /// improve the answer by more than that.
  tolerance,
  /// Only whether the distance exceeds `threshold` (the validity question), stopping as soon as
  /// one side is proven.
  threshold,
  /// The distance if it is below `cap`; otherwise only the fact that it is at least `cap`.
  cap,
};

struct DistanceOptions {
  QueryMode mode = QueryMode::exact;
  /// tolerance mode: absolute slack, in length units of the scene (finite, >= 0).
  double absTolerance = 0.0;
  /// tolerance mode: slack relative to the returned upper bound (finite, >= 0, dimensionless).
  double relTolerance = 0.0;
  /// threshold mode: the safety margin D (finite, >= 0, length units).
  double threshold = 0.0;
  /// cap mode: distances at or beyond this are reported only as ">= cap" (> 0, length units).
  double cap = std::numeric_limits<double>::infinity();

  static DistanceOptions exactDistance() { return {}; }
  static DistanceOptions withTolerance(double absTol, double relTol) {
    DistanceOptions o;
    o.mode = QueryMode::tolerance;
    o.absTolerance = absTol;
    o.relTolerance = relTol;
    return o;
  }
  static DistanceOptions aboveThreshold(double d) {
    DistanceOptions o;
    o.mode = QueryMode::threshold;
    o.threshold = d;
    return o;
  }
  static DistanceOptions cappedAt(double d) {
    DistanceOptions o;
    o.mode = QueryMode::cap;
    o.cap = d;
    return o;
  }
};

/// \brief What the result guarantees.
enum class DistanceStatus {
  exact,           ///< distance is the minimum distance (lower == upper == distance).
  withinTolerance, ///< the minimum distance lies in [lower, upper], upper - lower within tolerance.
  aboveThreshold,  ///< proven: minimum distance > threshold (lower >= threshold: pairs culled at
                   ///< the threshold count with it as their bound).
  withinThreshold, ///< proven: minimum distance <= threshold (upper <= threshold; distance = upper).
  beyondCap,       ///< proven: minimum distance >= cap (lower == cap, upper may be infinite).
};

const char* toString(DistanceStatus status);

/// \brief How the work went: the counters that explain speed (STYLE habit 2).
struct DistanceCounters {
  int maxDepth = 0;                        ///< deepest recursion level reached (root = 0)
  std::uint64_t subMeshPairs = 0;          ///< sub-mesh pairs visited (stage one run on them)
  std::uint64_t pairsRejectedByBounds = 0; ///< pairs skipped by the rule of sec. 6.2
  std::uint64_t pairsHashed = 0;           ///< pairs that reached the spatial hashing stage (sec. 5)
  std::uint64_t pairsSplit = 0;            ///< pairs whose hulls overlapped and were split (sec. 6)
  std::uint64_t trianglesHashed = 0;       ///< triangles inside the slabs (first culling)
  /// Hashing stages started again with the upper bound they had lowered (sec. 5's slab and cells
  /// sized anew for the triangles left); their triangles count again in trianglesHashed.
  std::uint64_t hashRestarts = 0;
  std::uint64_t trianglePairsTested = 0;   ///< exact triangle-triangle distance evaluations
  std::uint64_t gjkCalls = 0;              ///< GJK runs
  std::uint64_t gjkIterations = 0;         ///< GJK iterations over all runs
  int gjkMaxIterations = 0;                ///< most iterations one GJK run took
  /// 1 when a query on trees went over its budget of node pairs (meshes whose trees cannot tell
  /// triangles apart, such as a stack of copies of one triangle) and was finished from scratch;
  /// the counts above then hold both passes.
  int treeAbandoned = 0;
  /// 1 when a query from scratch went over its budget of work (about twice what building both meshes'
  /// trees costs) and was finished on trees built for it and dropped after it; the counts above
  /// then hold both passes. A caller asking many queries of such meshes should build the trees
  /// once (Mesh::buildHierarchy).
  int scratchAbandoned = 0;
};

/// \brief The answer. Lengths in the scene's units; points in the world frame.
struct DistanceResult {
  /// Best distance found: a distance between two actual points of the meshes (so never below
  /// the true minimum, up to rounding). In exact mode it is the minimum. In cap mode with status
  /// beyondCap it equals `cap`.
  double distance = std::numeric_limits<double>::infinity();
  /// Interval that contains the minimum distance. Exact: lower == upper == distance.
  double lower = 0.0;
  double upper = std::numeric_limits<double>::infinity();
  /// Witness points realizing `distance`: witnessA on mesh A, witnessB on mesh B, world frame.
  /// Equal when the meshes intersect (distance 0). Meaningless (NaN-free zeros) for beyondCap
  /// and aboveThreshold without a pair found.
  Vec3 witnessA = Vec3::Zero();
  Vec3 witnessB = Vec3::Zero();
  /// Triangles carrying the witnesses (indices into the meshes), -1 when none was found.
  std::int64_t triangleA = -1;
  std::int64_t triangleB = -1;
  DistanceStatus status = DistanceStatus::exact;
  DistanceCounters counters;
};

/// \brief Per-thread working memory for queries. Reused, it makes queries allocation-free once
/// it has grown to the meshes' size, except a query from scratch that goes over its budget: it
/// builds trees for itself (DistanceCounters::scratchAbandoned). Not shareable between threads
/// running queries at once.
///
/// It also remembers, per mesh pair (by address), the triangles of the last answer: the next
/// query between the same meshes measures them first, which gives it an upper bound close to the
/// answer when the poses moved little (a planner's consecutive checks). The hint only changes how
/// fast the answer is proven, never the answer beyond rounding (meshes that meet only at rounding
/// level, a shared face of two rotated boxes, answered 2e-19 from a fresh scratch and 0 from a
/// warm one in an outside review: both within the accuracy promised above).
class DistanceScratch {
 public:
  DistanceScratch();
  ~DistanceScratch();
  DistanceScratch(DistanceScratch&&) noexcept;
  DistanceScratch& operator=(DistanceScratch&&) noexcept;

  struct Buffers;
  Buffers& buffers();

 private:
  std::unique_ptr<Buffers> buffers_;
};

/// \brief Minimum distance between mesh \p a placed by \p poseA and mesh \p b placed by \p poseB.
///
/// Thread-safe for concurrent calls on the same meshes with distinct scratch objects. Throws
/// InputError for invalid options (a mode outside QueryMode, negative tolerance, non-finite
/// threshold, non-positive cap) or a pose that is not rigid (non-finite entries, a rotation part
/// not orthonormal within tolerance::kPoseOrthonormality, a bottom row other than 0 0 0 1) or
/// whose translation exceeds tolerance::kMaxCoordinate, and for a scene spanning less than
/// tolerance::kMinSceneMagnitude, where products of its lengths underflow, and for a Mesh moved
/// from (no triangles). A DistanceScratch moved from is usable again. An orthonormal part of
/// determinant -1 (a mirror image, the left part made from the right one's mesh) is an isometry
/// too, and is taken.
DistanceResult distance(const Mesh& a, const Pose& poseA, const Mesh& b, const Pose& poseB,
                        const DistanceOptions& options, DistanceScratch& scratch);

/// \brief Convenience overload with a scratch of its own (allocates on every call).
DistanceResult distance(const Mesh& a, const Pose& poseA, const Mesh& b, const Pose& poseB,
                        const DistanceOptions& options = {});

}  // namespace adsd
