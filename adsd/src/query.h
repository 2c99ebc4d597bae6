#pragma once
// The state of one distance query: the two meshes in mesh A's frame, the running global bounds
// of sec. 6.2, the mode's rules for dropping work, the counters, and the per-thread buffers.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

#include "adsd/distance.h"
#include "adsd/mesh_hierarchy.h"
#include "adsd/tolerances.h"
#include "gjk.h"

namespace adsd {

/// One triangle admitted to a slab (sec. 5.3), in mesh A's frame, with its box in the grid frame
/// of sec. 5.1 (x, y in the separating plane, z along the separating direction).
struct SlabTriangle {
  Vec3 corner[3];
  double minX, maxX, minY, maxY, minZ, maxZ;
  std::uint32_t triangle;
};

/// A pair of tree nodes still to decide in a traversal (tree_traversal.cpp), with the lower bound
/// found for it (the order's key, checked again when it is taken: the bound may have fallen
/// meanwhile). When a node is a leaf, its mask says which of its triangles are not yet proven
/// farther than the bound from the other node (bit k: triangle t0 + k): a triangle far from a
/// box is far from everything the box holds.
struct PendingNodePair {
  std::int32_t a, b;
  // Kept small: a best-first traversal moves these through its heap, and the move is a good
  // part of the cost of a node pair.
  std::uint16_t depth;
  std::uint8_t maskA, maskB;
  double lower;
  double nearness;  // how near the pair looks: the order among equal lower bounds (traverseTrees)
};

/// Where the last query between two meshes found its answer: the triangles of its witnesses.
/// A planner's consecutive queries between the same meshes are near each other, so that pair's
/// distance at the new poses is an upper bound close to the new answer before any node pair is
/// opened (the first upper bound that sec. 6.2's rejection rule starts from). Only a hint:
/// whatever it names is measured anew, and indices out of range are ignored.
struct WitnessHint {
  const Mesh* a = nullptr;
  const Mesh* b = nullptr;
  std::uint32_t triangleA = 0, triangleB = 0;
};

struct DistanceScratch::Buffers {
  // Hints by mesh pair, direct-mapped on the meshes' addresses (a checker queries a robot part
  // against a handful of environment parts in turn; a collision of two pairs costs only a hint).
  static constexpr std::size_t kWitnessHints = 64;
  WitnessHint witnessHints[kWitnessHints];
  WitnessHint& hintFor(const Mesh& a, const Mesh& b) {
    const auto key = reinterpret_cast<std::uintptr_t>(&a) * 31u + reinterpret_cast<std::uintptr_t>(&b);
    return witnessHints[(key >> 4) % kWitnessHints];
  }
  // The traversal's pending node pairs: a stack for validity queries, a heap for the others.
  std::vector<PendingNodePair> pendingNodePairs;
  // Sub-meshes are ranges of these permutations of the triangle indices; the recursion partitions
  // them in place (depth first, so a range holds the same set whenever it is revisited).
  std::vector<std::uint32_t> orderA, orderB;
  // Each sub-mesh's distinct vertices, kept on a stack (a child's list lives while its parent's
  // visit runs): supports scan each vertex once instead of every corner of every triangle.
  std::vector<std::uint32_t> verticesA, verticesB;
  std::vector<std::uint32_t> vertexMarkA, vertexMarkB;  // per vertex: last list it was added to
  std::uint32_t mark = 0;
  // Per vertex, its projection on the current split or slab direction.
  std::vector<double> projectionA, projectionB;
  // Per triangle, its corners' extent along the current split direction.
  std::vector<double> lowA, highA, lowB, highB;
  // Stage two.
  std::vector<SlabTriangle> slabA, slabB;
  std::vector<std::uint32_t> bigA;            // slab A triangles too large to hash
  std::vector<std::uint32_t> bucketStart;     // CSR hash table: bucket -> range of entries
  std::vector<std::uint32_t> bucketEntries;   // slab A indices
  std::vector<std::uint32_t> entryBucket;     // scratch for building the table
  std::vector<std::uint32_t> lastVisitor;     // per slab A triangle: last slab B triangle tested + 1
};

namespace detail {

/// A sub-mesh of a query from scratch: triangles order[t0, t1) and their distinct vertices
/// vertices[v0, v1).
struct SubMesh {
  std::uint32_t t0, t1, v0, v1;
  std::uint32_t triangles() const { return t1 - t0; }
};

class Query {
 public:
  Query(const Mesh& a, const Pose& poseA, const Mesh& b, const Pose& poseB, const DistanceOptions& options,
        DistanceScratch::Buffers& buffers);

  /// Runs RecursiveMinDist (Algorithm 1) on the whole meshes and fills the result.
  DistanceResult run();

 private:
  /// Places B in A's frame (rotationBA_, translationBA_, ...) and sets the roundoff allowance.
  void placeFrames();
  /// A validity query between two meshes with trees whose roots' circumscribed spheres are
  /// farther apart than the threshold (most of a planner's checks far from obstacles): true, with
  /// the result in \p out, decided in the world frame before placeFrames (tree_traversal.cpp).
  bool rootSpheresApart(DistanceResult& out) const;
  DistanceResult finish() const;
  /// The paper's stages from scratch on the whole meshes (Algorithm 1 from the roots).
  void runFromScratch();
  /// Work of the stages from scratch, in units of about a nanosecond each
  /// (tolerance::kScratchWorkPerTriangle): past the budget the query stops (done_) and run()
  /// finishes it on trees.
  void charge(std::uint64_t units) {
    scratchWork_ += units;
    if (scratchWork_ > scratchBudget_) {
      counters_.scratchAbandoned = 1;
      done_ = true;
    }
  }
  /// Offers the distance of the triangles that answered the last query between these meshes
  /// (WitnessHint), when the scratch has them.
  void startFromWitnessHint();
  // --- stage three and the recursion (decomposition.cpp) ---
  void visit(const SubMesh& a, const SubMesh& b, int depth, const Vec3& hint);
  /// Stage three from scratch: the support-plane split of sec. 6.1, then the child pairs.
  void splitAdaptively(const SubMesh& a, const SubMesh& b, int depth, const Vec3& n);
  void testAllPairs(const SubMesh& a, const SubMesh& b);
  // --- queries with hierarchies (tree_traversal.cpp) ---
  /// Over both trees' node pairs, box tests before triangle tests: best first by lower bound
  /// when the query lowers an upper bound; depth first, nearest first, for a threshold query,
  /// which stops at the first triangle pair within the threshold.
  /// Gives up past a budget of node pairs (counters_.treeAbandoned), for run() to finish from
  /// scratch.
  void traverseTrees();
  /// What pairs must be proven farther than (before the roundoff allowance) to be dropped: the
  /// global upper bound of sec. 6.2, or the threshold, cap or tolerance the mode allows.
  double pruneBound() const;
  /// Tests the live triangle pairs of two leaves (bit k of a mask: triangle t0 + k), dropping
  /// those proven farther than `bound` (= limit + roundoff); both fall as the upper bound does.
  void testLeafPair(const MeshHierarchy::Node& na, std::uint32_t maskA, const MeshHierarchy::Node& nb,
                    std::uint32_t maskB, double& limit, double& bound);
  /// Appends the distinct vertices of triangles order[t0, t1) to `list`; returns the sub-mesh.
  static SubMesh collectVertices(const Mesh& mesh, const std::vector<std::uint32_t>& order, std::uint32_t t0,
                                 std::uint32_t t1, std::vector<std::uint32_t>& list,
                                 std::vector<std::uint32_t>& marks, std::uint32_t mark);
  /// Projections of a sub-mesh's vertices on direction n (A frame): into projectionA / projectionB.
  void projectA(const SubMesh& a, const Vec3& n);
  void projectB(const SubMesh& b, const Vec3& n);
  // --- stage two (spatial_hash.cpp) ---
  /// Tests a separated pair by spatial hashing; false when the grid would cull too little for the
  /// pair's size (tolerance::kHashCandidatesPerTriangle): split it then. A stage that started
  /// again with a lower bound (hashRestarts) may decline after testing some pairs; the split
  /// covers them again.
  bool hashStage(const SubMesh& a, const SubMesh& b, const GjkResult& g);
  /// First culling: the triangles of a sub-mesh reaching into the slab, into slabA / slabB.
  void gatherSlabA(const SubMesh& a, const Vec3& ex, const Vec3& ey, const Vec3& ez, double slabLow);
  void gatherSlabB(const SubMesh& b, const Vec3& ex, const Vec3& ey, const Vec3& ez, double slabHigh);
  void testSlabPair(const SlabTriangle& ta, const SlabTriangle& tb);

  // --- supports (eq. 4-5) over a sub-mesh's vertices, in mesh A's frame ---
  SupportPoint supportA(const SubMesh& a, const Vec3& d) const;
  SupportPoint supportB(const SubMesh& b, const Vec3& d) const;
  // --- supports (eq. 4-5) of a tree node's sub-mesh, by branch and bound over its subtree ---
  /// The vertex of node \p node of \p tree (mesh \p mesh) farthest along \p d (mesh frame),
  /// searched from \p warm (a point of the node's, mesh frame); the result names a triangle of
  /// the node's that has it as a corner. With a \p slack > 0, boxes that reach at most that much
  /// beyond the best vertex found are left unopened: the result is then a vertex within
  /// SupportPoint::reachBeyond (<= slack) of the support.
  static SupportPoint nodeSupport(const Mesh& mesh, const MeshHierarchy& tree, std::int32_t node, const Vec3& d,
                                  SupportPoint warm, double slack = 0.0);
  /// Both meshes small and on their hulls' boundaries (MeshHierarchy::onHullBoundary): GJK on
  /// all their vertices, to convergence, and the triangle pair at the hulls' nearest points
  /// (convex_pair.cpp). True when that settles the query (the support planes' gap proves the
  /// pair's distance, or the mode's rule drops the rest); else the upper bound found stays.
  bool settleConvexPair();
  /// Both nodes closed convex components (MeshHierarchy::Node::convexSolid): GJK on them to
  /// convergence, stopping once the pair is proven farther than \p bound, and where the hulls
  /// are apart the triangle pair at their nearest points measured (convex_pair.cpp); every
  /// distance found is offered. Returns the support planes' gap minus the roundoff allowance, a
  /// lower bound of the pair's distance within that allowance of the one measured; -infinity
  /// when the solids touch or one holds the other (the traversal then opens the pair).
  double convexNodesBound(std::int32_t a, std::int32_t b, double bound);
  /// Measures the triangle pair at GJK's nearest hull points \p g.onA, \p g.onB, among triangles
  /// orderA[a0, a1) of A and orderB[b0, b1) of B (a null order: the triangles by index), and
  /// offers its distance.
  void measureAtHullPoints(const GjkResult& g, const std::uint32_t* orderA, std::uint32_t a0, std::uint32_t a1,
                           const std::uint32_t* orderB, std::uint32_t b0, std::uint32_t b1);
  /// GJK on the sub-meshes of tree nodes \p a and \p b (sec. 4), supports by branch and bound
  /// over their subtrees (nodeSupport, each search warmed by the last support point), stopping
  /// when \p stop accepts the lower bound (minus roundoff), at \p relativeGap, or once the
  /// simplex is within \p hopelessBelow of the origin (runGjk); counts the run and offers the
  /// closest support points found.
  /// With a \p slackShare > 0 (and a \p hopelessBelow >= 0), each support search may stop that
  /// share of the room between the pair's least distance found so far and \p hopelessBelow short
  /// of the support (nodeSupport's slack).
  GjkResult gjkOnNodes(std::int32_t a, std::int32_t b, const std::function<bool(double)>& stop, double relativeGap,
                       double hopelessBelow = -std::numeric_limits<double>::infinity(), double slackShare = 0.0);
  /// GJK on the sub-meshes of node pair (a, b) (sec. 4): raises \p lower to the support planes'
  /// margin and offers the closest support points as an upper bound. Stops once the margin proves
  /// the pair farther than \p bound, once the hulls are proven within \p bound (no margin can
  /// then prove it), or after a few iterations. Returns the margin (- roundoff).
  double hullBound(std::int32_t a, std::int32_t b, double bound);
  /// Whether tree nodes \p a (of A) and \p b (of B) hold the triangles of the nearest pair found
  /// so far (best_): their hulls are then at most best_ apart.
  bool holdsBestPair(std::int32_t a, std::int32_t b) const;

  // --- the mode's rules ---
  /// May a pair (of sub-meshes or triangles) whose distance is at least `lowerSafe` be dropped?
  /// Records the bound when it is (for the result's interval).
  bool skip(double lowerSafe);
  /// Exact and capped queries: a pair whose true distance is proven at least this cannot change
  /// the answer beyond the accuracy promised: the best less the roundoff allowance and, once the
  /// best is clear of contact by a few of those, the tie slack (tolerance::kTieSlack). Near 0 the
  /// rule stays the roundoff's alone: pairs of coincident meshes whose bounds round a little above
  /// 0 must still be opened, so that they answer 0 (with the slack, 7.9e-17 of the diagonal in the
  /// stress suite's mesh/coincident family), which a margin of 0 tells from a clearance.
  double exactDropFrom() const {
    return best_ - roundoff_ - (best_ > 4.0 * roundoff_ ? tieSlack_ : 0.0);
  }
  /// The distance below which pairs matter geometrically: the global upper bound of sec. 6.2,
  /// tightened by the threshold or cap where the mode has one.
  double geometricBound() const;
  void offer(const Vec3& onA, const Vec3& onB, double d, std::int64_t featureA, bool vertexA,
             std::int64_t featureB, bool vertexB);
  void offer(const PointPair& pair);

  Vec3 toA(const Vec3& pointOfB) const { return rotationBA_ * pointOfB + translationBA_; }
  /// What a triangle pair's distance may stop at (triangleDistanceUpTo): a validity query's
  /// threshold, as any pair within it decides the query; nothing (-1) for the other modes.
  double enoughDistance() const { return options_.mode == QueryMode::threshold ? options_.threshold : -1.0; }
  /// What a triangle pair's distance matters below (triangleDistanceBelow) on the paths from
  /// scratch: the prune bound with its roundoff allowance once some pair has been measured (those
  /// paths must end with a real distance, so nothing is left out before one), else nothing.
  double triangleCeiling(double limit) const {
    return std::isfinite(best_) ? limit + roundoff_ : std::numeric_limits<double>::infinity();
  }
  /// Accounts for a pair that triangleDistanceBelow found at or beyond \p ceiling, which is
  /// \p limit plus the roundoff allowance: the pair's true distance exceeds \p limit, the lower
  /// bound recorded for the interval (passed, not recovered from the ceiling, which could round
  /// below it).
  void leftOutAbove(double found, double ceiling, double limit) {
    if (!(found < ceiling)) minSkippedLower_ = std::min(minSkippedLower_, limit);
  }

  const Mesh& a_;
  const Mesh& b_;
  // Both trees, or neither (a query from scratch).
  const MeshHierarchy* treeA_ = nullptr;
  const MeshHierarchy* treeB_ = nullptr;
  // The triangle permutations the sub-meshes are ranges of (the trees' or the scratch buffers').
  const std::uint32_t* orderA_ = nullptr;
  const std::uint32_t* orderB_ = nullptr;
  // The caller's poses: a Query lives within one distance() call.
  const Pose& poseA_;
  const Pose& poseB_;
  const DistanceOptions options_;
  DistanceScratch::Buffers& buf_;
  Eigen::Matrix3d rotationBA_;   // B frame -> A frame
  Vec3 translationBA_;
  Eigen::Matrix3d rotationAB_;   // directions from A frame into B frame (transpose)
  double magnitude_ = 0.0;       // largest |coordinate| of either mesh in A's frame
  double roundoff_ = 0.0;        // kBoundSafetyUlps * eps * magnitude_
  double tieSlack_ = 0.0;        // roundoff_, at most kTieSlack * the larger mesh's diagonal (exactDropFrom)

  // The global upper bound (sec. 6.2) and where it is attained (A frame).
  double best_ = std::numeric_limits<double>::infinity();
  Vec3 bestOnA_ = Vec3::Zero(), bestOnB_ = Vec3::Zero();
  std::int64_t bestFeatureA_ = -1, bestFeatureB_ = -1;
  bool bestVertexA_ = false, bestVertexB_ = false;
  // Smallest lower bound of any pair dropped by the mode's rules (tolerance, threshold, cap).
  double minSkippedLower_ = std::numeric_limits<double>::infinity();
  bool done_ = false;  // the answer is settled (offer): within a validity query's threshold, or 0
  std::uint64_t scratchWork_ = 0;
  std::uint64_t scratchBudget_ = std::numeric_limits<std::uint64_t>::max();
  DistanceCounters counters_;
};

}  // namespace detail
}  // namespace adsd
