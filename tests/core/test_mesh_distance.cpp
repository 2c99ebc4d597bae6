/// \file
/// \brief adsd::distance (the paper's RecursiveMinDist) against the brute-force binary128 oracle
/// on random close-proximity poses of generated mesh pairs whose convex hulls overlap (issue 2,
/// "Done when"): exact mode to 1e-10 x the scene's bounding-box diagonal, tolerance intervals that
/// contain the oracle, threshold and cap decisions, symmetry in A and B, invariance under a common
/// rigid motion and under permutations of triangles and corners, no NaN anywhere, and counters
/// showing that recursion (sec. 6) and hashing (sec. 5) really ran.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include "adsd/distance.h"
#include "adsd/error.h"
#include "adsd/mesh_hierarchy.h"
#include "adsd/shapes.h"
#include "oracle.h"
#include "random_geometry.h"

namespace adsd {
namespace {

using oracle::SeededRandom;

using oracle::kPromisedAccuracy;
using oracle::sceneDiagonal;
/// Poses per mesh pair: 4 pairs x 260 = 1040 >= the 1000 of issue 2. Sanitizer builds (about ten
/// times slower) check a tenth of them.
#ifdef ADSD_TESTS_UNDER_SANITIZER
constexpr int kPosesPerPair = 26;
#else
constexpr int kPosesPerPair = 260;
#endif

/// A pair of meshes in a close, hull-overlapping configuration, and how far to perturb it.
struct ScenePair {
  std::string name;
  Mesh a, b;
  Pose nominalB;   ///< B relative to A in the nominal configuration
  double maxShift; ///< random translation of B, per axis, in A's frame (length units)
  double maxAngle; ///< random rotation of B about its own origin (radians)
};

ScenePair interlockedTori() {
  // Two rings linked like a chain: B stands in the xz plane through A's hole. The centre lines
  // keep about 1 apart and the tubes have radius 0.44, leaving a gap of about 0.1 that the
  // perturbation closes in some poses (interpenetration included on purpose: ~7% of them).
  return {"interlocked tori", shapes::torus(1.0, 0.44, 40, 14), shapes::torus(1.0, 0.44, 40, 14),
          Pose(Eigen::Translation3d(1, 0, 0) * Eigen::AngleAxisd(M_PI / 2, Vec3::UnitX())), 0.08, 0.12};
}

ScenePair knotAndStick() {
  // A stick threaded through the trefoil's central hole (the knot's tube comes within 0.75 of
  // the z axis, the stick is 0.6 thick), tilted and shifted.
  return {"knotted tube and stick", shapes::knottedTube(1.0, 0.25, 2, 3, 100, 10), shapes::capsule(0.6, 1.5, 24),
          Pose::Identity(), 0.1, 0.15};
}

ScenePair hookedCShapes() {
  // Two C's hooked into each other like chain links, openings facing away from the contact.
  return {"hooked C-shapes", shapes::cShape(1.0, 0.25, 0.9, 64), shapes::cShape(1.0, 0.25, 0.9, 64),
          Pose(Eigen::Translation3d(-0.4, 0, 0) * Eigen::AngleAxisd(M_PI / 2, Vec3::UnitX())), 0.1, 0.1};
}

ScenePair objectInRoom() {
  // The motion-planning case: a small object (a capsule with a crossbar) in a corner of a room,
  // a few centimetres from two walls and the ceiling.
  const Mesh object = shapes::merge({shapes::capsule(0.2, 0.4, 16), shapes::box(Vec3(0.3, 0.1, 0.1))}, {});
  return {"object in a room", shapes::room(Vec3(2, 1.5, 1), 0.1, 8), object,
          Pose(Eigen::Translation3d(1.6, 1.1, 0.3)), 0.1, 0.1};
}

/// The same surface with vertices, triangles and corners reordered (orientation kept).
Mesh permuted(const Mesh& mesh, SeededRandom& random) {
  const std::size_t n = mesh.vertices().size();
  std::vector<std::uint32_t> newIndex(n);
  std::iota(newIndex.begin(), newIndex.end(), 0u);
  std::shuffle(newIndex.begin(), newIndex.end(), random.engine());
  std::vector<Vec3> vertices(n);
  for (std::size_t i = 0; i < n; ++i) vertices[newIndex[i]] = mesh.vertices()[i];
  std::vector<TriangleIndices> triangles;
  for (const TriangleIndices& t : mesh.triangles()) {
    const int r = int(random.below(3));
    triangles.push_back({newIndex[t[r]], newIndex[t[(r + 1) % 3]], newIndex[t[(r + 2) % 3]]});
  }
  std::shuffle(triangles.begin(), triangles.end(), random.engine());
  return Mesh(std::move(vertices), std::move(triangles), mesh.name() + " (permuted)");
}

std::string describePose(const Pose& pose) {
  std::ostringstream out;
  out.precision(17);
  const Eigen::Quaterniond q(pose.rotation());
  out << "t = (" << pose.translation().x() << ", " << pose.translation().y() << ", " << pose.translation().z()
      << ") q = (" << q.w() << ", " << q.x() << ", " << q.y() << ", " << q.z() << ")";
  return out.str();
}

/// No field of a result is NaN (infinities are legitimate in `upper` for some modes).
::testing::AssertionResult noNaN(const DistanceResult& r) {
  if (std::isnan(r.distance) || std::isnan(r.lower) || std::isnan(r.upper) || r.witnessA.hasNaN() ||
      r.witnessB.hasNaN()) {
    return ::testing::AssertionFailure() << "NaN in result: distance " << r.distance << " [" << r.lower << ", "
                                         << r.upper << "]";
  }
  return ::testing::AssertionSuccess();
}

struct SceneStats {
  int poses = 0, intersecting = 0, posesSplit = 0, failures = 0;
  int maxDepth = 0, gjkMaxIterations = 0;
  std::uint64_t pairsHashed = 0, trianglePairsTested = 0, oraclePairs = 0;
  double worstError = 0, medianDistance = 0;
  std::map<std::string, int> failuresByKind;  ///< "(mode) what" -> count
};

class MeshDistanceAgainstOracle : public ::testing::Test {
 protected:
  /// Runs every check on kPosesPerPair poses of the scene; failures are reported with the
  /// scene, seed, pose index and the exact poses.
  SceneStats run(const ScenePair& scene, std::uint64_t seed) {
    SeededRandom random(seed);
    SceneStats stats;
    Mesh permutedA = permuted(scene.a, random);
    Mesh permutedB = permuted(scene.b, random);
    if (scene.a.hierarchy() != nullptr) permutedA.buildHierarchy();
    if (scene.b.hierarchy() != nullptr) permutedB.buildHierarchy();
    std::vector<double> distances;
    DistanceScratch scratch;

    for (int i = 0; i < kPosesPerPair; ++i) {
      // A common random placement of the whole configuration, and B perturbed around its
      // nominal place in A's frame.
      const Pose world(Eigen::Translation3d(random.inCube(2.0)) * random.rotation());
      const Pose poseA = world;
      const Pose poseB = world * Eigen::Translation3d(random.inCube(scene.maxShift)) * scene.nominalB *
                         Pose(random.smallRotation(scene.maxAngle));
      const oracle::MeshPairDistance o = oracle::meshDistance(scene.a, poseA, scene.b, poseB);
      const double diag = sceneDiagonal(scene.a, poseA, scene.b, poseB);
      const double tol = kPromisedAccuracy * diag;
      // The oracle's distance is the exact minimum up to ~1e-30 x the coordinates, so meshes it
      // finds 1e-9 x diag apart cannot meet; only closer poses need the intersection predicate.
      const bool intersecting = o.value <= 1e-9 * diag && oracle::meshesIntersect(scene.a, poseA, scene.b, poseB);
      std::ostringstream where;
      where << scene.name << " seed " << seed << " pose " << i << "\n  poseA " << describePose(poseA) << "\n  poseB "
            << describePose(poseB) << "\n  oracle " << oracle::toString(o.distance) << " (triangles " << o.triangleA
            << ", " << o.triangleB << "), diagonal " << diag << ", intersecting " << intersecting << "\n  ";
      // Each failure is counted under its kind (the mode and the parenthesized reason); the
      // first three of each kind are reported with the full case.
      auto check = [&](bool ok, const std::string& what) {
        if (ok) return;
        ++stats.failures;
        const std::string kind = what.substr(0, what.find_first_of(" :")) +
                                 (what.rfind('(') != std::string::npos ? " " + what.substr(what.rfind('(')) : "");
        if (stats.failuresByKind[kind]++ < 3) ADD_FAILURE() << where.str() << what;
      };

      // Exact mode, on a scratch without a witness hint, so that the counters below show the
      // traversal or recursion itself; every later query of this pose reuses `scratch`, whose hint
      // names the last answer's triangles (a start the answer must not depend on).
      DistanceScratch cold;
      const DistanceResult exact = distance(scene.a, poseA, scene.b, poseB, DistanceOptions::exactDistance(), cold);
      const double error = std::abs(exact.distance - o.value);
      {
        std::ostringstream got;
        got.precision(17);
        got << "exact: distance " << exact.distance << " [" << exact.lower << ", " << exact.upper << "] status "
            << toString(exact.status) << " error " << error << " > " << tol;
        check(bool(noNaN(exact)), got.str() + " (NaN)");
        check(error <= tol, got.str() + " (error)");
        check(exact.status == DistanceStatus::exact, got.str() + " (status)");
        check(exact.lower == exact.distance && exact.upper == exact.distance, got.str() + " (interval not [d, d])");
        check(intersecting || o.value <= tol || exact.distance > 0, got.str() + " (false contact)");
      }
      checkWitnesses(scene, poseA, poseB, exact, tol, check);
      stats.worstError = std::max(stats.worstError, error / diag);
      stats.maxDepth = std::max(stats.maxDepth, exact.counters.maxDepth);
      stats.gjkMaxIterations = std::max(stats.gjkMaxIterations, exact.counters.gjkMaxIterations);
      stats.pairsHashed += exact.counters.pairsHashed;
      stats.trianglePairsTested += exact.counters.trianglePairsTested;
      stats.posesSplit += exact.counters.pairsSplit > 0;
      stats.oraclePairs += o.trianglePairsEvaluated;

      // Tolerance mode: the interval contains the oracle's distance and is as narrow as asked.
      {
        static constexpr double kTolerances[4][2] = {{1e-3, 0}, {0, 1e-2}, {1e-2, 1e-1}, {1e-6, 1e-6}};
        const double absTol = kTolerances[i % 4][0] * diag, relTol = kTolerances[i % 4][1];
        const DistanceResult r =
            distance(scene.a, poseA, scene.b, poseB, DistanceOptions::withTolerance(absTol, relTol), scratch);
        std::ostringstream got;
        got.precision(17);
        got << "tolerance (abs " << absTol << ", rel " << relTol << "): distance " << r.distance << " [" << r.lower
            << ", " << r.upper << "] status " << toString(r.status);
        check(bool(noNaN(r)), got.str() + " (NaN)");
        check(r.lower <= o.value + tol && o.value - tol <= r.upper, got.str() + " (interval misses the oracle)");
        check(r.upper - r.lower <= std::max(absTol, relTol * r.upper) + tol, got.str() + " (interval too wide)");
        check(r.distance >= o.value - tol && r.distance <= r.upper + tol, got.str() + " (distance outside)");
        check(r.status == DistanceStatus::withinTolerance || r.status == DistanceStatus::exact, got.str() + " (status)");
      }

      // Threshold mode: two margins per pose around the oracle's distance.
      for (int k = 0; k < 2; ++k) {
        static constexpr double kFactors[5] = {0.0, 0.5, 0.97, 1.03, 2.0};
        const double factor = kFactors[(2 * i + k) % 5];
        const double margin = o.value > 0 ? factor * o.value : factor * 1e-3 * diag;
        const DistanceResult r = distance(scene.a, poseA, scene.b, poseB, DistanceOptions::aboveThreshold(margin), scratch);
        std::ostringstream got;
        got.precision(17);
        got << "threshold " << margin << ": distance " << r.distance << " [" << r.lower << ", " << r.upper
            << "] status " << toString(r.status);
        check(bool(noNaN(r)), got.str() + " (NaN)");
        const bool above = r.status == DistanceStatus::aboveThreshold;
        check(above || r.status == DistanceStatus::withinThreshold, got.str() + " (status)");
        if (o.value > margin + tol) check(above, got.str() + " (should be above)");
        if (o.value < margin - tol || (intersecting && margin == 0)) check(!above, got.str() + " (should be within)");
        // distance.h: aboveThreshold means "proven: minimum distance > threshold (lower >= threshold)".
        if (above) check(r.lower >= margin && r.upper > margin, got.str() + " (interval not above the threshold)");
        if (above) check(r.lower <= o.value + tol, got.str() + " (lower above the oracle)");
        if (!above) check(r.upper <= margin && r.distance <= margin, got.str() + " (upper above the threshold)");
        if (!above) check(r.distance >= o.value - tol, got.str() + " (distance below the oracle)");
      }

      // Cap mode: below the cap the exact distance, beyond it only ">= cap".
      {
        const double cap = o.value > 0 ? (i % 2 ? 0.5 : 2.0) * o.value : 1e-3 * diag;
        const DistanceResult r = distance(scene.a, poseA, scene.b, poseB, DistanceOptions::cappedAt(cap), scratch);
        std::ostringstream got;
        got.precision(17);
        got << "cap " << cap << ": distance " << r.distance << " [" << r.lower << ", " << r.upper << "] status "
            << toString(r.status);
        check(bool(noNaN(r)), got.str() + " (NaN)");
        if (o.value < cap - tol) {
          check(r.status == DistanceStatus::exact && std::abs(r.distance - o.value) <= tol, got.str() + " (should be exact)");
        }
        if (o.value > cap + tol) {
          check(r.status == DistanceStatus::beyondCap && r.distance == cap && r.lower == cap, got.str() + " (should be beyond)");
        }
      }

      // Symmetry: B against A.
      {
        const DistanceResult r = distance(scene.b, poseB, scene.a, poseA, DistanceOptions::exactDistance(), scratch);
        std::ostringstream got;
        got.precision(17);
        got << "swapped: distance " << r.distance;
        check(bool(noNaN(r)) && std::abs(r.distance - o.value) <= tol, got.str() + " (error)");
      }

      // A common rigid motion of both meshes (up to 100 diagonals away) changes nothing.
      if (i % 2 == 0) {
        const Pose motion(Eigen::Translation3d(random.unitVector() * random.uniform(0, 100 * diag)) * random.rotation());
        const DistanceResult r =
            distance(scene.a, motion * poseA, scene.b, motion * poseB, DistanceOptions::exactDistance(), scratch);
        std::ostringstream got;
        got.precision(17);
        got << "moved: distance " << r.distance << " after the motion " << describePose(motion);
        check(bool(noNaN(r)) && std::abs(r.distance - o.value) <= tol, got.str() + " (error)");
      }

      // Permuted vertices, triangles and corners change nothing.
      if (i % 4 == 1) {
        const DistanceResult r = distance(permutedA, poseA, permutedB, poseB, DistanceOptions::exactDistance(), scratch);
        std::ostringstream got;
        got.precision(17);
        got << "permuted: distance " << r.distance;
        check(bool(noNaN(r)) && std::abs(r.distance - o.value) <= tol, got.str() + " (error)");
      }

      ++stats.poses;
      stats.intersecting += intersecting;
      distances.push_back(o.value / diag);
    }
    std::nth_element(distances.begin(), distances.begin() + distances.size() / 2, distances.end());
    stats.medianDistance = distances[distances.size() / 2];
    std::printf(
        "%-24s poses %d  intersecting %d  median distance/diagonal %.3g  max error/diagonal %.3g  max depth %d  "
        "poses split %d  pairs hashed %llu  triangle pairs tested %llu (oracle evaluated %llu)  max GJK iterations %d  "
        "failures %d\n",
        scene.name.c_str(), stats.poses, stats.intersecting, stats.medianDistance, stats.worstError, stats.maxDepth,
        stats.posesSplit, (unsigned long long)stats.pairsHashed, (unsigned long long)stats.trianglePairsTested,
        (unsigned long long)stats.oraclePairs, stats.gjkMaxIterations, stats.failures);
    for (const auto& [kind, count] : stats.failuresByKind) std::printf("    failed %-45s %d times\n", kind.c_str(), count);
    return stats;
  }

  /// Witnesses in the world frame, on the reported triangles, realizing the distance.
  template <class Check>
  void checkWitnesses(const ScenePair& scene, const Pose& poseA, const Pose& poseB, const DistanceResult& r,
                      double tol, Check& check) {
    const bool indicesValid = r.triangleA >= 0 && std::size_t(r.triangleA) < scene.a.triangleCount() &&
                              r.triangleB >= 0 && std::size_t(r.triangleB) < scene.b.triangleCount();
    check(indicesValid, "exact: witness triangles " + std::to_string(r.triangleA) + ", " + std::to_string(r.triangleB) +
                            " (triangle index out of range)");
    if (!indicesValid) return;
    const auto ta = oracle::posedTriangle(scene.a, poseA, std::size_t(r.triangleA));
    const auto tb = oracle::posedTriangle(scene.b, poseB, std::size_t(r.triangleB));
    const double offA = double(oracle::pointTriangleDistance(oracle::Quad3(r.witnessA), ta[0], ta[1], ta[2]));
    const double offB = double(oracle::pointTriangleDistance(oracle::Quad3(r.witnessB), tb[0], tb[1], tb[2]));
    const double realized = (r.witnessA - r.witnessB).norm();
    std::ostringstream got;
    got.precision(17);
    got << "exact: witnessA " << offA << " off its triangle, witnessB " << offB << ", |wA - wB| " << realized
        << " vs distance " << r.distance;
    check(offA <= tol && offB <= tol && std::abs(realized - r.distance) <= tol, got.str() + " (witnesses)");
  }

  /// The checks every scene must pass, and what every scene must have exercised.
  /// \p paperStages: the query runs the paper's three stages (from scratch); with trees it runs
  /// the box-and-triangle traversal, which splits and recurses but never hashes.
  static void expectExercised(const SceneStats& s, bool paperStages = true) {
    EXPECT_EQ(s.failures, 0);
    EXPECT_EQ(s.poses, kPosesPerPair);
    // The hulls overlap in every pose (that is what the scenes are for), so the root pair is
    // split every time (sec. 6), and the recursion goes deeper than one level somewhere.
    EXPECT_EQ(s.posesSplit, s.poses);
    EXPECT_GT(s.maxDepth, 1);
    if (paperStages) {
      EXPECT_GT(s.pairsHashed, 0u);
    }
    // Close proximity: most poses separated, by a small fraction of the scene.
    EXPECT_LT(s.intersecting, s.poses / 2);
    EXPECT_LT(s.medianDistance, 0.05);
  }
};

TEST_F(MeshDistanceAgainstOracle, InterlockedTori) { expectExercised(run(interlockedTori(), 201)); }
TEST_F(MeshDistanceAgainstOracle, KnottedTubeAndStick) { expectExercised(run(knotAndStick(), 202)); }
TEST_F(MeshDistanceAgainstOracle, HookedCShapes) { expectExercised(run(hookedCShapes(), 203)); }
TEST_F(MeshDistanceAgainstOracle, ObjectInARoom) { expectExercised(run(objectInRoom(), 204)); }

/// The same scene with both meshes' hierarchies built: queries take the rigid-body path
/// (adsd/mesh_hierarchy.h) and must give the same guarantees.
ScenePair withTrees(ScenePair scene) {
  scene.a.buildHierarchy();
  scene.b.buildHierarchy();
  scene.name += " (trees)";
  return scene;
}

TEST_F(MeshDistanceAgainstOracle, InterlockedToriWithTrees) { expectExercised(run(withTrees(interlockedTori()), 301), false); }
TEST_F(MeshDistanceAgainstOracle, KnottedTubeAndStickWithTrees) { expectExercised(run(withTrees(knotAndStick()), 302), false); }
TEST_F(MeshDistanceAgainstOracle, HookedCShapesWithTrees) { expectExercised(run(withTrees(hookedCShapes()), 303), false); }
TEST_F(MeshDistanceAgainstOracle, ObjectInARoomWithTrees) { expectExercised(run(withTrees(objectInRoom()), 304), false); }

/// Meshes that intersect have distance 0, and no pair can be nearer: every query mode settles
/// there instead of going on through every pair of overlapping sub-meshes. Two copies of one
/// torus in the same place overlap everywhere: thousands of triangle pairs intersect.
TEST(MeshDistance, IntersectingMeshesSettleAtZero) {
  for (const bool trees : {false, true}) {
    Mesh a = shapes::torus(1.0, 0.44, 40, 14);
    Mesh b = a;
    if (trees) {
      a.buildHierarchy();
      b.buildHierarchy();
    }
    const Pose turned(Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()));
    for (const DistanceOptions& options :
         {DistanceOptions::exactDistance(), DistanceOptions::withTolerance(0.0, 0.01), DistanceOptions::cappedAt(1.0)}) {
      SCOPED_TRACE(std::string(trees ? "trees" : "from scratch") + ", mode " +
                   std::to_string(static_cast<int>(options.mode)));
      const DistanceResult r = distance(a, turned, b, turned, options);
      EXPECT_EQ(r.distance, 0.0);
      EXPECT_EQ(r.lower, 0.0);
      EXPECT_EQ(r.upper, 0.0);
      EXPECT_EQ(r.status, DistanceStatus::exact);
      // Settled at the first intersecting pair: a few leaves' worth of triangle pairs, not the
      // thousands that intersect.
      EXPECT_LE(r.counters.trianglePairsTested, 64u) << "triangles per mesh " << a.triangleCount();
    }
  }
}

TEST(MeshDistance, BadOptionsAndPosesAreInputErrors) {
  const Mesh box = shapes::box(Vec3(1, 1, 1));
  const Pose apart(Eigen::Translation3d(3, 0, 0));
  EXPECT_THROW(distance(box, Pose::Identity(), box, apart, DistanceOptions::withTolerance(-1, 0)), InputError);
  EXPECT_THROW(distance(box, Pose::Identity(), box, apart, DistanceOptions::withTolerance(0, -0.1)), InputError);
  EXPECT_THROW(distance(box, Pose::Identity(), box, apart, DistanceOptions::aboveThreshold(NAN)), InputError);
  EXPECT_THROW(distance(box, Pose::Identity(), box, apart, DistanceOptions::cappedAt(0)), InputError);
  Pose broken = apart;
  broken.matrix()(0, 3) = NAN;
  EXPECT_THROW(distance(box, Pose::Identity(), box, broken), InputError);
  // And a plain query on two unit boxes 1 apart.
  const DistanceResult r = distance(box, Pose::Identity(), box, apart);
  EXPECT_NEAR(r.distance, 1.0, 1e-15);
  EXPECT_EQ(r.status, DistanceStatus::exact);
}

/// A scratch remembers the last answer's triangles per mesh pair and starts the next query from
/// their distance (WitnessHint). Along a path of nearby poses, as a planner asks, every mode must
/// answer exactly what a scratch without hints answers, and the hint must save work: fewer node
/// pairs in total than the cold queries (counted, not timed).
TEST(MeshDistance, WitnessHintsChangeNoAnswer) {
  for (const bool trees : {false, true}) {
    Mesh a = shapes::torus(1.0, 0.44, 40, 14);
    Mesh b = shapes::knottedTube(1.0, 0.25, 2, 3, 100, 10);
    if (trees) {
      a.buildHierarchy();
      b.buildHierarchy();
    }
    DistanceScratch warm;
    std::uint64_t warmPairs = 0, coldPairs = 0;
    for (int i = 0; i < 120; ++i) {
      // B circles A at a distance that goes from contact to 1.5 diagonals and back.
      const double angle = 0.02 * i;
      const Pose poseB = Eigen::Translation3d(Vec3(std::cos(angle), std::sin(angle), 0.2) * (2.0 + 2.5 * std::sin(0.05 * i))) *
                         Eigen::AngleAxisd(0.03 * i, Vec3(1, 2, 3).normalized());
      for (const DistanceOptions& options :
           {DistanceOptions::exactDistance(), DistanceOptions::withTolerance(0.0, 0.01), DistanceOptions::cappedAt(1.0),
            DistanceOptions::aboveThreshold(0.05)}) {
        SCOPED_TRACE(std::string(trees ? "trees" : "from scratch") + ", pose " + std::to_string(i) + ", mode " +
                     std::to_string(static_cast<int>(options.mode)));
        DistanceScratch cold;
        const DistanceResult r = distance(a, Pose::Identity(), b, poseB, options, warm);
        const DistanceResult c = distance(a, Pose::Identity(), b, poseB, options, cold);
        EXPECT_EQ(r.status, c.status);
        if (options.mode == QueryMode::exact || r.status == DistanceStatus::exact) {
          EXPECT_NEAR(r.distance, c.distance, 1e-12);
        }
        if (options.mode == QueryMode::tolerance) {
          // Both intervals contain the distance, so they overlap.
          EXPECT_LE(r.lower, c.upper + 1e-12);
          EXPECT_LE(c.lower, r.upper + 1e-12);
        }
        if (options.mode == QueryMode::exact) {
          warmPairs += r.counters.subMeshPairs;
          coldPairs += c.counters.subMeshPairs;
        }
      }
    }
    EXPECT_LT(warmPairs, coldPairs) << (trees ? "trees" : "from scratch");
  }
}

/// A small, finely meshed knot far (1 to 4 length units, beyond its own size) above a large,
/// coarse ring: a leaf of the ring is a few triangles larger than the whole knot. The leaf's box is fat at the knot's
/// scale, so box bounds alone opened the knot's tree down to its leaves against every leaf near
/// it; the leaf against a knot node is bounded by GJK on their hulls (tree_traversal.cpp,
/// worthHullBound), whose near sides seen from afar are surface. Answers against the oracle; the
/// node pairs per query must stay below the knot's leaf count (counts, not times: 264 per query
/// with the hull bound, 1578 with boxes alone).
TEST(MeshDistance, AFineMeshFarFromACoarseOneIsBoundedByHulls) {
  Mesh knot = shapes::knottedTube(0.05, 0.02, 2, 3, 160, 10);
  Mesh ring = shapes::torus(6.0, 2.0, 48, 24);
  knot.buildHierarchy();
  ring.buildHierarchy();
  const std::size_t knotLeaves = (knot.triangleCount() + MeshHierarchy::kLeafTriangles - 1) / MeshHierarchy::kLeafTriangles;
  SeededRandom random(4242);
  const int poses = kPosesPerPair / 10;
  std::uint64_t pairs = 0;
  for (int i = 0; i < poses; ++i) {
    // Above the ring's tube (its top at height 2), 1 to 4 beyond its surface.
    const double angle = random.uniform(0.0, 2.0 * M_PI), lift = 2.0 + random.uniform(1.0, 4.0);
    const Pose poseKnot(Eigen::Translation3d(6.0 * std::cos(angle), 6.0 * std::sin(angle), lift) * random.rotation());
    const oracle::MeshPairDistance truth = oracle::meshDistance(knot, poseKnot, ring, Pose::Identity());
    const double allowed = kPromisedAccuracy * sceneDiagonal(knot, poseKnot, ring, Pose::Identity());
    SCOPED_TRACE("pose " + std::to_string(i) + ", oracle " + std::to_string(truth.value));
    const DistanceResult exact = distance(knot, poseKnot, ring, Pose::Identity(), DistanceOptions::exactDistance());
    ASSERT_EQ(exact.status, DistanceStatus::exact);
    EXPECT_NEAR(exact.distance, truth.value, allowed);
    const DistanceResult swapped = distance(ring, Pose::Identity(), knot, poseKnot, DistanceOptions::exactDistance());
    EXPECT_NEAR(swapped.distance, truth.value, allowed);
    pairs += exact.counters.subMeshPairs + swapped.counters.subMeshPairs;
  }
  const double perQuery = static_cast<double>(pairs) / (2.0 * poses);
  EXPECT_LT(perQuery, static_cast<double>(knotLeaves)) << "node pairs per query, knot of " << knotLeaves << " leaves";
}

/// An open sheet curved like a turbine blade: a third of a cylinder of radius 3 and height 2, a
/// grid of around x up quads (48 x 12 unless asked). Seen from afar, its nodes' boxes all reach
/// about as far as its best vertex, and the hull bound's support searches stop short of the
/// support by a share of the room to the bound, adding what they left unopened to the margin
/// (SupportPoint::reachBeyond). A margin that left it out would drop pairs that hold the answer.
Mesh curvedSheet(int around = 48, int up = 12) {
  std::vector<Vec3> vertices;
  std::vector<TriangleIndices> triangles;
  for (int i = 0; i <= around; ++i) {
    const double angle = (2.0 * M_PI / 3.0) * i / around;
    for (int j = 0; j <= up; ++j) vertices.emplace_back(3.0 * std::cos(angle), 3.0 * std::sin(angle), 2.0 * j / up);
  }
  auto at = [&](int i, int j) { return static_cast<std::uint32_t>(i * (up + 1) + j); };
  for (int i = 0; i < around; ++i) {
    for (int j = 0; j < up; ++j) {
      triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return Mesh(vertices, triangles, "curved sheet");
}

/// The sheet against a torus from near its surface to beyond its size, the torus on either side
/// of the sheet and turned at random: exact answers against the oracle, both ways round, and the
/// hull bound must have run (on trees, GJK runs only there).
TEST(MeshDistance, ACurvedSheetSeenFromAfarKeepsItsAnswerUnderTheHullBound) {
  Mesh sheet = curvedSheet();
  Mesh ring = shapes::torus(0.5, 0.15, 24, 10);
  sheet.buildHierarchy();
  ring.buildHierarchy();
  SeededRandom random(5150);
  const int poses = kPosesPerPair / 10;
  std::uint64_t gjkRuns = 0;
  for (int i = 0; i < poses; ++i) {
    // Beside the sheet, inside or outside the cylinder, its tube 0.15 to 4 from the sheet's surface.
    const double angle = random.uniform(0.3, 1.8), height = random.uniform(0.0, 2.0);
    const double radius = random.uniform(0.0, 1.0) < 0.5 ? random.uniform(3.8, 7.5) : random.uniform(0.2, 2.2);
    const Pose poseRing(Eigen::Translation3d(radius * std::cos(angle), radius * std::sin(angle), height) *
                        random.rotation());
    const oracle::MeshPairDistance truth = oracle::meshDistance(sheet, Pose::Identity(), ring, poseRing);
    const double allowed = kPromisedAccuracy * sceneDiagonal(sheet, Pose::Identity(), ring, poseRing);
    SCOPED_TRACE("pose " + std::to_string(i) + ", oracle " + std::to_string(truth.value));
    const DistanceResult exact = distance(sheet, Pose::Identity(), ring, poseRing, DistanceOptions::exactDistance());
    ASSERT_EQ(exact.status, DistanceStatus::exact);
    EXPECT_NEAR(exact.distance, truth.value, allowed);
    const DistanceResult swapped = distance(ring, poseRing, sheet, Pose::Identity(), DistanceOptions::exactDistance());
    EXPECT_NEAR(swapped.distance, truth.value, allowed);
    gjkRuns += exact.counters.gjkCalls + swapped.counters.gjkCalls;
  }
  EXPECT_GT(gjkRuns, 0u);
}

/// A finer sheet (4608 triangles) facing a finer ball (3120) from 0.2 to 2 away, where the pairs
/// holding the nearest points are hull-bounded level after level (worthHullBound). Their children
/// keep the parent's bound (traverseTrees' `test`), so that those whose hull bound fell just short
/// are not ordered and bounded by their boxes alone again. Exact answers against the oracle; node
/// pairs per query over 26 poses: 385 when children started from their boxes' bound, 315 with the
/// parent's (the CGAL blade against the bull mid range, bench_bands --counters: 260 and 176).
TEST(MeshDistance, ChildrenOfAHullBoundedPairKeepItsBound) {
  Mesh sheet = curvedSheet(96, 24);
  Mesh ball = shapes::sphere(0.4, 40);
  sheet.buildHierarchy();
  ball.buildHierarchy();
  SeededRandom random(2718);
  // The counters are summed over a fixed number of poses; the oracle, slow on 14 million triangle
  // pairs, checks as many as the build affords (a tenth of them under the sanitizers).
  constexpr int kPoses = 26;
  const int checked = std::min(kPoses, kPosesPerPair / 10);
  std::uint64_t nodePairs = 0;
  for (int i = 0; i < kPoses; ++i) {
    // Outside the cylinder, where the sheet bends away from the ball.
    const double angle = random.uniform(0.3, 1.8), height = random.uniform(0.2, 1.8);
    const double radius = 3.0 + 0.4 + random.uniform(0.2, 2.0);
    const Pose poseBall(Eigen::Translation3d(radius * std::cos(angle), radius * std::sin(angle), height) *
                        random.rotation());
    const DistanceResult exact = distance(sheet, Pose::Identity(), ball, poseBall, DistanceOptions::exactDistance());
    ASSERT_EQ(exact.status, DistanceStatus::exact);
    nodePairs += exact.counters.subMeshPairs;
    if (i >= checked) continue;
    const oracle::MeshPairDistance truth = oracle::meshDistance(sheet, Pose::Identity(), ball, poseBall);
    EXPECT_NEAR(exact.distance, truth.value, kPromisedAccuracy * sceneDiagonal(sheet, Pose::Identity(), ball, poseBall))
        << "pose " << i;
  }
  EXPECT_LT(static_cast<double>(nodePairs) / kPoses, 350.0) << "node pairs per query";
}

// Two flat bars crossing at right angles, one above the other, each turned 45 degrees about its
// length: no face axis of either box and not the line through their centres separates them, only
// the cross product of their lengths (z). A validity query tested the roots by their spheres
// alone and went down to the leaves (DRC-Hubo's fingers: 190 node pairs); the roots' box test
// with the edge-edge axes decides it at once, and the threshold on either side of the distance
// still gets its answer.
TEST(MeshDistance, BoxesApartOnlyAlongAnEdgeAxisEndAValidityQueryAtTheRoots) {
  Mesh a = shapes::box(Vec3(1.0, 0.15, 0.025));
  Mesh b = shapes::box(Vec3(0.15, 1.0, 0.025));
  a.buildHierarchy();
  b.buildHierarchy();
  const double turn = M_PI / 4;
  const Pose poseA(Eigen::AngleAxisd(turn, Vec3::UnitX()));
  const Pose poseB(Eigen::Translation3d(0.5, 0.5, 0.35) * Eigen::AngleAxisd(turn, Vec3::UnitY()));
  // Each bar reaches 0.15 sin 45 + 0.025 cos 45 along z from its centre line.
  const double gap = 0.35 - 2.0 * (0.15 + 0.025) * std::sqrt(0.5);
  const oracle::MeshPairDistance truth = oracle::meshDistance(a, poseA, b, poseB);
  EXPECT_NEAR(truth.value, gap, 1e-12);
  const DistanceResult free = distance(a, poseA, b, poseB, DistanceOptions::aboveThreshold(0.0));
  EXPECT_EQ(free.status, DistanceStatus::aboveThreshold);
  EXPECT_EQ(free.counters.subMeshPairs, 1u);
  const DistanceResult justAbove = distance(a, poseA, b, poseB, DistanceOptions::aboveThreshold(gap - 1e-6));
  EXPECT_EQ(justAbove.status, DistanceStatus::aboveThreshold);
  const DistanceResult within = distance(a, poseA, b, poseB, DistanceOptions::aboveThreshold(gap + 1e-6));
  EXPECT_EQ(within.status, DistanceStatus::withinThreshold);
  EXPECT_NEAR(within.distance, truth.value, 1e-12);
}

// A validity query whose roots' spheres are apart by more than the threshold is decided in the
// world frame, before B is placed in A's frame (Query::rootSpheresApart): the answer must be the
// one the traversal gives, a real distance between two mesh points above the threshold with the
// threshold as its lower bound, under a large translation common to both poses as well. Thresholds
// between the spheres' gap and the distance, and beyond it, go on to the traversal and its
// answers.
TEST(MeshDistance, ValidityQueryDecidedAtTheRootSpheresKeepsItsPromises) {
  Mesh a = shapes::knottedTube(1.0, 0.2, 2, 3, 96, 12);
  Mesh b = shapes::torus(1.0, 0.3, 48, 16);
  a.buildHierarchy();
  b.buildHierarchy();
  const double radiusA = a.hierarchy()->nodes()[0].box.radius, radiusB = b.hierarchy()->nodes()[0].box.radius;
  for (const double offset : {0.0, 1e5}) {
    SCOPED_TRACE(offset);
    const Vec3 common(offset, -offset, 0.5 * offset);
    const Pose poseA = Eigen::Translation3d(common) * Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized());
    const Pose poseB = Eigen::Translation3d(common + Vec3(radiusA + radiusB + 0.5, 0.7, -0.2)) *
                       Eigen::AngleAxisd(-1.1, Vec3(0, 1, 1).normalized());
    const Vec3 centreA = poseA * a.hierarchy()->nodes()[0].box.center;
    const Vec3 centreB = poseB * b.hierarchy()->nodes()[0].box.center;
    const double sphereGap = (centreA - centreB).norm() - radiusA - radiusB;
    ASSERT_GT(sphereGap, 0.1);
    const oracle::MeshPairDistance truth = oracle::meshDistance(a, poseA, b, poseB);
    ASSERT_GT(truth.value, sphereGap);
    for (const double threshold : {0.0, 0.5 * sphereGap, 0.999 * sphereGap}) {
      SCOPED_TRACE(threshold);
      const DistanceResult r = distance(a, poseA, b, poseB, DistanceOptions::aboveThreshold(threshold));
      EXPECT_EQ(r.status, DistanceStatus::aboveThreshold);
      EXPECT_EQ(r.lower, threshold);
      EXPECT_EQ(r.counters.subMeshPairs, 1u);
      EXPECT_GE(r.distance, truth.value - kPromisedAccuracy * (1.0 + offset));
      EXPECT_EQ(r.upper, r.distance);
      EXPECT_NEAR(r.distance, (r.witnessA - r.witnessB).norm(), 1e-12 * (1.0 + offset));
      // The witnesses are corners of the triangles named.
      ASSERT_GE(r.triangleA, 0);
      ASSERT_GE(r.triangleB, 0);
      double offA = std::numeric_limits<double>::infinity(), offB = offA;
      for (int k = 0; k < 3; ++k) {
        offA = std::min(offA, (poseA * a.corner(static_cast<std::size_t>(r.triangleA), k) - r.witnessA).norm());
        offB = std::min(offB, (poseB * b.corner(static_cast<std::size_t>(r.triangleB), k) - r.witnessB).norm());
      }
      EXPECT_LE(offA, 1e-12 * (1.0 + offset));
      EXPECT_LE(offB, 1e-12 * (1.0 + offset));
    }
    // Past the spheres' gap the traversal decides, on both sides of the distance.
    const DistanceResult below =
        distance(a, poseA, b, poseB, DistanceOptions::aboveThreshold(0.5 * (sphereGap + truth.value)));
    EXPECT_EQ(below.status, DistanceStatus::aboveThreshold);
    const DistanceResult beyond = distance(a, poseA, b, poseB, DistanceOptions::aboveThreshold(truth.value * 1.001));
    EXPECT_EQ(beyond.status, DistanceStatus::withinThreshold);
    EXPECT_LE(beyond.distance, truth.value * 1.001);
  }
}

// From scratch, a separated pair whose hulls nearly touch while the surfaces are far apart: a ball
// hovering over a wide "C" lying flat, off its centre. The hulls are `gap` apart, the ball is
// metres from the C, so the bounds leave the whole C in the slab and cells as large as it:
// the grid would pair nearly every triangle with every other (the CGAL blade and turbine 10 apart
// took 1.7 s so). The pair is split instead, and its halves' bounds drop most of it.
TEST(MeshDistance, SeparatedPairTheGridCannotCullIsSplitAndStaysExact) {
  const Mesh ring = shapes::cShape(4.0, 0.4, 0.6, 100);
  const Mesh ball = shapes::sphere(0.5, 24);
  const double gap = 0.05;
  const Pose poseA = Eigen::Translation3d(Vec3(0.3, -0.2, 1.0)) * Eigen::AngleAxisd(0.2, Vec3(1, 0, 0));
  const Pose poseB = poseA * Eigen::Translation3d(Vec3(1.2, -0.8, 0.2 + gap + 0.5));
  const oracle::MeshPairDistance truth = oracle::meshDistance(ring, poseA, ball, poseB);
  const double accuracy = kPromisedAccuracy * oracle::sceneDiagonal(ring, poseA, ball, poseB);
  ASSERT_GT(truth.value, 20 * gap);  // the surfaces are far apart for hulls `gap` apart
  DistanceScratch scratch;
  const DistanceResult exact = distance(ring, poseA, ball, poseB, DistanceOptions::exactDistance(), scratch);
  EXPECT_NEAR(exact.distance, truth.value, accuracy);
  EXPECT_NEAR((exact.witnessA - exact.witnessB).norm(), exact.distance, accuracy);
  // Split at the root although GJK separated it, and far fewer triangle pairs than the grid met.
  EXPECT_GE(exact.counters.pairsSplit, 1u);
  EXPECT_GE(exact.counters.maxDepth, 1);
  EXPECT_LT(exact.counters.trianglePairsTested, ring.triangleCount() * ball.triangleCount() / 100);
  // The other modes on the same path keep their promises.
  const DistanceResult tolerant =
      distance(ring, poseA, ball, poseB, DistanceOptions::withTolerance(0.0, 0.01), scratch);
  EXPECT_LE(tolerant.lower, truth.value + accuracy);
  EXPECT_GE(tolerant.upper, truth.value - accuracy);
  EXPECT_LE(tolerant.upper - tolerant.lower, 0.01 * tolerant.upper + accuracy);
  EXPECT_EQ(distance(ring, poseA, ball, poseB, DistanceOptions::aboveThreshold(0.99 * truth.value), scratch).status,
            DistanceStatus::aboveThreshold);
  EXPECT_EQ(distance(ring, poseA, ball, poseB, DistanceOptions::aboveThreshold(1.01 * truth.value), scratch).status,
            DistanceStatus::withinThreshold);
  const DistanceResult capped =
      distance(ring, poseA, ball, poseB, DistanceOptions::cappedAt(0.5 * truth.value), scratch);
  EXPECT_EQ(capped.status, DistanceStatus::beyondCap);
}

}  // namespace
// Meshes posed 1e15 and 1e20 times their size apart (on an axis and a plane, and on the diagonal
// with both poses far out): the roundoff allowance of the numbers the
// query works with (64 eps M, distance.h) is larger than the meshes, so any triangle pair is the
// answer within the promised accuracy, and the query stops at the first. It went through every
// pair instead, none of them provably farther than another (the CGAL cow and bunny 1e15 apart:
// 21 million triangle pairs, 4 s; a 2-million-triangle terrain 1e16 from the cow did not end).
TEST(MeshDistance, MeshesFarApartForTheirSizeAreAnsweredAtOnce) {
  const Mesh ring = shapes::cShape(4.0, 0.4, 0.6, 30);
  const Mesh ball = shapes::sphere(0.5, 12);
  Mesh ringWithTree = ring, ballWithTree = ball;
  ringWithTree.buildHierarchy();
  ballWithTree.buildHierarchy();
  for (const double apart : {1e15, 1e20, -1e15, -1e20}) {
    // Negative: both poses far out, on opposite ends of the diagonal, where B's vertices in A's
    // frame round to a lattice of ulp(2e20) in every coordinate (all pairs measured, an outside
    // review), where on one axis they kept their shape across the other two.
    const Vec3 offsetA = apart > 0 ? Vec3(0.3, -0.2, 1.0) : Vec3::Constant(-apart);
    const Vec3 offsetB = apart > 0 ? Vec3(apart, 0.5 * apart, 0.0) : Vec3::Constant(apart);
    const Pose poseA = Eigen::Translation3d(offsetA) * Eigen::AngleAxisd(0.2, Vec3(1, 0, 0));
    const Pose poseB = Eigen::Translation3d(offsetB) * Eigen::AngleAxisd(1.0, Vec3(0, 1, 0));
    const oracle::MeshPairDistance truth = oracle::meshDistance(ring, poseA, ball, poseB);
    const double accuracy = kPromisedAccuracy * oracle::sceneDiagonal(ring, poseA, ball, poseB);
    // Without the stop, every one of these pairs was measured.
    ASSERT_GT(ring.triangleCount() * ball.triangleCount(), 10000u);
    for (const bool trees : {false, true}) {
      SCOPED_TRACE(std::string(trees ? "trees, " : "from scratch, ") + std::to_string(apart));
      for (const DistanceOptions& options :
           {DistanceOptions::exactDistance(), DistanceOptions::cappedAt(4 * std::abs(apart))}) {
        const DistanceResult r = trees ? distance(ringWithTree, poseA, ballWithTree, poseB, options)
                                       : distance(ring, poseA, ball, poseB, options);
        EXPECT_NEAR(r.distance, truth.value, accuracy);
        EXPECT_EQ(r.status, DistanceStatus::exact);
        EXPECT_LT(r.counters.trianglePairsTested, 100u);
      }
    }
  }
}

/// Two parallel triangles s across, their corners s and 2 s along the axes: s / sqrt(3) apart.
/// At s = 1e-55 the face test's sixth power of lengths underflowed to 0, and 0 >= 0 proved the
/// nearer face farther than it is: the answer was s, 73 % too far (triangle_distance.cpp,
/// faceFartherThan). The scales answered: since scenes below tolerance::kMinSceneMagnitude (1e-40)
/// are refused (InputBoundary.ScenesTooSmallToResolveAreRefused), 1e-40 is the smallest.
TEST(MeshDistance, TinyParallelTrianglesKeepTheirFaceDistance) {
  for (const double s : {1.0, 1e-20, 1e-30, 1e-40}) {
    SCOPED_TRACE(s);
    const std::vector<Vec3> corners = {Vec3(s, 0, 0), Vec3(0, s, 0), Vec3(0, 0, s)};
    const Mesh a(corners, {{0, 1, 2}}, "a");
    const Mesh b({2.0 * corners[0], 2.0 * corners[1], 2.0 * corners[2]}, {{0, 1, 2}}, "b");
    const DistanceResult r = distance(a, Pose::Identity(), b, Pose::Identity(), DistanceOptions::exactDistance());
    EXPECT_NEAR(r.distance, s / std::sqrt(3.0), 1e-12 * s);
  }
}

/// Trees that cannot tell triangles apart: 3000 copies of one triangle (the API keeps repeats),
/// each corner raised or lowered by up to 1e-6, against 3000 such copies 1e-3 above it. Every
/// leaf's box is nearly the same, so the traversal's work grew with the product of the counts (an
/// outside review: 20 000 copies took 9.9 s per query, where the stages from scratch answered in
/// milliseconds). Past its budget the traversal hands the query to the stages from scratch: the
/// answer is the same, exact, and the work stays within the budget plus the pass from scratch.
/// (Exact copies tie, and the tie slack drops them: tolerance::kTieSlack. Here the highest copies
/// are some 2e-6 / 3000 apart, ten thousand times that slack, about 5e-14 in this scene.)
TEST(MeshDistance, AStackOfCopiesOfOneTriangleIsFinishedFromScratch) {
  const std::uint32_t copies = 3000;
  std::vector<Vec3> below, above;
  std::vector<TriangleIndices> triangles;
  SeededRandom random(1009);
  // Two copies over the same triangle are nearest at a corner, where their heights differ least
  // (their difference is affine over the triangle), and tilted by 1e-6 they are that far apart to
  // within 1e-15: the answer is the least over the corners of the highest below and lowest above.
  double highestBelow[3] = {-1.0, -1.0, -1.0}, lowestAbove[3] = {1.0, 1.0, 1.0};
  for (std::uint32_t i = 0; i < copies; ++i) {
    int k = 0;
    for (const Vec3& corner : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}) {
      const double down = random.uniform(-1e-6, 1e-6), up = 1e-3 + random.uniform(-1e-6, 1e-6);
      below.push_back(corner + Vec3(0, 0, down));
      above.push_back(corner + Vec3(0, 0, up));
      highestBelow[k] = std::max(highestBelow[k], down);
      lowestAbove[k] = std::min(lowestAbove[k], up);
      ++k;
    }
    triangles.push_back({3 * i, 3 * i + 1, 3 * i + 2});
  }
  double expected = 1.0;
  for (int k = 0; k < 3; ++k) expected = std::min(expected, lowestAbove[k] - highestBelow[k]);
  Mesh a(below, triangles, "below"), b(above, triangles, "above");
  const double allowed = kPromisedAccuracy * sceneDiagonal(a, Pose::Identity(), b, Pose::Identity()) + 1e-15;
  const DistanceResult scratch = distance(a, Pose::Identity(), b, Pose::Identity());
  EXPECT_NEAR(scratch.distance, expected, allowed);
  a.buildHierarchy();
  b.buildHierarchy();
  for (const DistanceOptions& options : {DistanceOptions::exactDistance(), DistanceOptions::cappedAt(0.5)}) {
    const DistanceResult r = distance(a, Pose::Identity(), b, Pose::Identity(), options);
    EXPECT_NEAR(r.distance, expected, allowed);
    EXPECT_EQ(r.status, DistanceStatus::exact);
    EXPECT_EQ(r.counters.treeAbandoned, 1);
    // The budget (8 node pairs per triangle) and what the pass from scratch adds; without the
    // budget the traversal went on to over a million.
    EXPECT_LT(r.counters.subMeshPairs, 8u * 2 * copies + 2 * scratch.counters.subMeshPairs + 16);
  }
  // A 1 % tolerance accepts the first pair: every other is within 1 % of it.
  const DistanceResult t = distance(a, Pose::Identity(), b, Pose::Identity(), DistanceOptions::withTolerance(0, 0.01));
  EXPECT_NEAR(t.distance, expected, 0.01 * expected);
  EXPECT_LE(t.lower, expected + 1e-15);
  EXPECT_EQ(t.counters.treeAbandoned, 0);
  // A validity query between them ends at the roots' boxes, well within its budget.
  const DistanceResult v = distance(a, Pose::Identity(), b, Pose::Identity(), DistanceOptions::aboveThreshold(5e-4));
  EXPECT_EQ(v.status, DistanceStatus::aboveThreshold);
  EXPECT_EQ(v.counters.treeAbandoned, 0);
}

// Refit (Mesh::setVertices on a mesh with a tree) fits every node's box to its own vertices, as
// the build does: a deformation and its reversal leave the built boxes, and queries on them open
// the same node pairs. Fitted to its children's box corners, every level's box grew (an outside
// review: the cow against the bunny opened 6 times the node pairs after a setVertices of the
// vertices it already had).
TEST(MeshHierarchy, ARefitToTheBuiltVerticesGivesTheBuiltBoxes) {
  Mesh knot = shapes::knottedTube(1.0, 0.15, 2, 3, 160, 12);
  Mesh ball = shapes::sphere(0.3, 24);
  knot.buildHierarchy();
  ball.buildHierarchy();
  const std::vector<Vec3> built = knot.vertices();
  const std::vector<MeshHierarchy::Node> builtNodes = knot.hierarchy()->nodes();
  const Pose poseBall(Eigen::Translation3d(0.4, 1.9, 0.3));
  const DistanceResult before = distance(knot, Pose::Identity(), ball, poseBall, DistanceOptions::exactDistance());
  std::vector<Vec3> bent = built;
  for (Vec3& v : bent) v.z() += 0.3 * std::sin(2.0 * v.x());
  knot.setVertices(bent);
  knot.setVertices(built);
  const std::vector<MeshHierarchy::Node>& nodes = knot.hierarchy()->nodes();
  ASSERT_EQ(nodes.size(), builtNodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    EXPECT_EQ(nodes[i].box.center, builtNodes[i].box.center) << "node " << i;
    EXPECT_EQ(nodes[i].box.half, builtNodes[i].box.half) << "node " << i;
  }
  const DistanceResult after = distance(knot, Pose::Identity(), ball, poseBall, DistanceOptions::exactDistance());
  EXPECT_EQ(after.distance, before.distance);
  EXPECT_EQ(after.counters.subMeshPairs, before.counters.subMeshPairs);
}

/// A square grid of 2 n^2 triangles spanning \p side x \p side from \p origin, in the plane of
/// the unit vectors \p u and \p v.
Mesh gridSquare(const Vec3& origin, const Vec3& u, const Vec3& v, double side, int n, const std::string& name) {
  std::vector<Vec3> vertices;
  std::vector<TriangleIndices> triangles;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) vertices.push_back(origin + side * (u * i + v * j) / n);
  }
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const auto a = static_cast<std::uint32_t>(i * (n + 1) + j), b = a + 1;
      const auto c = a + static_cast<std::uint32_t>(n + 1), d = c + 1;
      triangles.push_back({a, b, d});
      triangles.push_back({a, d, c});
    }
  }
  return Mesh(std::move(vertices), std::move(triangles), name);
}

// Two fine flat sheets overlapping in one plane (a part lying on a table, both meshed as
// surfaces): every pair of their overlapping boxes has a lower bound of 0, and best first took
// those ties by their estimate alone, across the whole sheet, before a first pair of leaves could
// show the distance 0 (an outside review: 53 443 node pairs, 16 ms, for sheets of 80 000 and
// 65 000 triangles, against FCL's 0.4 ms). Among pairs whose boxes overlap the deeper goes first,
// so the query reaches leaves at once; on real meshes this changed the node pairs of exact queries
// near contact by at most 3 % (bench_bands --counters, touching to mid range).
TEST(MeshDistance, OverlappingSheetsInOnePlaneReachTheirLeavesAtOnce) {
  const Vec3 x(1, 0, 0), y(0, 1, 0);
  Mesh a = gridSquare(Vec3(0, 0, 0), x, y, 1.0, 100, "sheet a");
  Mesh b = gridSquare(Vec3(0, 0, 0), x, y, 1.0, 90, "sheet b");
  a.buildHierarchy();
  b.buildHierarchy();
  for (const Vec3& shift : {Vec3(0.003, 0.0021, 0), Vec3(0.25, -0.4, 0), Vec3(-0.5, 0.5, 0)}) {
    const DistanceResult r =
        distance(a, Pose::Identity(), b, Pose(Eigen::Translation3d(shift)), DistanceOptions::exactDistance());
    EXPECT_EQ(r.status, DistanceStatus::exact);
    EXPECT_EQ(r.distance, 0.0);
    EXPECT_LT(r.counters.subMeshPairs, 500u) << "shift " << shift.transpose();
    std::printf("[overlapping sheets] shift (%g, %g): %llu node pairs\n", shift.x(), shift.y(),
                static_cast<unsigned long long>(r.counters.subMeshPairs));
  }
}

// A finely meshed block resting flat above a finely meshed plate: every triangle of its bottom is
// at the same distance from the plate, so the bounds of those pairs tie with the best distance
// found up to a few ulps, and before tolerance::kTieSlack an exact query opened them (an outside
// review: 104 000 node pairs, 20 ms, for a block of 43 200 triangles on a plate of 180 000; 1 200
// tilted by 0.05 rad). Both paths, against the distance the placement gives. A tolerance of 0
// drops them too: it never drops less than an exact query (a code review: 69.6 s on 20 000 copies
// of one triangle, where the exact query took none); its interval holds the distance, as wide as
// the rounding allowance at most.
TEST(MeshDistance, AFlatBlockOnAPlateIsNotOpenedForItsTies) {
  const Vec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1), o(0, 0, 0);
  constexpr int kSide = 16;
  std::vector<Mesh> faces = {gridSquare(o, y, x, 1.0, kSide, "bottom"), gridSquare(z, x, y, 1.0, kSide, "top"),
                             gridSquare(o, x, z, 1.0, kSide, "front"), gridSquare(y, z, x, 1.0, kSide, "back"),
                             gridSquare(o, z, y, 1.0, kSide, "left"), gridSquare(x, y, z, 1.0, kSide, "right")};
  Mesh block = shapes::merge(faces, std::vector<Pose>(faces.size(), Pose::Identity()));
  Mesh plate = gridSquare(Vec3(-2, -2, 0), x, y, 5.0, 120, "plate");
  const double gap = 1e-3;
  const Pose onPlate(Eigen::Translation3d(0.013, 0.021, gap));
  const DistanceResult scratch = distance(block, onPlate, plate, Pose::Identity(), DistanceOptions::exactDistance());
  block.buildHierarchy();
  plate.buildHierarchy();
  const DistanceResult trees = distance(block, onPlate, plate, Pose::Identity(), DistanceOptions::exactDistance());
  const DistanceResult capped = distance(block, onPlate, plate, Pose::Identity(), DistanceOptions::cappedAt(0.1));
  for (const DistanceResult* r : {&scratch, &trees, &capped}) {
    EXPECT_EQ(r->status, DistanceStatus::exact);
    EXPECT_NEAR(r->distance, gap, 1e-15);
  }
  const DistanceResult zero = distance(block, onPlate, plate, Pose::Identity(), DistanceOptions::withTolerance(0, 0));
  EXPECT_NEAR(zero.upper, gap, 1e-15);
  EXPECT_LE(zero.lower, gap + 1e-15);
  EXPECT_GE(zero.lower, gap - 1e-12);
  EXPECT_EQ(trees.counters.treeAbandoned, 0);
  EXPECT_LT(trees.counters.subMeshPairs, 3000u);
  EXPECT_LT(capped.counters.subMeshPairs, 3000u);
  EXPECT_LT(zero.counters.subMeshPairs, 3000u);
  EXPECT_LT(scratch.counters.trianglePairsTested, 100u);
  std::printf("[flat block on a plate] node pairs: trees %llu, capped %llu, tolerance 0 %llu; from scratch %llu "
              "triangle pairs\n",
              static_cast<unsigned long long>(trees.counters.subMeshPairs),
              static_cast<unsigned long long>(capped.counters.subMeshPairs),
              static_cast<unsigned long long>(zero.counters.subMeshPairs),
              static_cast<unsigned long long>(scratch.counters.trianglePairsTested));
}

/// A query from scratch whose bounds cannot drop its triangle pairs: a knot 0.3 across inside a
/// sphere shell of radius 1, every pair of their triangles within 0.3 of the answer, so the
/// stages' GJK bounds and slabs keep thousands of pairs at every level. Without a budget the
/// stages tested 65 361 to 140 361 triangle pairs (27 to 52 ms); with it they stop at about twice
/// what building both trees costs and trees built for the query finish it (26 461 to 29 280 pairs,
/// 15 to 28 ms). The answers are the oracle's in every mode.
TEST(MeshDistance, AQueryFromScratchOverItsBudgetIsFinishedOnTreesBuiltForIt) {
  const Mesh knot = shapes::knottedTube(0.05, 0.015, 2, 3, 96, 8);
  const Mesh shell = shapes::sphere(1.0, 32);
  for (double offset : {0.0, 0.1, 0.3}) {
    Pose pose = Pose::Identity();
    pose.translation() = Vec3(0.03, 0.02, offset);
    const double expected = oracle::meshDistance(knot, Pose::Identity(), shell, pose).value;
    const double allowed = kPromisedAccuracy * sceneDiagonal(knot, Pose::Identity(), shell, pose);
    SCOPED_TRACE("offset " + std::to_string(offset) + ", oracle " + std::to_string(expected));
    const DistanceResult exact = distance(knot, Pose::Identity(), shell, pose);
    EXPECT_NEAR(exact.distance, expected, allowed);
    EXPECT_EQ(exact.status, DistanceStatus::exact);
    EXPECT_EQ(exact.counters.scratchAbandoned, 1);
    EXPECT_LT(exact.counters.trianglePairsTested, 40000u);
    const DistanceResult capped = distance(knot, Pose::Identity(), shell, pose, DistanceOptions::cappedAt(0.7));
    EXPECT_EQ(capped.status, expected < 0.7 ? DistanceStatus::exact : DistanceStatus::beyondCap);
    if (expected < 0.7) {
      EXPECT_NEAR(capped.distance, expected, allowed);
    }
    const DistanceResult tolerant =
        distance(knot, Pose::Identity(), shell, pose, DistanceOptions::withTolerance(0, 0.01));
    EXPECT_LE(tolerant.lower, expected + allowed);
    EXPECT_GE(tolerant.upper, expected - allowed);
    EXPECT_LE(tolerant.upper, 1.01 * expected + allowed);
    for (double threshold : {expected - 1e-6, expected + 1e-6}) {
      const DistanceResult valid =
          distance(knot, Pose::Identity(), shell, pose, DistanceOptions::aboveThreshold(threshold));
      EXPECT_EQ(valid.status, expected > threshold ? DistanceStatus::aboveThreshold : DistanceStatus::withinThreshold);
    }
  }
}

/// A triangle 2e4 across beside a small knot, and another knot 23 above its plane: GJK's upper
/// bound comes from the big triangle's corners (hundreds away), so the first slab and cells held
/// both knots whole; the first B triangle tested found the plane 23 away, and every B triangle
/// then met every A triangle in one cell (the cow in place of the knot: 33 million box tests,
/// 0.4 s, an outside review). The stage starts again with the bound it found.
TEST(MeshDistance, AHashingStageStartsAgainWithTheBoundItFound) {
  const Mesh knot = shapes::knottedTube(0.2, 0.06, 2, 3, 240, 12);
  const Mesh giant({Vec3(-1e4, -1e4, -3), Vec3(1e4, -1e4, -3), Vec3(0, 1e4, -3)}, {{0, 1, 2}}, "giant");
  const Mesh a = shapes::merge({knot, giant}, {});
  Pose pose = Pose::Identity();
  pose.translation() = Vec3(-70, 174, 20);
  const double expected = oracle::meshDistance(a, Pose::Identity(), knot, pose).value;
  const DistanceResult r = distance(a, Pose::Identity(), knot, pose);
  EXPECT_NEAR(r.distance, expected, kPromisedAccuracy * sceneDiagonal(a, Pose::Identity(), knot, pose));
  EXPECT_GE(r.counters.hashRestarts, 1u);
}

}  // namespace adsd
