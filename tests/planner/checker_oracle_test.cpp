// Validity and clearance of both checkers against the independent brute-force oracle
// (tests/oracle: every robot triangle against every environment triangle, binary128), on seeded
// random states of the shipped problems' scenes. Issue 4 asks for 1e-10 × the scene's diagonal.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <random>

#include "adsd/error.h"
#include "adsd/io/load_mesh.h"
#include "adsd/mesh_hierarchy.h"
#include "adsd/planner/certified_motion_validator.h"
#include "adsd/planner/features.h"
#if ADSD_PLANNER_HAS_FCL
#include "adsd/planner/fcl_validity_checker.h"
#endif
#include "adsd/planner/mesh_validity_checker.h"
#include "adsd/shapes.h"
#include "oracle.h"
#include "scene_fixtures.h"

namespace adsd::planner {
namespace {

using test::PoseSampler;
using test::SceneFixture;

/// Issue 4's accuracy for exact clearance, relative to the scene's length scale (dimensionless).
constexpr double kClearanceAccuracy = 1e-10;

struct OracleAnswer {
  double distance = std::numeric_limits<double>::infinity();
  bool intersecting = false;
};

OracleAnswer oracleAt(const SceneFixture& f, const Pose& pose) {
  OracleAnswer a;
  for (const Mesh& r : f.scene->robot) {
    for (const Mesh& e : f.oracleEnvironment) {
      a.distance = std::min(a.distance, oracle::meshDistance(r, pose, e, Pose::Identity()).value);
      a.intersecting = a.intersecting || oracle::meshesIntersect(r, pose, e, Pose::Identity());
    }
  }
  return a;
}

/// The state count: \p fallback, or ADSD_ORACLE_STATES when set (issue 4's acceptance run uses
/// 10000 per problem; the suite keeps to a few seconds).
int stateCount(int fallback) {
  const char* env = std::getenv("ADSD_ORACLE_STATES");
  const int n = env != nullptr ? std::atoi(env) : 0;
  return n > 0 ? n : fallback;
}

/// Runs \p states random states of \p f through our checker (and FCL's), comparing with the oracle.
void compareWithOracle(const SceneFixture& f, int defaultStates, std::uint64_t seed) {
  const int states = stateCount(defaultStates);
  auto ours = std::make_shared<MeshValidityChecker>(f.si, f.scene);
#if ADSD_PLANNER_HAS_FCL
  auto fcl = std::make_shared<FclValidityChecker>(f.si, f.scene);
#endif
  const double tolerance = kClearanceAccuracy * ours->scale();
  PoseSampler sampler(f, seed);
  ompl::base::ScopedState<> state(f.si);
  int valid = 0, colliding = 0, ambiguous = 0, fclDisagreements = 0;
  int oursValidityDisagreements = 0, fclValidityDisagreements = 0;
  double oursMaxError = 0.0, fclMaxError = 0.0;  // |clearance - oracle|, the scene's length unit
  for (int i = 0; i < states; ++i) {
    const Pose pose = sampler.next();
    poseToState(pose, f.scene->space, state.get());
    const Pose asChecked = poseFromState(state.get(), f.scene->space);  // the state's own rounding
    const OracleAnswer truth = oracleAt(f, asChecked);
    // The oracle's distance of intersecting meshes is zero up to its binary128 rounding.
    ASSERT_TRUE(!truth.intersecting || truth.distance <= tolerance)
        << "oracle disagrees with itself, state " << i << ": " << truth.distance;

    double dist = -1.0;
    const bool validWithDistance = ours->isValid(state.get(), dist);
    const double clearance = ours->clearance(state.get());
    EXPECT_NEAR(clearance, truth.distance, tolerance) << f.name << " state " << i;
    oursMaxError = std::max(oursMaxError, std::fabs(clearance - truth.distance));
    EXPECT_EQ(dist, clearance) << f.name << " state " << i << ": isValid(state, dist) gives clearance()";
    const bool inBounds = f.si->satisfiesBounds(state.get());
    if (truth.distance > tolerance) {
      ++valid;
      const bool oursValid = ours->isValid(state.get());
      oursValidityDisagreements += oursValid != inBounds || validWithDistance != inBounds;
      EXPECT_EQ(oursValid, inBounds) << f.name << " state " << i << " oracle " << truth.distance;
      EXPECT_EQ(validWithDistance, inBounds) << f.name << " state " << i;
    } else if (truth.intersecting) {
      ++colliding;
      const bool oursValid = ours->isValid(state.get());
      oursValidityDisagreements += oursValid || validWithDistance;
      EXPECT_FALSE(oursValid) << f.name << " state " << i;
      EXPECT_FALSE(validWithDistance) << f.name << " state " << i;
    } else {
      ++ambiguous;  // touching within rounding: either answer is right
    }

#if ADSD_PLANNER_HAS_FCL
    // FCL, side by side: recorded, and held to a looser bound (its GJK stops at its own tolerance).
    const double fclClearance = fcl->clearance(state.get());
    const bool fclValid = fcl->isValid(state.get());
    fclMaxError = std::max(fclMaxError, std::fabs(fclClearance - truth.distance));
    const bool fclWrong = std::fabs(fclClearance - truth.distance) > 1e-6 * ours->scale() ||
                          (truth.distance > tolerance && fclValid != inBounds) || (truth.intersecting && fclValid);
    fclValidityDisagreements += (truth.distance > tolerance && fclValid != inBounds) || (truth.intersecting && fclValid);
    if (fclWrong) {
      ++fclDisagreements;
      std::printf("[fcl vs oracle] %s state %d: fcl clearance %.17g valid %d, oracle %.17g intersecting %d\n",
                  f.name.c_str(), i, fclClearance, fclValid, truth.distance, truth.intersecting);
    }
#endif
  }
  std::printf("[%s] %d states: %d valid, %d colliding, %d touching within rounding; FCL disagreed on %d\n",
              f.name.c_str(), states, valid, colliding, ambiguous, fclDisagreements);
  std::printf("[%s] max |clearance - oracle| / scene diagonal: adsd %.3g, FCL %.3g; validity disagreements: "
              "adsd %d, FCL %d\n",
              f.name.c_str(), oursMaxError / ours->scale(), fclMaxError / ours->scale(), oursValidityDisagreements,
              fclValidityDisagreements);
  // The sample must exercise both answers (STYLE habit: check the random mix).
  EXPECT_GT(valid, states / 10) << f.name;
  EXPECT_GT(colliding, states / 10) << f.name;
  const QueryCounts c = ours->counts();
  EXPECT_EQ(c.validityChecks, static_cast<std::uint64_t>(valid + colliding));
  EXPECT_EQ(c.clearanceQueries, static_cast<std::uint64_t>(2 * states));
}

TEST(CheckerVersusOracle, Office) { compareWithOracle(test::officeFixture(), 150, 1); }
TEST(CheckerVersusOracle, Maze) { compareWithOracle(test::mazeFixture(), 150, 2); }
TEST(CheckerVersusOracle, ThinWall) { compareWithOracle(test::thinWallFixture(), 150, 3); }
TEST(CheckerVersusOracle, BugTrap) { compareWithOracle(test::bugTrapFixture(), 60, 4); }
TEST(CheckerVersusOracle, TwistedPassage) { compareWithOracle(test::twistedPassageFixture(), 150, 5); }
TEST(CheckerVersusOracle, AlphaPuzzle) { compareWithOracle(test::alphaPuzzleFixture(), 10, 6); }

TEST(CheckerVersusOracle, CowDoorwayWithTheRealModel) {
  // The cow comes from the real-model cache (problems/data/fetch_meshes.sh); without it, skip.
  const char* dataDir = std::getenv("ADSD_DATA_DIR");
  const char* home = std::getenv("HOME");
  const std::string cow = (dataDir != nullptr && *dataDir != '\0') ? std::string(dataDir) + "/cow.off"
                          : home != nullptr                        ? std::string(home) + "/.cache/adsd/meshes/cow.off"
                                                                   : std::string();
  if (cow.empty() || !std::filesystem::exists(cow)) GTEST_SKIP() << "no " << cow << ": run problems/data/fetch_meshes.sh";
  shapes::ProblemScene scene = shapes::cowDoorwayScene();
  scene.robot = {recentreRobot(io::loadMesh(cow), RigidBodySpace::se3)};
  compareWithOracle(test::makeFixture(scene, RigidBodySpace::se3, {Vec3(-2, -1, -1), Vec3(2, 1, 1)}), 10, 9);
}

TEST(CheckerVersusOracle, BroadPhaseOverSeveralEnvironmentMeshes) {
  // The maze split into two meshes (and the office added far away): the broad phase may skip
  // meshes but must not change any answer.
  SceneFixture f = test::mazeFixture();
  const Mesh maze = shapes::mazeScene().environment;
  std::vector<Vec3> left, right;
  std::vector<TriangleIndices> leftT, rightT;
  for (const TriangleIndices& t : maze.triangles()) {
    const bool isLeft = maze.vertices()[t[0]].x() < 0.0;
    auto& v = isLeft ? left : right;
    auto& tris = isLeft ? leftT : rightT;
    const auto base = static_cast<std::uint32_t>(v.size());
    for (int k = 0; k < 3; ++k) v.push_back(maze.vertices()[t[k]]);
    tris.push_back({base, base + 1, base + 2});
  }
  Pose far = Pose::Identity();
  far.translate(Vec3(100, 0, 0));
  f.scene->environment = {Mesh(left, leftT, "maze left"), Mesh(right, rightT, "maze right"),
                          shapes::merge({shapes::officeScene().environment}, {far})};
  f.oracleEnvironment = f.scene->environment;
  compareWithOracle(f, 100, 7);
}

TEST(BroadPhase, KeepsBoxesTouchingWithinRoundoff) {
  // A robot box pressed face to face against an environment box: the meshes touch (distance 0, a
  // collision at margin 0), yet the broad phase's box gap, computed from rounded centres and half
  // extents, comes out a few ulps above 0 for many sizes. Such a pair must still reach the narrow
  // phase.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> coordinate(-5.0, 5.0), length(0.01, 2.0);
  int cases = 0, gapRoundsAboveZero = 0;
  while (cases < 100) {
    const double halfWidth = length(rng), lo = coordinate(rng), hi = lo + length(rng);
    const double x = hi + halfWidth;
    if (x - halfWidth != hi) continue;
    ++cases;
    const double centre = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
    if (std::abs(centre - x) - half - halfWidth > 0.0) ++gapRoundsAboveZero;

    const Mesh unit = shapes::box(Vec3(1.0, 1.0, 1.0));
    std::vector<Vec3> corners = unit.vertices();
    for (Vec3& v : corners) v.x() = v.x() < 0.0 ? lo : hi;
    const shapes::ProblemScene generated{
        "touching boxes", {shapes::box(Vec3(halfWidth, 0.5, 0.5))}, Mesh(corners, unit.triangles(), "wall")};
    const SceneFixture f = test::makeFixture(generated, RigidBodySpace::se2, {Vec3(-10, -10, 0), Vec3(10, 10, 0)});
    ompl::base::ScopedState<ompl::base::SE2StateSpace> state(f.si);
    state->setXY(x, 0.0);
    state->setYaw(0.0);
    // The touch, checked by construction: the robot's lowest x lands on hi exactly. (The oracle
    // read 1.7e-16 for the first case: far within the 1e-10 x scale it is trusted to, but not
    // the exact 0 this test is about.)
    const Pose pose = poseFromState(state.get(), f.scene->space);
    double lowestX = std::numeric_limits<double>::infinity();
    for (const Vec3& v : f.scene->robot[0].vertices()) lowestX = std::min(lowestX, (pose * v).x());
    ASSERT_EQ(lowestX, hi);
    const MeshValidityChecker ours(f.si, f.scene);
    EXPECT_FALSE(ours.isValid(state.get())) << "lo " << lo << " hi " << hi << " half width " << halfWidth;
    EXPECT_EQ(ours.clearance(state.get()), 0.0) << "lo " << lo << " hi " << hi << " half width " << halfWidth;
  }
  EXPECT_GT(gapRoundsAboveZero, 10);  // the rounding this test is about happened
}

TEST(SplitIntoParts, KeepsEveryTriangleOnce) {
  const Mesh office = shapes::officeScene().environment;  // 32 separate boxes
  for (const std::size_t maxParts : {std::size_t{64}, std::size_t{5}, std::size_t{1}}) {
    const std::vector<Mesh> parts = splitIntoParts(office, maxParts);
    EXPECT_EQ(parts.size(), std::min<std::size_t>(32, maxParts));
    std::size_t triangles = 0;
    Eigen::AlignedBox3d box;
    for (const Mesh& p : parts) {
      triangles += p.triangleCount();
      box.extend(p.bounds());
    }
    EXPECT_EQ(triangles, office.triangleCount());
    EXPECT_TRUE(box.isApprox(office.bounds()));
  }
}

/// \p mesh with vertices at identical positions made one (as a loader that joins identical
/// vertices reads touching boxes).
Mesh welded(const Mesh& mesh) {
  std::vector<Vec3> vertices;
  std::vector<TriangleIndices> triangles;
  std::vector<std::uint32_t> index(mesh.vertices().size());
  for (std::size_t v = 0; v < mesh.vertices().size(); ++v) {
    std::size_t same = 0;
    while (same < vertices.size() && vertices[same] != mesh.vertices()[v]) ++same;
    if (same == vertices.size()) vertices.push_back(mesh.vertices()[v]);
    index[v] = static_cast<std::uint32_t>(same);
  }
  for (const TriangleIndices& t : mesh.triangles()) triangles.push_back({index[t[0]], index[t[1]], index[t[2]]});
  return Mesh(std::move(vertices), std::move(triangles), mesh.name());
}

// Walls and boxes are their own hulls: a wall thinner than the piece size stays whole however
// long (cut, its pieces would be open boxes), and boxes touching at shared corners come apart
// into boxes; a box as wide as the pieces are large could hold the robot, and is cut.
TEST(SplitIntoParts, KeepsThinConvexSolidsWholeAndSeparatesTouchingOnes) {
  const Mesh wall = shapes::box(Vec3(5, 0.1, 1));  // 10 long, 0.2 thick
  std::vector<Mesh> parts = splitIntoParts(wall, 1000, 1.5);
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_TRUE(isClosedConvex(parts[0]));

  // A desk: a top resting on two legs, a corner of each shared (welded; binary fractions, so
  // that the corners coincide exactly), and a wide block.
  const Mesh desk = welded(shapes::merge({shapes::box(Vec3(1, 0.5, 0.125)), shapes::box(Vec3(0.125, 0.125, 0.375)),
                                          shapes::box(Vec3(0.125, 0.125, 0.375))},
                                         {Pose(Eigen::Translation3d(0, 0, 0.875)),
                                          Pose(Eigen::Translation3d(-0.875, -0.375, 0.375)),
                                          Pose(Eigen::Translation3d(0.875, 0.375, 0.375))}));
  ASSERT_LT(desk.vertices().size(), 24u) << "the legs' top corners are the top's";
  parts = splitIntoParts(desk, 1000, 1.5);
  ASSERT_EQ(parts.size(), 3u);
  for (const Mesh& p : parts) EXPECT_TRUE(isClosedConvex(p)) << p.name();

  const Mesh block = shapes::box(Vec3(2, 2, 2));
  parts = splitIntoParts(block, 1000, 1.5);
  EXPECT_GT(parts.size(), 1u);
}

TEST(SplitIntoParts, CutsASurroundingRoomIntoPiecesOfTheGivenSize) {
  // A room's inner shell holds whatever is inside it in its convex hull: cut into pieces no larger
  // than 1.5, every triangle kept once, each piece within the size unless too few triangles to cut.
  const Mesh walls = shapes::room(Vec3(2.5, 1.5, 1.5), 0.1, 4);
  const std::vector<Mesh> pieces = splitIntoParts(walls, 1000, 1.5);
  std::size_t triangles = 0;
  Eigen::AlignedBox3d box;
  for (const Mesh& p : pieces) {
    triangles += p.triangleCount();
    box.extend(p.bounds());
    EXPECT_TRUE(p.bounds().diagonal().norm() <= 1.5 || p.triangleCount() <= kMinPieceTriangles)
        << p.name() << ": " << p.triangleCount() << " triangles, diagonal " << p.bounds().diagonal().norm();
  }
  EXPECT_EQ(triangles, walls.triangleCount());
  EXPECT_TRUE(box.isApprox(walls.bounds()));
  EXPECT_GT(pieces.size(), 2u * 6u);  // more than the two shells' faces
  // Grouped again into at most 16 parts, still every triangle once.
  const std::vector<Mesh> grouped = splitIntoParts(walls, 16, 1.5);
  EXPECT_EQ(grouped.size(), 16u);
  triangles = 0;
  for (const Mesh& p : grouped) triangles += p.triangleCount();
  EXPECT_EQ(triangles, walls.triangleCount());
}

TEST(CheckerSettings, ClearanceTypeIsHonest) {
  const SceneFixture f = test::officeFixture();
  using Specs = ompl::base::StateValidityCheckerSpecs;
  EXPECT_EQ(MeshValidityChecker(f.si, f.scene).getSpecs().clearanceComputationType, Specs::EXACT);
  EXPECT_EQ(MeshValidityChecker(f.si, f.scene, 0.0, DistanceOptions::withTolerance(0.01, 0.0))
                .getSpecs()
                .clearanceComputationType,
            Specs::BOUNDED_APPROXIMATE);
  EXPECT_EQ(MeshValidityChecker(f.si, f.scene, 0.0, DistanceOptions::cappedAt(0.5)).getSpecs().clearanceComputationType,
            Specs::BOUNDED_APPROXIMATE);
  EXPECT_THROW({ MeshValidityChecker c(f.si, f.scene, 0.0, DistanceOptions::aboveThreshold(0.0)); }, InputError);
  EXPECT_THROW({ MeshValidityChecker c(f.si, f.scene, -1.0); }, InputError);
  EXPECT_THROW({ MeshValidityChecker c(f.si, f.scene, std::nan("")); }, InputError);
}

TEST(CheckerSettings, CappedAndTolerantClearanceAreLowerBounds) {
  const SceneFixture f = test::officeFixture();
  MeshValidityChecker exact(f.si, f.scene);
  MeshValidityChecker capped(f.si, f.scene, 0.0, DistanceOptions::cappedAt(0.3));
  MeshValidityChecker tolerant(f.si, f.scene, 0.0, DistanceOptions::withTolerance(0.05, 0.0));
  PoseSampler sampler(f, 8);
  ompl::base::ScopedState<> state(f.si);
  int aboveCap = 0;
  for (int i = 0; i < 100; ++i) {
    poseToState(sampler.next(), f.scene->space, state.get());
    const double d = exact.clearance(state.get());
    const double c = capped.clearance(state.get());
    const double t = tolerant.clearance(state.get());
    EXPECT_EQ(c, std::min(d, 0.3)) << i;  // exact below the cap, the cap above it
    aboveCap += d > 0.3;
    EXPECT_LE(t, d + kClearanceAccuracy * exact.scale()) << i;
    EXPECT_GE(t, d - 0.05 - kClearanceAccuracy * exact.scale()) << i;
  }
  EXPECT_GT(aboveCap, 10);
}

TEST(CheckerSettings, SafetyMarginMakesNearStatesInvalid) {
  const SceneFixture f = test::thinWallFixture();
  MeshValidityChecker plain(f.si, f.scene);
  MeshValidityChecker careful(f.si, f.scene, 0.1);
#if ADSD_PLANNER_HAS_FCL
  FclValidityChecker fclCareful(f.si, f.scene, 0.1);
#endif
  ompl::base::ScopedState<ompl::base::SE2StateSpace> s(f.si);
  s->setXY(-0.06, -1.0);  // the bar's face is 0.04 from the wall's
  s->setYaw(0.0);
  EXPECT_NEAR(plain.clearance(s.get()), 0.04, 1e-12);
  EXPECT_TRUE(plain.isValid(s.get()));
  EXPECT_FALSE(careful.isValid(s.get()));
#if ADSD_PLANNER_HAS_FCL
  EXPECT_FALSE(fclCareful.isValid(s.get()));
#endif
  s->setXY(-0.2, -1.0);
  EXPECT_TRUE(careful.isValid(s.get()));
#if ADSD_PLANNER_HAS_FCL
  EXPECT_TRUE(fclCareful.isValid(s.get()));
#endif
}

TEST(CheckerSettings, OutOfBoundsStatesAreInvalid) {
  const SceneFixture f = test::thinWallFixture();
  MeshValidityChecker checker(f.si, f.scene);
  ompl::base::ScopedState<ompl::base::SE2StateSpace> s(f.si);
  s->setYaw(0.0);
  s->setXY(-3.0, -3.0);
  EXPECT_TRUE(checker.isValid(s.get()));
  s->setXY(-4.5, -3.0);  // beyond the outer wall: free space, but outside the volume
  EXPECT_GT(checker.clearance(s.get()), 0.2);
  double dist = 0.0;
  EXPECT_FALSE(checker.isValid(s.get()));
  EXPECT_FALSE(checker.isValid(s.get(), dist));
}

// A NaN position passes OMPL's bounds test (its comparisons are false); the checker threw the
// distance query's InputError into the planner for it, while a NaN yaw was simply invalid.
TEST(CheckerSettings, StatesThatAreNotNumbersAreInvalidAtClearanceZero) {
  const SceneFixture plane = test::thinWallFixture();
  MeshValidityChecker flat(plane.si, plane.scene);
  ompl::base::ScopedState<ompl::base::SE2StateSpace> s(plane.si);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const Vec3& xyYaw : {Vec3(nan, -3.0, 0.0), Vec3(-3.0, nan, 0.0), Vec3(-3.0, -3.0, nan)}) {
    s->setXY(xyYaw.x(), xyYaw.y());
    s->setYaw(xyYaw.z());
    double dist = 1.0;
    EXPECT_NO_THROW(EXPECT_FALSE(flat.isValid(s.get())));
    EXPECT_NO_THROW(EXPECT_FALSE(flat.isValid(s.get(), dist)));
    EXPECT_EQ(dist, 0.0);
    EXPECT_NO_THROW(EXPECT_EQ(flat.clearance(s.get()), 0.0));
    EXPECT_NO_THROW(EXPECT_EQ(flat.clearanceUpTo(s.get(), 1.0), 0.0));
  }
  const SceneFixture space = test::bugTrapFixture();
  MeshValidityChecker solid(space.si, space.scene);
  ompl::base::ScopedState<ompl::base::SE3StateSpace> t(space.si);
  t->setXYZ(nan, 0.0, 0.0);
  t->rotation().setIdentity();
  EXPECT_NO_THROW(EXPECT_FALSE(solid.isValid(t.get())));
  EXPECT_NO_THROW(EXPECT_EQ(solid.clearance(t.get()), 0.0));
  t->setXYZ(0.0, 0.0, 0.0);
  t->rotation().x = nan;
  EXPECT_NO_THROW(EXPECT_FALSE(solid.isValid(t.get())));
  EXPECT_NO_THROW(EXPECT_EQ(solid.clearance(t.get()), 0.0));
}

// With a clearance that is a lower bound (a tolerance's, a cap's), isValid(state, dist) called
// states invalid that isValid(state) called valid, the bound lying at or below the margin there
// (an outside review: 890 of 2000 states near the office's walls, with a tolerance of 1e-3 +
// 1 %). Here a cap of half the safety margin puts every bound below the margin: both calls agree
// on states just clear of the margin and well clear of it, and on one within it.
TEST(CheckerSettings, ValidityWithABoundedClearanceIsTheThresholdQuerysToo) {
  const SceneFixture f = test::thinWallFixture();
  const double margin = 0.01;
  const DistanceOptions settings[] = {DistanceOptions::cappedAt(0.5 * margin),
                                      DistanceOptions::withTolerance(1e-3, 0.01)};
  for (const DistanceOptions& options : settings) {
    MeshValidityChecker checker(f.si, f.scene, margin, options);
    ompl::base::ScopedState<ompl::base::SE2StateSpace> s(f.si);
    s->setYaw(0.0);
    // The bar's face touches the wall's at x = -0.02 (SafetyMarginMakesNearStatesInvalid): gaps beyond
    // the margin from 1e-7 to 1e-1.
    for (int k = 0; k <= 30; ++k) {
      const double gap = margin + std::pow(10.0, -7.0 + 6.0 * k / 30.0);
      s->setXY(-0.02 - gap, -1.0);
      double dist = -1.0;
      EXPECT_TRUE(checker.isValid(s.get())) << "gap " << gap;
      EXPECT_TRUE(checker.isValid(s.get(), dist)) << "gap " << gap << ", clearance bound " << dist;
      EXPECT_LE(dist, gap + 1e-12);
    }
    s->setXY(-0.02 - 0.5 * margin, -1.0);  // within the margin
    double dist = 1.0;
    EXPECT_FALSE(checker.isValid(s.get()));
    EXPECT_FALSE(checker.isValid(s.get(), dist));
  }
}

// A cap of 0 asks for nothing beyond a lower bound of at least min(clearance, 0): 0, for a state in
// contact as for one clear of the wall (it threw the distance query's "cap must be > 0" wherever
// the broad phase kept a pair: an outside review).
TEST(CheckerSettings, ACapOfZeroIsAnsweredZero) {
  const SceneFixture f = test::thinWallFixture();
  MeshValidityChecker checker(f.si, f.scene);
  ompl::base::ScopedState<ompl::base::SE2StateSpace> s(f.si);
  s->setYaw(0.0);
  // The bar's face touches the wall's at x = -0.02: overlapping, touching, and 1e-6 to 1 clear.
  for (const double gap : {-0.01, 0.0, 1e-6, 1e-3, 0.1, 1.0}) {
    s->setXY(-0.02 - gap, -1.0);
    EXPECT_NO_THROW(EXPECT_EQ(checker.clearanceUpTo(s.get(), 0.0), 0.0)) << "gap " << gap;
  }
}

// States the distance query cannot take are invalid at clearance 0 from every call, not an
// exception thrown into the planner (x = 1e300) or an answer for some rotation (a quaternion of
// no length answered 1.38 in the bug trap); a bad cap and null pointers are the caller's errors,
// reported as such (they were a NaN passed on and a segfault). An outside review.
TEST(CheckerSettings, StatesBeyondTheQueryAndNullArgumentsAreRefusedCleanly) {
  SceneFixture plane = test::thinWallFixture();
  ompl::base::RealVectorBounds wide(2);
  wide.setLow(-1e301);
  wide.setHigh(1e301);
  plane.si->getStateSpace()->as<ompl::base::SE2StateSpace>()->setBounds(wide);
  MeshValidityChecker flat(plane.si, plane.scene);
  ompl::base::ScopedState<ompl::base::SE2StateSpace> s(plane.si);
  s->setXY(1e300, -1.0);
  s->setYaw(0.0);
  double dist = 1.0;
  EXPECT_NO_THROW(EXPECT_FALSE(flat.isValid(s.get())));
  EXPECT_NO_THROW(EXPECT_FALSE(flat.isValid(s.get(), dist)));
  EXPECT_EQ(dist, 0.0);
  EXPECT_NO_THROW(EXPECT_EQ(flat.clearance(s.get()), 0.0));
  s->setXY(-3.0, -3.0);
  EXPECT_THROW(flat.clearanceUpTo(s.get(), std::nan("")), InputError);
  EXPECT_THROW(flat.clearanceUpTo(s.get(), -1.0), InputError);
  EXPECT_GT(flat.clearanceUpTo(s.get(), 0.0), -1.0);

  const SceneFixture space = test::bugTrapFixture();
  MeshValidityChecker solid(space.si, space.scene);
  ompl::base::ScopedState<ompl::base::SE3StateSpace> t(space.si);
  t->setXYZ(-1.0, 0.0, 0.0);
  t->rotation().x = t->rotation().y = t->rotation().z = t->rotation().w = 0.0;
  EXPECT_FALSE(solid.isValid(t.get()));
  EXPECT_EQ(solid.clearance(t.get()), 0.0);

  EXPECT_THROW({ MeshValidityChecker c(plane.si, nullptr); }, InputError);
  EXPECT_THROW({ CertifiedMotionValidator v(plane.si, nullptr); }, InputError);
}

// An SE(3) scene over an SE(2) space read past each state's memory (valgrind: invalid reads in
// poseFromState), and an SE(2) scene over an SE(3) space ignored z: both are refused when built.
TEST(CheckerSpace, ASpaceOfTheOtherKindIsRefused) {
  const SceneFixture office = test::officeFixture();
  ASSERT_EQ(office.scene->space, RigidBodySpace::se2);
  auto se3 = std::make_shared<ompl::base::SE3StateSpace>();
  se3->setBounds(ompl::base::RealVectorBounds(3));
  auto se3Information = std::make_shared<ompl::base::SpaceInformation>(se3);
  EXPECT_THROW(MeshValidityChecker(se3Information, office.scene), InputError);
  auto lifted = std::make_shared<RigidBodyScene>(*office.scene);
  lifted->space = RigidBodySpace::se3;
  EXPECT_THROW(MeshValidityChecker(office.si, lifted), InputError);
  EXPECT_NO_THROW(MeshValidityChecker(office.si, office.scene));
}

}  // namespace
}  // namespace adsd::planner
