/// \file
/// \brief Meshes made of several parts (an environment of box obstacles given as one mesh): the
/// tree keeps each connected component whole in one node, flags the closed convex ones
/// (MeshHierarchy::Node::convexSolid), and queries settle a pair of such nodes by GJK and one
/// triangle pair (convex_pair.cpp, convexNodesBound). Checked against the brute-force binary128
/// oracle at uniform poses over the environment (in contact, near, far), in the exact, cap and
/// tolerance modes, before and after a deformation dents one of the solids; a convex solid
/// against the leaves of meshes that are not, in every mode and in validity queries near contact.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "adsd/distance.h"
#include "adsd/mesh_hierarchy.h"
#include "adsd/shapes.h"
#include "open_box.h"
#include "oracle.h"
#include "random_geometry.h"

namespace adsd {
namespace {

using oracle::kPromisedAccuracy;
using oracle::sceneDiagonal;
using oracle::SeededRandom;

#ifdef ADSD_TESTS_UNDER_SANITIZER
constexpr int kPoses = 15;
#else
constexpr int kPoses = 150;
#endif

using testing::openBox;

Pose at(double x, double y, double z, double angle = 0.0) {
  return Pose(Eigen::Translation3d(x, y, z) * Eigen::AngleAxisd(angle, Vec3(1, 2, 3).normalized()));
}

/// An environment of nine parts in one mesh: six boxes of different sizes and turns, a round
/// solid, an open box and a torus (neither convex solids), and their component sizes in order.
struct Environment {
  Mesh mesh;
  std::vector<std::size_t> partTriangles;
  std::vector<bool> partIsConvexSolid;
};

Environment environment() {
  const std::vector<Mesh> parts = {shapes::box(Vec3(0.5, 0.5, 0.5)),   shapes::box(Vec3(2.0, 0.1, 1.0)),
                                   shapes::box(Vec3(0.3, 0.8, 0.2)),   shapes::box(Vec3(0.1, 0.1, 1.5)),
                                   shapes::box(Vec3(1.0, 1.0, 0.05)),  shapes::box(Vec3(0.4, 0.2, 0.6)),
                                   shapes::sphere(0.6, 8),             openBox(0.5),
                                   shapes::torus(0.8, 0.2, 10, 6)};
  const std::vector<Pose> poses = {at(0, 0, 0),      at(3, 1, 0, 0.3), at(-2, 2, 1, 1.1), at(1, -3, 0, 0.7),
                                   at(-3, -2, 0, 2.0), at(2, 3, 2, -0.4), at(0, 2.5, -1.5), at(-1, -1, 2.5, 0.5),
                                   at(3, -1, 2, 0.9)};
  Environment e{shapes::merge(parts, poses), {}, {}};
  for (std::size_t i = 0; i < parts.size(); ++i) {
    e.partTriangles.push_back(parts[i].triangleCount());
    e.partIsConvexSolid.push_back(i < 7);
  }
  e.mesh.buildHierarchy();
  return e;
}

/// The parts' triangles are ranges of the merged mesh, in order.
std::vector<std::size_t> partOfTriangles(const Environment& e) {
  std::vector<std::size_t> part;
  for (std::size_t i = 0; i < e.partTriangles.size(); ++i) part.insert(part.end(), e.partTriangles[i], i);
  return part;
}

TEST(ConvexComponents, EveryPartIsOneNodeAndOnlyClosedConvexOnesAreSolids) {
  const Environment e = environment();
  const MeshHierarchy& tree = *e.mesh.hierarchy();
  const std::vector<std::size_t> part = partOfTriangles(e);
  std::vector<int> wholeNodes(e.partTriangles.size(), 0), solidNodes(e.partTriangles.size(), 0);
  for (const MeshHierarchy::Node& n : tree.nodes()) {
    const std::size_t first = part[tree.order()[n.t0]];
    const bool onePart = std::all_of(tree.order().begin() + n.t0, tree.order().begin() + n.t1,
                                     [&](std::uint32_t t) { return part[t] == first; });
    const bool wholePart = onePart && n.t1 - n.t0 == e.partTriangles[first];
    EXPECT_EQ(n.span == MeshHierarchy::ComponentSpan::whole, wholePart) << "node " << n.t0 << ".." << n.t1;
    EXPECT_EQ(n.span == MeshHierarchy::ComponentSpan::several, !onePart) << "node " << n.t0 << ".." << n.t1;
    if (!wholePart) {
      EXPECT_EQ(n.convexSolid, 0) << "node " << n.t0 << ".." << n.t1;
      continue;
    }
    ++wholeNodes[first];
    solidNodes[first] += n.convexSolid;
  }
  for (std::size_t i = 0; i < e.partTriangles.size(); ++i) {
    EXPECT_EQ(wholeNodes[i], 1) << "part " << i << " is not one node";
    EXPECT_EQ(solidNodes[i], e.partIsConvexSolid[i] ? 1 : 0) << "part " << i;
  }
}

struct Robot {
  std::string name;
  Mesh mesh;
};

std::vector<Robot> robots() {
  std::vector<Robot> r = {{"box", shapes::box(Vec3(0.4, 0.25, 0.15))},
                          {"round", shapes::sphere(0.3, 8)},
                          {"C shape", shapes::cShape(0.4, 0.1, 0.9, 10)},
                          {"two boxes", shapes::merge({shapes::box(Vec3(0.2, 0.2, 0.2)), shapes::box(Vec3(0.1, 0.5, 0.1))},
                                                      {at(0, 0, 0), at(0.6, 0, 0, 0.4)})}};
  for (Robot& robot : r) robot.mesh.buildHierarchy();
  return r;
}

/// Exact, cap and 1 % tolerance queries at uniform poses over the environment's box, the
/// robot's too (one in eight in contact or nearly), against the oracle; \p gjkSettled counts the
/// exact queries that ran GJK on node pairs.
void expectOracleAnswers(const Mesh& env, const Robot& robot, SeededRandom& random, int& gjkSettled) {
  const Eigen::AlignedBox3d region = env.bounds();
  for (int i = 0; i < kPoses; ++i) {
    const Vec3 place(random.uniform(region.min().x(), region.max().x()), random.uniform(region.min().y(), region.max().y()),
                     random.uniform(region.min().z(), region.max().z()));
    const Pose poseRobot(Eigen::Translation3d(place) * random.rotation());
    const Pose poseEnv = Pose::Identity();
    const oracle::MeshPairDistance truth = oracle::meshDistance(robot.mesh, poseRobot, env, poseEnv);
    const double allowed = kPromisedAccuracy * sceneDiagonal(robot.mesh, poseRobot, env, poseEnv);
    SCOPED_TRACE(robot.name + ", pose " + std::to_string(i) + ", oracle " + std::to_string(truth.value));

    const DistanceResult exact = distance(robot.mesh, poseRobot, env, poseEnv, DistanceOptions::exactDistance());
    ASSERT_EQ(exact.status, DistanceStatus::exact);
    EXPECT_NEAR(exact.distance, truth.value, allowed);
    EXPECT_NEAR((exact.witnessA - exact.witnessB).norm(), exact.distance, allowed);
    gjkSettled += exact.counters.gjkCalls > 0;

    if (truth.value > allowed) {
      const DistanceResult below = distance(robot.mesh, poseRobot, env, poseEnv, DistanceOptions::cappedAt(0.5 * truth.value));
      EXPECT_EQ(below.status, DistanceStatus::beyondCap);
      EXPECT_LE(below.lower, truth.value + allowed);
      const DistanceResult above = distance(robot.mesh, poseRobot, env, poseEnv, DistanceOptions::cappedAt(2.0 * truth.value));
      EXPECT_EQ(above.status, DistanceStatus::exact);
      EXPECT_NEAR(above.distance, truth.value, allowed);
    }
    const DistanceResult tolerant =
        distance(robot.mesh, poseRobot, env, poseEnv, DistanceOptions::withTolerance(0.0, 0.01));
    EXPECT_LE(tolerant.lower, truth.value + allowed);
    EXPECT_GE(tolerant.upper, truth.value - allowed);
    EXPECT_LE(tolerant.upper, 1.01 * tolerant.lower + allowed);
    const DistanceResult valid = distance(robot.mesh, poseRobot, env, poseEnv, DistanceOptions::aboveThreshold(0.0));
    EXPECT_EQ(valid.status == DistanceStatus::aboveThreshold, truth.value > allowed);
  }
}

TEST(ConvexComponents, AnswersMatchTheOracleAcrossTheEnvironment) {
  const Environment e = environment();
  SeededRandom random(9001);
  for (const Robot& robot : robots()) {
    int gjkSettled = 0;
    expectOracleAnswers(e.mesh, robot, random, gjkSettled);
    // The box and the round robot are convex solids themselves: most of their queries meet the
    // environment's solids as solids.
    if (robot.name == "box" || robot.name == "round") {
      EXPECT_GE(gjkSettled, kPoses / 2) << robot.name;
    }
  }
}

/// A convex solid (a capsule) against meshes that are not convex solids: kept whole against the
/// nodes outside it, it settles their leaves by GJK (tree_traversal.cpp, convexPairToSettle); in
/// a room, whose walls are two nested closed convex shells around it, neither is kept whole
/// against what lies inside its box. Answers against the oracle in every mode.
TEST(ConvexComponents, AConvexSolidMeetsTheLeavesOfOtherMeshesWhole) {
  Robot capsule{"capsule", shapes::capsule(0.06, 0.35, 12)};
  capsule.mesh.buildHierarchy();
  ASSERT_TRUE(capsule.mesh.hierarchy()->nodes()[0].convexSolid);
  Mesh torus = shapes::torus(0.8, 0.25, 16, 8);
  Mesh room = shapes::room(Vec3(1.0, 0.8, 0.6), 0.1, 2);
  torus.buildHierarchy();
  room.buildHierarchy();
  SeededRandom random(5150);
  int gjkSettled = 0;
  expectOracleAnswers(torus, capsule, random, gjkSettled);
  expectOracleAnswers(room, capsule, random, gjkSettled);

  // The same capsule less its last triangle (an end cap's) is not closed, so not a solid, and its
  // tree is opened against the torus's nodes. Whole, the solid opens far fewer node pairs at the
  // same poses (counts, not times: the path is taken, not how fast it is).
  std::vector<TriangleIndices> opened = capsule.mesh.triangles();
  opened.pop_back();
  Mesh open(capsule.mesh.vertices(), opened, "open capsule");
  open.buildHierarchy();
  ASSERT_FALSE(open.hierarchy()->nodes()[0].convexSolid);
  std::uint64_t pairsSolid = 0, pairsOpen = 0, pairsSwapped = 0;
  for (int i = 0; i < kPoses; ++i) {
    const Vec3 place(random.uniform(-1.2, 1.2), random.uniform(-1.2, 1.2), random.uniform(-0.6, 0.6));
    const Pose pose(Eigen::Translation3d(place) * random.rotation());
    const DistanceResult solid = distance(capsule.mesh, pose, torus, Pose::Identity(), DistanceOptions::exactDistance());
    const DistanceResult notSolid = distance(open, pose, torus, Pose::Identity(), DistanceOptions::exactDistance());
    // The solid as the second mesh: the other frame's transforms, the same traversal.
    const DistanceResult swapped = distance(torus, Pose::Identity(), capsule.mesh, pose, DistanceOptions::exactDistance());
    pairsSolid += solid.counters.subMeshPairs;
    pairsOpen += notSolid.counters.subMeshPairs;
    pairsSwapped += swapped.counters.subMeshPairs;
  }
  EXPECT_LT(2 * pairsSolid, pairsOpen) << "solid " << pairsSolid << " node pairs, open " << pairsOpen;
  EXPECT_LT(2 * pairsSwapped, pairsOpen) << "solid as B " << pairsSwapped << " node pairs, open " << pairsOpen;

  // A non-convex robot inside the room: its nodes lie inside the shells' boxes, where the shells
  // are split by size as before, not kept whole (a robot inside one convex shell would else be
  // opened to its leaves against the whole shell). The same room with a triangle taken out of
  // each shell has no solids: the node pairs must stay of its order.
  std::vector<TriangleIndices> holed = room.triangles();
  holed.erase(holed.end() - 1);
  holed.erase(holed.begin());
  Mesh openRoom(room.vertices(), holed, "room with holes");
  openRoom.buildHierarchy();
  for (const MeshHierarchy::Node& n : openRoom.hierarchy()->nodes()) ASSERT_EQ(n.convexSolid, 0);
  ASSERT_TRUE(std::any_of(room.hierarchy()->nodes().begin(), room.hierarchy()->nodes().end(),
                          [](const MeshHierarchy::Node& n) { return n.convexSolid != 0; }));
  Mesh ring = shapes::torus(0.3, 0.08, 24, 10);
  ring.buildHierarchy();
  std::uint64_t pairsInRoom = 0, pairsInOpenRoom = 0;
  for (int i = 0; i < kPoses; ++i) {
    const Vec3 place(random.uniform(-0.5, 0.5), random.uniform(-0.4, 0.4), random.uniform(-0.2, 0.2));
    const Pose pose(Eigen::Translation3d(place) * random.rotation());
    pairsInRoom += distance(ring, pose, room, Pose::Identity(), DistanceOptions::exactDistance()).counters.subMeshPairs;
    pairsInOpenRoom +=
        distance(ring, pose, openRoom, Pose::Identity(), DistanceOptions::exactDistance()).counters.subMeshPairs;
  }
  EXPECT_LT(pairsInRoom, 2 * pairsInOpenRoom) << "closed room " << pairsInRoom << ", open " << pairsInOpenRoom;
}

/// Validity queries near contact: a capsule kept whole against the torus's nodes has the leaves
/// outside it bounded by GJK on the hulls (tree_traversal.cpp, convexPairToBound), where split by
/// size its strips, each as long as itself, were opened against every leaf its box reached. At
/// poses 0.06-6 % of the capsule's length from the torus, thresholds below and above the oracle's
/// distance give the right status, and the solid opens far fewer node pairs than the same capsule
/// less one triangle (counts, not times).
TEST(ConvexComponents, AValidityQueryNearContactBoundsACapsulesLeafPairsByItsHull) {
  Mesh capsule = shapes::capsule(0.05, 0.6, 24);
  capsule.buildHierarchy();
  ASSERT_TRUE(capsule.hierarchy()->nodes()[0].convexSolid);
  std::vector<TriangleIndices> opened = capsule.triangles();
  opened.pop_back();
  Mesh open(capsule.vertices(), opened, "open capsule");
  open.buildHierarchy();
  Mesh torus = shapes::torus(0.8, 0.25, 32, 16);
  torus.buildHierarchy();
  SeededRandom random(4242);
  constexpr int kNearPoses = 20;  // not fewer under the sanitizers: the count compares totals
  std::uint64_t pairsSolid = 0, pairsOpen = 0;
  int near = 0;
  for (int attempt = 0; attempt < 4000 && near < kNearPoses; ++attempt) {
    const Vec3 place(random.uniform(-1.2, 1.2), random.uniform(-1.2, 1.2), random.uniform(-0.5, 0.5));
    const Pose pose(Eigen::Translation3d(place) * random.rotation());
    // Cheap first: most draws are far or in contact, which the exact query tells at once.
    const double d = distance(capsule, pose, torus, Pose::Identity(), DistanceOptions::exactDistance()).distance;
    if (!(d > 0.00035 && d < 0.035)) continue;
    const oracle::MeshPairDistance truth = oracle::meshDistance(capsule, pose, torus, Pose::Identity());
    const double allowed = kPromisedAccuracy * sceneDiagonal(capsule, pose, torus, Pose::Identity());
    SCOPED_TRACE("pose " + std::to_string(attempt) + ", oracle " + std::to_string(truth.value));
    ++near;
    for (const double threshold : {0.0, 0.5 * truth.value, 1.5 * truth.value}) {
      const DistanceResult solid =
          distance(capsule, pose, torus, Pose::Identity(), DistanceOptions::aboveThreshold(threshold));
      const DistanceResult swapped =
          distance(torus, Pose::Identity(), capsule, pose, DistanceOptions::aboveThreshold(threshold));
      const DistanceResult notSolid =
          distance(open, pose, torus, Pose::Identity(), DistanceOptions::aboveThreshold(threshold));
      const bool above = truth.value > threshold + allowed;
      EXPECT_EQ(solid.status == DistanceStatus::aboveThreshold, above) << "threshold " << threshold;
      EXPECT_EQ(swapped.status == DistanceStatus::aboveThreshold, above) << "threshold " << threshold;
      EXPECT_EQ(notSolid.status == DistanceStatus::aboveThreshold, above) << "threshold " << threshold;
      if (above) {  // the proof that every pair is apart, where the hull bound saves work
        EXPECT_LE(solid.lower, truth.value + allowed);
        pairsSolid += solid.counters.subMeshPairs;
        pairsOpen += notSolid.counters.subMeshPairs;
      }
    }
  }
  ASSERT_EQ(near, kNearPoses) << "too few poses near contact";
  EXPECT_LT(2 * pairsSolid, pairsOpen) << "solid " << pairsSolid << " node pairs, open " << pairsOpen;
}

/// A deformation that pushes one corner of the first box inwards dents it: refit must take its
/// convexSolid flag away (GJK on its hull would then see the corner the surface no longer has),
/// and the answers stay the oracle's.
TEST(ConvexComponents, ADentedSolidLosesItsFlagOnRefit) {
  Environment e = environment();
  std::vector<Vec3> moved = e.mesh.vertices();
  // The first box's corner (+,+,+) is one of its first 8 vertices; pull it to the centre's side.
  for (std::size_t v = 0; v < 8; ++v) {
    if (moved[v].x() > 0 && moved[v].y() > 0 && moved[v].z() > 0) moved[v] = Vec3(0.1, 0.1, 0.1);
  }
  e.mesh.setVertices(moved);
  const MeshHierarchy& tree = *e.mesh.hierarchy();
  int solids = 0;
  for (const MeshHierarchy::Node& n : tree.nodes()) solids += n.convexSolid;
  EXPECT_EQ(solids, 6);  // seven before the dent
  SeededRandom random(31337);
  int gjkSettled = 0;
  expectOracleAnswers(e.mesh, robots()[0], random, gjkSettled);
}

}  // namespace
}  // namespace adsd
