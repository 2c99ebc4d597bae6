// The public query: validation, the frame set-up, the mode's rules, and the result.

#include "adsd/distance.h"

#include <chrono>
#include <cmath>
#include <memory>
#include <numeric>
#include <string>

#include "adsd/error.h"
#include "adsd/triangle_distance.h"
#include "input_checks.h"
#include "query.h"
#include "triangle_separation.h"

namespace adsd {

const char* toString(DistanceStatus status) {
  switch (status) {
    case DistanceStatus::exact: return "exact";
    case DistanceStatus::withinTolerance: return "within-tolerance";
    case DistanceStatus::aboveThreshold: return "above-threshold";
    case DistanceStatus::withinThreshold: return "within-threshold";
    case DistanceStatus::beyondCap: return "beyond-cap";
  }
  return "unknown";
}

DistanceScratch::DistanceScratch() : buffers_(std::make_unique<Buffers>()) {}
DistanceScratch::Buffers& DistanceScratch::buffers() {
  // A scratch moved from has none; it is usable again, as a moved-from standard container is.
  if (!buffers_) buffers_ = std::make_unique<Buffers>();
  return *buffers_;
}
DistanceScratch::~DistanceScratch() = default;
DistanceScratch::DistanceScratch(DistanceScratch&&) noexcept = default;
DistanceScratch& DistanceScratch::operator=(DistanceScratch&&) noexcept = default;

namespace detail {

namespace {

void validate(const DistanceOptions& o, const Pose& poseA, const Pose& poseB) {
  requireRigidPose(poseA, "A");
  requireRigidPose(poseB, "B");
  switch (o.mode) {
    case QueryMode::exact: break;
    case QueryMode::tolerance:
      if (!(o.absTolerance >= 0.0) || !std::isfinite(o.absTolerance))
        throw InputError("distance query: absTolerance must be finite and >= 0");
      if (!(o.relTolerance >= 0.0) || !std::isfinite(o.relTolerance))
        throw InputError("distance query: relTolerance must be finite and >= 0");
      break;
    case QueryMode::threshold:
      if (!(o.threshold >= 0.0) || !std::isfinite(o.threshold))
        throw InputError("distance query: threshold must be finite and >= 0");
      break;
    case QueryMode::cap:
      if (!(o.cap > 0.0)) throw InputError("distance query: cap must be > 0");
      break;
    default:  // a value cast into the enum: it would have run as an exact query, unasked
      throw InputError("distance query: mode " + std::to_string(static_cast<int>(o.mode)) +
                       " is none of exact, tolerance, threshold and cap");
  }
}

}  // namespace

Query::Query(const Mesh& a, const Pose& poseA, const Mesh& b, const Pose& poseB, const DistanceOptions& options,
             DistanceScratch::Buffers& buffers)
    : a_(a), b_(b), poseA_(poseA), poseB_(poseB), options_(options), buf_(buffers) {}

void Query::placeFrames() {
  // Mesh A's frame is the working frame: A needs no transform, and B's pose relative to A keeps
  // translations that are large but common to both poses out of the arithmetic.
  // A rotation's transpose is its inverse, exactly. A pose is accepted as rigid to
  // tolerance::kPoseOrthonormality, and the transpose of one that far off moves a point p of the
  // frame by that much times |p|: mesh A 1e5 from its frame's origin, R off by 1e-10, was answered
  // 1.0000049 for 0.9999951 (an outside review). Such a rotation is inverted as a matrix instead;
  // what stays is a relative error of that size in the distance, within the promise.
  auto inverseOf = [](const Eigen::Matrix3d& r) -> Eigen::Matrix3d {
    const double deviation = (r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
    if (deviation <= tolerance::kRotationInverseByTranspose) return r.transpose();
    return r.inverse();
  };
  const Eigen::Matrix3d inverseA = inverseOf(poseA_.linear());
  rotationBA_ = inverseA * poseB_.linear();
  translationBA_ = inverseA * (poseB_.translation() - poseA_.translation());
  rotationAB_ = inverseOf(rotationBA_);
  magnitude_ = std::sqrt(3.0) * (a_.maxAbsCoordinate() + b_.maxAbsCoordinate()) + translationBA_.norm();
  roundoff_ = tolerance::kBoundSafetyUlps * tolerance::kEpsilon * magnitude_;
  tieSlack_ = std::min(roundoff_, tolerance::kTieSlack * std::max(a_.diagonal(), b_.diagonal()));
}

namespace {

/// Support mapping (eq. 4-5) of a sub-mesh from scratch: the vertex of list[v0, v1) maximizing d.x.
std::uint32_t scanSupport(const std::vector<Vec3>& vertices, const std::vector<std::uint32_t>& list, std::uint32_t v0,
                          std::uint32_t v1, const Vec3& d) {
  double bestValue = -std::numeric_limits<double>::infinity();
  std::uint32_t bestVertex = list[v0];
  for (std::uint32_t i = v0; i < v1; ++i) {
    const double value = d.dot(vertices[list[i]]);
    if (value > bestValue) {
      bestValue = value;
      bestVertex = list[i];
    }
  }
  return bestVertex;
}

}  // namespace

SupportPoint Query::supportA(const SubMesh& a, const Vec3& d) const {
  const std::vector<Vec3>& vertices = a_.vertices();
  SupportPoint s;
  s.feature = scanSupport(vertices, buf_.verticesA, a.v0, a.v1, d);
  s.point = vertices[s.feature];
  s.isVertex = true;
  return s;
}

SupportPoint Query::supportB(const SubMesh& b, const Vec3& dInA) const {
  // Support in B's own frame with the direction rotated into it: no vertex is transformed but
  // the winner.
  const Vec3 d = rotationAB_ * dInA;
  const std::vector<Vec3>& vertices = b_.vertices();
  SupportPoint s;
  s.feature = scanSupport(vertices, buf_.verticesB, b.v0, b.v1, d);
  s.point = toA(vertices[s.feature]);
  s.isVertex = true;
  return s;
}

SubMesh Query::collectVertices(const Mesh& mesh, const std::vector<std::uint32_t>& order, std::uint32_t t0,
                               std::uint32_t t1, std::vector<std::uint32_t>& list, std::vector<std::uint32_t>& marks,
                               std::uint32_t mark) {
  SubMesh s{t0, t1, static_cast<std::uint32_t>(list.size()), 0};
  for (std::uint32_t i = t0; i < t1; ++i) {
    for (std::uint32_t v : mesh.triangles()[order[i]]) {
      if (marks[v] != mark) {
        marks[v] = mark;
        list.push_back(v);
      }
    }
  }
  s.v1 = static_cast<std::uint32_t>(list.size());
  return s;
}

void Query::projectA(const SubMesh& a, const Vec3& n) {
  const std::vector<Vec3>& vertices = a_.vertices();
  for (std::uint32_t i = a.v0; i < a.v1; ++i) {
    const std::uint32_t v = buf_.verticesA[i];
    buf_.projectionA[v] = n.dot(vertices[v]);
  }
}

void Query::projectB(const SubMesh& b, const Vec3& n) {
  const Vec3 nInB = rotationAB_ * n;
  const double offset = n.dot(translationBA_);
  const std::vector<Vec3>& vertices = b_.vertices();
  for (std::uint32_t i = b.v0; i < b.v1; ++i) {
    const std::uint32_t v = buf_.verticesB[i];
    buf_.projectionB[v] = nInB.dot(vertices[v]) + offset;
  }
}

bool Query::skip(double lowerSafe) {
  bool drop = false;
  switch (options_.mode) {
    // Exact (and capped below the cap): a pair that can be nearer than the best by no more than the
    // roundoff allowance and the tie slack (exactDropFrom) cannot change the answer beyond the
    // accuracy promised (distance.h), and where that allowance outgrows the meshes (posed 1e15 x
    // their size apart) every pair is such a pair: without this, each was opened down to its
    // triangles (cow and bunny 1e15 apart: 21 million triangle pairs, 4 s, for an answer the first
    // pair gave). The tie slack drops the pairs tied with the best (tolerance::kTieSlack).
    case QueryMode::exact: drop = lowerSafe >= exactDropFrom(); break;
    case QueryMode::tolerance:
      // Slack measured on the pair's own lower bound, not on the running best: the running best
      // only falls, and the interval's width must hold for the final one. And never less than an
      // exact query drops (ties, up to rounding): a tolerance of 0 on 20 000 copies of one
      // triangle took 69.6 s where the exact query took none (a code review).
      drop = lowerSafe + std::max(options_.absTolerance, options_.relTolerance * std::max(lowerSafe, 0.0)) >= best_ ||
             lowerSafe >= exactDropFrom();
      break;
    case QueryMode::threshold: drop = lowerSafe > options_.threshold || lowerSafe >= best_; break;
    case QueryMode::cap: drop = lowerSafe >= std::min(exactDropFrom(), options_.cap); break;
  }
  if (drop) minSkippedLower_ = std::min(minSkippedLower_, lowerSafe);
  return drop;
}

double Query::geometricBound() const {
  switch (options_.mode) {
    case QueryMode::threshold: return std::min(best_, options_.threshold);
    case QueryMode::cap: return std::min(best_, options_.cap);
    default: return best_;
  }
}

void Query::offer(const Vec3& onA, const Vec3& onB, double d, std::int64_t featureA, bool vertexA,
                  std::int64_t featureB, bool vertexB) {
  if (!(d < best_)) return;
  best_ = d;
  bestOnA_ = onA;
  bestOnB_ = onB;
  bestFeatureA_ = featureA;
  bestFeatureB_ = featureB;
  bestVertexA_ = vertexA;
  bestVertexB_ = vertexB;
  // Settled: a validity query proven within its threshold, or any query at distance 0 (no pair
  // can be nearer; without this, exact queries between intersecting meshes went on through every
  // pair of overlapping boxes).
  if (best_ <= 0.0 || (options_.mode == QueryMode::threshold && best_ <= options_.threshold)) done_ = true;
}

void Query::offer(const PointPair& pair) {
  offer(pair.a.point, pair.b.point, pair.distance, pair.a.feature, pair.a.isVertex, pair.b.feature, pair.b.isVertex);
}

namespace {

/// A witness found by a whole-mesh vertex scan names a vertex; the result names a triangle.
std::int64_t triangleWithVertex(const Mesh& mesh, std::int64_t vertex) {
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    for (std::uint32_t v : mesh.triangles()[t]) {
      if (v == vertex) return static_cast<std::int64_t>(t);
    }
  }
  return -1;
}

}  // namespace

void Query::startFromWitnessHint() {
  const WitnessHint& hint = buf_.hintFor(a_, b_);
  if (hint.a != &a_ || hint.b != &b_ || hint.triangleA >= a_.triangleCount() || hint.triangleB >= b_.triangleCount()) {
    return;
  }
  const Vec3 p[3] = {a_.corner(hint.triangleA, 0), a_.corner(hint.triangleA, 1), a_.corner(hint.triangleA, 2)};
  const Vec3 q[3] = {toA(b_.corner(hint.triangleB, 0)), toA(b_.corner(hint.triangleB, 1)),
                     toA(b_.corner(hint.triangleB, 2))};
  // A validity query gains from the hint only when its pair is within the threshold (the state
  // is in contact where the last one was); the separating axes rule the other case out cheaply.
  if (options_.mode == QueryMode::threshold && trianglesFartherThan(p, q, options_.threshold + roundoff_)) return;
  const TrianglePairResult t = triangleDistanceUpTo(p[0], p[1], p[2], q[0], q[1], q[2], enoughDistance());
  ++counters_.trianglePairsTested;
  offer(t.pointOnA, t.pointOnB, t.distance, hint.triangleA, false, hint.triangleB, false);
}

DistanceResult Query::run() {
  // A planner checks most states far from the obstacles, where a validity query ends at the
  // roots' spheres: decided before B is placed in A's frame, and before the first upper bound,
  // the witness hint and the traversal's set-up, it costs a fifth less (bench_bands, far band).
  if (options_.mode == QueryMode::threshold && a_.hierarchy() != nullptr && b_.hierarchy() != nullptr) {
    DistanceResult apart;
    if (rootSpheresApart(apart)) return apart;
  }
  placeFrames();
  const std::uint32_t nA = static_cast<std::uint32_t>(a_.triangleCount());
  const std::uint32_t nB = static_cast<std::uint32_t>(b_.triangleCount());
  // A corner of each mesh: the first upper bound. Every query then ends with a real, finite
  // distance, even one whose every pair the bounds dropped unmeasured (tests/stress: "tree
  // threshold: non-finite field").
  offer(a_.corner(0, 0), toA(b_.corner(0, 0)), (a_.corner(0, 0) - toA(b_.corner(0, 0))).norm(), 0, false, 0, false);
  // Remembers where this query's answer lies, for the next query between the same meshes.
  auto remember = [&](const DistanceResult& r) {
    if (r.triangleA >= 0 && r.triangleB >= 0) {
      buf_.hintFor(a_, b_) = WitnessHint{&a_, &b_, static_cast<std::uint32_t>(r.triangleA),
                                         static_cast<std::uint32_t>(r.triangleB)};
    }
    return r;
  };
  // Meshes that are points at the magnitude of the numbers the query works with (posed some 1e14
  // times their size apart, distance.h): every pair of their points is within both diameters
  // (at most 2 sqrt(3) times each mesh's largest coordinate) of the first corners' distance, and
  // that is within the roundoff allowance the answer carries anyway. Where such an allowance is
  // larger than the meshes, the bounds below prove no pair farther than another: the cow and the
  // bunny posed 1e20 apart on the diagonal, B's vertices rounded to a lattice of 3e4 in A's frame,
  // went through all 21 million triangle pairs from scratch (3 s; a 10 000-vertex dragon against
  // itself 82 s, an outside review).
  if (2.0 * std::sqrt(3.0) * (a_.maxAbsCoordinate() + b_.maxAbsCoordinate()) <= roundoff_) {
    return remember(finish());
  }
  if (a_.hierarchy() != nullptr && b_.hierarchy() != nullptr) {
    treeA_ = a_.hierarchy();
    treeB_ = b_.hierarchy();
    orderA_ = treeA_->order().data();
    orderB_ = treeB_->order().data();
    // Rigid meshes with trees: the boxes built once already hold what GJK and the hash grid
    // would work out per query, so every mode runs the box-and-triangle traversal of
    // tree_traversal.cpp (sec. 6.2's rejection rule on node pairs), with GJK kept for node pairs
    // far apart for their size (the hull bound).
    // Two small convex parts (a box robot against box obstacles, one pair at a time in a
    // planner's checker): GJK on their vertices usually settles an exact, cap or tolerance query
    // by itself, with one triangle pair (convex_pair.cpp). A validity query between them ends at
    // the roots of the traversal already.
    if (options_.mode != QueryMode::threshold && treeA_->onHullBoundary() && treeB_->onHullBoundary() &&
        settleConvexPair()) {
      return remember(finish());
    }
    // A validity query on trees measures the hint only once its roots are found near enough
    // (traverseTrees): most such queries end at the roots, for less than one triangle pair.
    if (options_.mode != QueryMode::threshold) startFromWitnessHint();
    if (!done_) traverseTrees();
    if (counters_.treeAbandoned == 0) return remember(finish());
    // Over its budget: the stages from scratch finish the query, from the upper bound found. The
    // bounds of the pairs the traversal dropped still hold (minSkippedLower_).
    treeA_ = treeB_ = nullptr;
    runFromScratch();
    return remember(finish());
  }
  // From scratch, within a budget of about twice what building both trees costs: the paper's bounds
  // can stay loose over thousands of triangle pairs (dragon_res4 against the bunny 2.0 apart:
  // 953 031 pairs tested, 0.44 s, where the trees cost 29 ms to build and 1 ms to query).
  scratchBudget_ = std::max<std::uint64_t>(tolerance::kScratchWorkPerTriangle * (std::uint64_t{nA} + nB),
                                           tolerance::kScratchWorkAtLeast);
  runFromScratch();
  const bool settled = best_ <= 0.0 || (options_.mode == QueryMode::threshold && best_ <= options_.threshold);
  if (settled) counters_.scratchAbandoned = 0;  // the pair that settled it came with the last charge
  if (counters_.scratchAbandoned == 0) return remember(finish());
  // Over it: trees for this query alone (a mesh's own, where it has one) finish it, from the
  // upper bound found; the bounds of the pairs the stages dropped still hold (minSkippedLower_).
  // Trees that cannot tell the triangles apart give up in turn (treeAbandoned), and the stages
  // from scratch then finish without a budget.
  done_ = false;
  scratchBudget_ = std::numeric_limits<std::uint64_t>::max();
  std::unique_ptr<MeshHierarchy> builtA, builtB;
  treeA_ = a_.hierarchy() != nullptr ? a_.hierarchy() : (builtA = std::make_unique<MeshHierarchy>(a_)).get();
  treeB_ = b_.hierarchy() != nullptr ? b_.hierarchy() : (builtB = std::make_unique<MeshHierarchy>(b_)).get();
  orderA_ = treeA_->order().data();
  orderB_ = treeB_->order().data();
  traverseTrees();
  if (counters_.treeAbandoned != 0) {
    treeA_ = treeB_ = nullptr;
    runFromScratch();
  }
  treeA_ = treeB_ = nullptr;
  return remember(finish());
}

void Query::runFromScratch() {
  const std::uint32_t nA = static_cast<std::uint32_t>(a_.triangleCount());
  const std::uint32_t nB = static_cast<std::uint32_t>(b_.triangleCount());
  charge(tolerance::kWorkTrianglePass * (std::uint64_t{nA} + nB));  // the set-up below
  buf_.orderA.resize(nA);
  buf_.orderB.resize(nB);
  std::iota(buf_.orderA.begin(), buf_.orderA.end(), 0u);
  std::iota(buf_.orderB.begin(), buf_.orderB.end(), 0u);
  buf_.lowA.resize(nA);
  buf_.highA.resize(nA);
  buf_.lowB.resize(nB);
  buf_.highB.resize(nB);
  buf_.projectionA.resize(a_.vertices().size());
  buf_.projectionB.resize(b_.vertices().size());
  buf_.verticesA.clear();
  buf_.verticesB.clear();
  if (buf_.vertexMarkA.size() < a_.vertices().size() || buf_.vertexMarkB.size() < b_.vertices().size() ||
      buf_.mark > UINT32_MAX - 4 * (nA + nB)) {
    // A new mesh size, or the marks could wrap during this query: start them afresh.
    buf_.vertexMarkA.assign(std::max(buf_.vertexMarkA.size(), a_.vertices().size()), 0);
    buf_.vertexMarkB.assign(std::max(buf_.vertexMarkB.size(), b_.vertices().size()), 0);
    buf_.mark = 0;
  }
  const SubMesh rootA = collectVertices(a_, buf_.orderA, 0, nA, buf_.verticesA, buf_.vertexMarkA, ++buf_.mark);
  const SubMesh rootB = collectVertices(b_, buf_.orderB, 0, nB, buf_.verticesB, buf_.vertexMarkB, ++buf_.mark);
  orderA_ = buf_.orderA.data();
  orderB_ = buf_.orderB.data();
  startFromWitnessHint();
  // First search vector: from a corner of B to a corner of A (any non-zero guess of a - b).
  if (!done_) visit(rootA, rootB, 0, a_.corner(0, 0) - toA(b_.corner(0, 0)));
}

DistanceResult Query::finish() const {
  DistanceResult r;
  r.counters = counters_;
  r.upper = best_;
  r.distance = best_;
  r.lower = std::max(0.0, std::min(best_, minSkippedLower_));
  r.witnessA = poseA_ * bestOnA_;
  r.witnessB = poseA_ * bestOnB_;
  r.triangleA = bestVertexA_ ? triangleWithVertex(a_, bestFeatureA_) : bestFeatureA_;
  r.triangleB = bestVertexB_ ? triangleWithVertex(b_, bestFeatureB_) : bestFeatureB_;
  switch (options_.mode) {
    case QueryMode::exact:
      r.status = DistanceStatus::exact;
      r.lower = best_;
      break;
    case QueryMode::tolerance:
      r.status = r.lower == r.upper ? DistanceStatus::exact : DistanceStatus::withinTolerance;
      break;
    case QueryMode::threshold:
      if (best_ <= options_.threshold) {
        r.status = DistanceStatus::withinThreshold;
        r.lower = 0.0;  // stopped at the first proof: nothing is known below it
      } else {
        r.status = DistanceStatus::aboveThreshold;
      }
      break;
    case QueryMode::cap:
      if (best_ < options_.cap) {
        r.status = DistanceStatus::exact;
        r.lower = best_;
      } else {
        r.status = DistanceStatus::beyondCap;
        r.lower = options_.cap;
        r.distance = options_.cap;
      }
      break;
  }
  return r;
}

}  // namespace detail

DistanceResult distance(const Mesh& a, const Pose& poseA, const Mesh& b, const Pose& poseB,
                        const DistanceOptions& options, DistanceScratch& scratch) {
  detail::validate(options, poseA, poseB);
  detail::requireTriangles(a);
  detail::requireTriangles(b);
  detail::requireResolvableScene(a, poseA, b, poseB);
  detail::Query query(a, poseA, b, poseB, options, scratch.buffers());
  return query.run();
}

DistanceResult distance(const Mesh& a, const Pose& poseA, const Mesh& b, const Pose& poseB,
                        const DistanceOptions& options) {
  DistanceScratch scratch;
  return distance(a, poseA, b, poseB, options, scratch);
}

}  // namespace adsd
