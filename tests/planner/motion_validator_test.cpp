// The certified motion validator: it rejects the thin-wall crossing that OMPL's discrete validator
// accepts, never accepts a motion the oracle finds a collision on, and reports the last valid state.
#include <gtest/gtest.h>

#include <limits>
#include <random>

#include <ompl/base/DiscreteMotionValidator.h>

#include "adsd/planner/certified_motion_validator.h"
#include "adsd/planner/features.h"
#if ADSD_PLANNER_HAS_FCL
#include "adsd/planner/fcl_validity_checker.h"
#endif
#include "adsd/planner/mesh_validity_checker.h"
#include "adsd/planner/path_report.h"
#include "oracle.h"
#include "scene_fixtures.h"

namespace adsd::planner {
namespace {

namespace ob = ompl::base;
using test::SceneFixture;

bool oracleCollides(const SceneFixture& f, const ob::State* s) {
  const Pose pose = poseFromState(s, f.scene->space);
  for (const Mesh& r : f.scene->robot) {
    for (const Mesh& e : f.oracleEnvironment) {
      if (oracle::meshesIntersect(r, pose, e, Pose::Identity())) return true;
    }
  }
  return false;
}

/// thin_wall.cfg's start and goal: the straight motion between them crosses the wall.
void thinWallEnds(const SceneFixture& f, ob::ScopedState<ob::SE2StateSpace>& start,
                  ob::ScopedState<ob::SE2StateSpace>& goal) {
  start->setXY(-2.03, -1.0);
  start->setYaw(0.0);
  goal->setXY(1.97, -1.0);
  goal->setYaw(0.0);
  (void)f;
}

/// The last state before the wall on the straight crossing from thin_wall.cfg's start to its goal,
/// found by halving the motion parameter down to \p resolution: clear of the wall by about
/// \p resolution times the motion's length (4).
void lastStateBeforeTheWall(const SceneFixture& f, const ob::StateValidityChecker& checker, double resolution,
                            ob::ScopedState<ob::SE2StateSpace>& out) {
  ob::ScopedState<ob::SE2StateSpace> start(f.si), goal(f.si);
  thinWallEnds(f, start, goal);
  double clearT = 0.0, blockedT = 2.03 / 4.0;  // at x = 0, in the wall
  for (int i = 0; i < 200 && blockedT - clearT > resolution; ++i) {
    const double t = 0.5 * (clearT + blockedT);
    f.si->getStateSpace()->interpolate(start.get(), goal.get(), t, out.get());
    (checker.isValid(out.get()) ? clearT : blockedT) = t;
  }
  f.si->getStateSpace()->interpolate(start.get(), goal.get(), clearT, out.get());
}

template <class Checker>
void thinWallCrossing(const char* label) {
  SceneFixture f = test::thinWallFixture();
  auto checker = std::make_shared<Checker>(f.si, f.scene);
  f.si->setStateValidityChecker(checker);
  f.si->setup();  // the discrete validator's resolution: OMPL's default fraction of the extent
  ob::ScopedState<ob::SE2StateSpace> start(f.si), goal(f.si), onWall(f.si);
  thinWallEnds(f, start, goal);
  onWall->setXY(0.0, -1.0);
  onWall->setYaw(0.0);
  ASSERT_TRUE(checker->isValid(start.get()));
  ASSERT_TRUE(checker->isValid(goal.get()));
  ASSERT_TRUE(oracleCollides(f, onWall.get())) << "the motion does cross the wall";

  ob::DiscreteMotionValidator discrete(f.si);
  checker->resetCounts();
  EXPECT_TRUE(discrete.checkMotion(start.get(), goal.get())) << "OMPL's discrete check steps over the wall";
  const QueryCounts discreteCounts = checker->counts();

  CertifiedMotionValidator certified(f.si, checker);
  checker->resetCounts();
  EXPECT_FALSE(certified.checkMotion(start.get(), goal.get()));
  std::pair<ob::State*, double> lastValid(f.si->allocState(), -1.0);
  EXPECT_FALSE(certified.checkMotion(start.get(), goal.get(), lastValid));
  const QueryCounts certifiedCounts = checker->counts();
  // The last valid state is before the wall (the bar's face reaches the wall at x = -0.02).
  EXPECT_GE(lastValid.second, 0.0);
  EXPECT_LT(lastValid.second, (2.03 - 0.02) / 4.0);
  EXPECT_FALSE(oracleCollides(f, lastValid.first));
  EXPECT_TRUE(checker->isValid(lastValid.first));
  f.si->freeState(lastValid.first);

  // And the way round through the gap at the top is certified.
  ob::ScopedState<ob::SE2StateSpace> up(f.si), over(f.si);
  up->setXY(-2.03, 3.0);
  up->setYaw(0.0);
  over->setXY(1.97, 3.0);
  over->setYaw(0.0);
  EXPECT_TRUE(certified.checkMotion(start.get(), up.get()));
  EXPECT_TRUE(certified.checkMotion(up.get(), over.get()));
  EXPECT_TRUE(certified.checkMotion(over.get(), goal.get()));
  const MotionCounts m = certified.counts();
  EXPECT_EQ(m.motions, 5u);
  EXPECT_EQ(m.rejected, 2u);
  std::printf("[thin wall, %s] straight crossing: discrete validator %llu validity checks (accepted); certified "
              "%llu validity checks + %llu clearance queries (rejected, twice)\n",
              label, static_cast<unsigned long long>(discreteCounts.validityChecks),
              static_cast<unsigned long long>(certifiedCounts.validityChecks),
              static_cast<unsigned long long>(certifiedCounts.clearanceQueries));
}

TEST(CertifiedMotion, RejectsTheThinWallCrossingThatTheDiscreteCheckAccepts) {
  thinWallCrossing<MeshValidityChecker>("adsd");
}
#if ADSD_PLANNER_HAS_FCL
TEST(CertifiedMotion, RejectsTheThinWallCrossingWithFclToo) { thinWallCrossing<FclValidityChecker>("fcl"); }
#endif

// A motion from 1e20 away through the thin wall: the interpolated states near the wall lie metres
// off the straight motion (a few eps of 1e20), and the query's distances there are trusted only to
// its roundoff allowance of that magnitude. Both are given away: rejected. (It was certified, and
// `adsd plan` printed a path through the office's walls.)
TEST(CertifiedMotion, MotionFromFarAwayThroughTheWallIsRejected) {
  SceneFixture f = test::thinWallFixture();
  // A volume that reaches 1e20 out along x.
  ob::RealVectorBounds bounds = f.si->getStateSpace()->as<ob::SE2StateSpace>()->getBounds();
  bounds.setLow(0, -2e20);
  f.si->getStateSpace()->as<ob::SE2StateSpace>()->setBounds(bounds);
  auto checker = std::make_shared<MeshValidityChecker>(f.si, f.scene);
  f.si->setStateValidityChecker(checker);
  f.si->setup();
  ob::ScopedState<ob::SE2StateSpace> start(f.si), goal(f.si), far(f.si);
  thinWallEnds(f, start, goal);
  for (const double x : {-1e20, -1e17, -1e12}) {
    SCOPED_TRACE(x);
    far->setXY(x, goal->getY());
    far->setYaw(goal->getYaw());
    ASSERT_TRUE(checker->isValid(far.get()));
    CertifiedMotionValidator certified(f.si, checker);
    EXPECT_FALSE(certified.checkMotion(far.get(), goal.get()));
  }
}

/// Random motions between valid states: every accepted motion is free of collision at dense
/// samples checked by the oracle; report how the two validators compare.
void randomMotions(const SceneFixture& f, int motions, std::uint64_t seed) {
  auto checker = std::make_shared<MeshValidityChecker>(f.si, f.scene);
  f.si->setStateValidityChecker(checker);
  f.si->setup();
  CertifiedMotionValidator certified(f.si, checker);
  ob::DiscreteMotionValidator discrete(f.si);
  test::PoseSampler sampler(f, seed);
  ob::ScopedState<> a(f.si), b(f.si), s(f.si);
  int accepted = 0, discreteOnly = 0, tried = 0;
  std::uint64_t certifiedQueries = 0, discreteQueries = 0;  // spent on the same motions
  constexpr int kSamplesPerMotion = 60;
  while (tried < motions) {
    poseToState(sampler.next(), f.scene->space, a.get());
    if (!checker->isValid(a.get())) continue;
    // A short motion from a: a second random state pulled towards a.
    poseToState(sampler.next(), f.scene->space, s.get());
    f.si->getStateSpace()->interpolate(a.get(), s.get(), 0.15, b.get());
    if (!checker->isValid(b.get())) continue;
    ++tried;
    const QueryCounts before = checker->counts();
    const bool byCertified = certified.checkMotion(a.get(), b.get());
    const QueryCounts between = checker->counts();
    const bool byDiscrete = discrete.checkMotion(a.get(), b.get());
    const QueryCounts after = checker->counts();
    certifiedQueries += (between.validityChecks - before.validityChecks) +
                        (between.clearanceQueries - before.clearanceQueries);
    discreteQueries += after.validityChecks - between.validityChecks;
    if (!byCertified) {
      discreteOnly += byDiscrete;
      continue;
    }
    ++accepted;
    for (int k = 0; k <= kSamplesPerMotion; ++k) {
      f.si->getStateSpace()->interpolate(a.get(), b.get(), static_cast<double>(k) / kSamplesPerMotion, s.get());
      ASSERT_FALSE(oracleCollides(f, s.get())) << f.name << ": certified motion collides at " << k;
    }
  }
  std::printf("[%s] %d motions: certified accepted %d with %llu queries; discrete accepted %d more, %llu queries\n",
              f.name.c_str(), motions, accepted, static_cast<unsigned long long>(certifiedQueries), discreteOnly,
              static_cast<unsigned long long>(discreteQueries));
  EXPECT_GT(accepted, motions / 5) << "the sample must contain accepted motions";
}

TEST(CertifiedMotion, AcceptedMotionsAreCollisionFreeInTheOffice) { randomMotions(test::officeFixture(), 40, 11); }
TEST(CertifiedMotion, AcceptedMotionsAreCollisionFreeInTheTwistedPassage) {
  randomMotions(test::twistedPassageFixture(), 40, 12);
}

// The least clearance along a path, motions included (leastClearanceAlong): the crossing that the
// discrete check accepts is found at 0, where the states at the validity-checking resolution
// measure it clear; a motion over the wall's top comes within 1 % of the least of 20 001 states
// along it, an oracle of dense samples (each checked by the brute force at its least).
TEST(LeastClearanceAlong, FindsTheWallADiscretePathStepsOverAndTheLeastOverTheTop) {
  SceneFixture f = test::thinWallFixture();
  auto checker = std::make_shared<MeshValidityChecker>(f.si, f.scene);
  f.si->setStateValidityChecker(checker);
  f.si->setup();
  ob::ScopedState<ob::SE2StateSpace> start(f.si), goal(f.si);
  thinWallEnds(f, start, goal);
  ompl::geometric::PathGeometric crossing(f.si, start.get(), goal.get());
  const PathMeasures sampled = measurePath(crossing, *checker);
  EXPECT_GT(sampled.minClearance, 0.0) << "the states at the resolution step over the wall";
  const PathLeastClearance along = leastClearanceAlong(crossing, *checker);
  EXPECT_EQ(along.least, 0.0);
  EXPECT_EQ(along.lowerBound, 0.0);

  // Over the top of the wall, the robot turning as it goes.
  ob::ScopedState<ob::SE2StateSpace> left(f.si), right(f.si), s(f.si);
  left->setXY(-1.0, 3.0);
  left->setYaw(0.3);
  right->setXY(1.3, 2.9);
  right->setYaw(-0.4);
  ompl::geometric::PathGeometric over(f.si, left.get(), right.get());
  const PathLeastClearance top = leastClearanceAlong(over, *checker);
  double dense = std::numeric_limits<double>::infinity(), denseAt = 0.0;
  for (int i = 0; i <= 20000; ++i) {
    f.si->getStateSpace()->interpolate(left.get(), right.get(), i / 20000.0, s.get());
    const double c = checker->clearance(s.get());
    if (c < dense) dense = c, denseAt = i / 20000.0;
  }
  f.si->getStateSpace()->interpolate(left.get(), right.get(), denseAt, s.get());
  double oracle = std::numeric_limits<double>::infinity();
  for (const Mesh& e : f.oracleEnvironment) {
    const Pose pose = poseFromState(s.get(), f.scene->space);
    const auto brute = oracle::meshDistance(f.scene->robot[0], pose, e, Pose::Identity());
    oracle = std::min(oracle, static_cast<double>(brute.value));
  }
  ASSERT_NEAR(dense, oracle, 1e-9) << "the dense samples' least, by the brute force";
  ASSERT_GT(dense, 0.0);
  EXPECT_LE(top.lowerBound, dense + 1e-12);
  EXPECT_LE(top.least, dense / 0.99 + 1e-12);
  EXPECT_GE(top.least, top.lowerBound);
  EXPECT_GE(top.lowerBound, 0.99 * top.least - 1e-9);
  EXPECT_LE(top.least, measurePath(over, *checker).minClearance);
  std::printf("[least clearance along] crossing: %zu queries; over the top: least %.9g, bound %.9g, %zu queries, "
              "20 001 samples' least %.9g\n",
              along.queries, top.least, top.lowerBound, top.queries, dense);
}

// A motion that leaves a wall its start is flush against (1e-9 of the scene away) is certified:
// its first steps are below kMinimumStepFraction, and each one's spare clearance grows by a
// factor, so they are taken until the steps are long again. Every such step was a rejection
// before, and certified planning from a flush start never solved (an outside review). The motion
// arriving there is certified too. A motion that slides along the wall at that distance is still
// rejected, and the oracle finds no collision on what is accepted.
TEST(CertifiedMotion, AMotionLeavingAWallItStartsFlushAgainstIsCertified) {
  SceneFixture f = test::thinWallFixture();
  auto checker = std::make_shared<MeshValidityChecker>(f.si, f.scene);
  f.si->setStateValidityChecker(checker);
  f.si->setup();
  ob::ScopedState<ob::SE2StateSpace> flush(f.si), away(f.si), along(f.si), s(f.si);
  lastStateBeforeTheWall(f, *checker, 1e-9, flush);
  const double flushClearance = checker->clearance(flush.get());
  ASSERT_GT(flushClearance, 0.0);
  ASSERT_LT(flushClearance, 1e-8 * checker->scale());
  away->setXY(flush->getX() - 1.0, flush->getY() + 1.0);
  away->setYaw(0.0);
  CertifiedMotionValidator certified(f.si, checker);
  EXPECT_TRUE(certified.checkMotion(flush.get(), away.get())) << "leaving the wall at 45 degrees";
  // The same motion arriving: its steps shrink with the clearance and graze before the end, which
  // a walk from the flush end reaches (path.check() of a path a goal tree grew asks this).
  EXPECT_TRUE(certified.checkMotion(away.get(), flush.get())) << "arriving at the wall at 45 degrees";
  for (int i = 0; i <= 400; ++i) {
    f.si->getStateSpace()->interpolate(flush.get(), away.get(), i / 400.0, s.get());
    EXPECT_FALSE(oracleCollides(f, s.get())) << "at " << i / 400.0;
  }
  along->setXY(flush->getX(), flush->getY() - 0.5);
  along->setYaw(0.0);
  EXPECT_FALSE(certified.checkMotion(flush.get(), along.get())) << "sliding along the wall 1e-9 from it";
}

// A path whose first state nearly touches the wall, then crosses it: the least clearance measured
// (at that state) is below the tolerance's floor (a millionth of the scene), so a search that
// stopped once the least was within tolerance stopped at once, with the crossing's intervals
// bounded at 0 unexamined, and `adsd plan` called such a path free (an outside review: a cow
// through a window's edge). Whether the path comes within the margin is decided too.
TEST(LeastClearanceAlong, AStateNearlyTouchingDoesNotHideACrossingAfterIt) {
  SceneFixture f = test::thinWallFixture();
  auto checker = std::make_shared<MeshValidityChecker>(f.si, f.scene);
  f.si->setStateValidityChecker(checker);
  f.si->setup();
  ob::ScopedState<ob::SE2StateSpace> start(f.si), goal(f.si), near(f.si);
  thinWallEnds(f, start, goal);
  // Along the crossing, the last state before the wall: clear by less than a ten-millionth of
  // the scene.
  f.si->getStateSpace()->interpolate(start.get(), goal.get(), 2.03 / 4.0, near.get());
  ASSERT_FALSE(checker->isValid(near.get())) << "the crossing is in the wall at x = 0";
  lastStateBeforeTheWall(f, *checker, 1e-8, near);
  const double nearClearance = checker->clearance(near.get());
  ASSERT_GT(nearClearance, 0.0);
  ASSERT_LT(nearClearance, 1e-7 * checker->scale());
  ompl::geometric::PathGeometric fromNear(f.si, near.get(), goal.get());
  const PathLeastClearance along = leastClearanceAlong(fromNear, *checker);
  EXPECT_EQ(along.least, 0.0) << "the wall right after the first state";
  EXPECT_EQ(along.lowerBound, 0.0);
  // And a path that only nearly touches, then turns away, is not called in contact.
  ob::ScopedState<ob::SE2StateSpace> back(f.si);
  back->setXY(-2.03, 1.0);
  back->setYaw(0.0);
  ompl::geometric::PathGeometric away(f.si, near.get(), back.get());
  const PathLeastClearance awayAlong = leastClearanceAlong(away, *checker);
  EXPECT_GT(awayAlong.least, 0.0);
  EXPECT_LE(awayAlong.least, nearClearance);
  EXPECT_GT(awayAlong.lowerBound, 0.0) << "proven clear, in " << awayAlong.queries << " queries";
}

// The states a path is measured and shown at (measuredStates): the validity-checking resolution's,
// as PathGeometric::interpolate() makes them, state for state; a path whose resolution would need
// millions of states (a path file of random states: `adsd view` took 25 s, 830 MB and a 138 MB
// page for 20 000 of them) is cut coarser, to about kMaxMeasuredStates states, motions whole.
TEST(MeasuredStates, AreTheResolutionsStatesUpToACap) {
  SceneFixture f = test::officeFixture();
  auto checker = std::make_shared<MeshValidityChecker>(f.si, f.scene);
  f.si->setStateValidityChecker(checker);
  f.si->setup();
  const ob::RealVectorBounds bounds = f.si->getStateSpace()->as<ob::SE2StateSpace>()->getBounds();
  std::mt19937 random(5);
  std::uniform_real_distribution<double> x(bounds.low[0], bounds.high[0]), y(bounds.low[1], bounds.high[1]),
      yaw(-3.0, 3.0);
  ob::ScopedState<ob::SE2StateSpace> s(f.si);
  const auto randomPath = [&](int states) {
    ompl::geometric::PathGeometric path(f.si);
    for (int i = 0; i < states; ++i) {
      s->setXY(x(random), y(random));
      s->setYaw(yaw(random));
      path.append(s.get());
    }
    return path;
  };

  const ompl::geometric::PathGeometric few = randomPath(4);
  ompl::geometric::PathGeometric interpolated(few);
  interpolated.interpolate();
  bool coarser = true;
  const ompl::geometric::PathGeometric measured = measuredStates(few, &coarser);
  EXPECT_FALSE(coarser);
  ASSERT_EQ(measured.getStateCount(), interpolated.getStateCount());
  ASSERT_GT(measured.getStateCount(), 40u) << "random motions across the office span many resolutions";
  for (std::size_t i = 0; i < measured.getStateCount(); ++i) {
    EXPECT_TRUE(f.si->equalStates(measured.getState(i), interpolated.getState(i))) << i;
  }

  const ompl::geometric::PathGeometric many = randomPath(3000);
  ompl::geometric::PathGeometric full(many);
  full.interpolate();
  ASSERT_GT(full.getStateCount(), 3 * kMaxMeasuredStates) << "the resolution's states, uncapped";
  const ompl::geometric::PathGeometric capped = measuredStates(many, &coarser);
  EXPECT_TRUE(coarser);
  EXPECT_LE(capped.getStateCount(), kMaxMeasuredStates + many.getStateCount());
  EXPECT_GE(capped.getStateCount(), kMaxMeasuredStates / 2);
  // Every state of the path is among them, in order.
  std::size_t next = 0;
  for (std::size_t i = 0; i < capped.getStateCount() && next < many.getStateCount(); ++i) {
    if (f.si->equalStates(capped.getState(i), many.getState(next))) ++next;
  }
  EXPECT_EQ(next, many.getStateCount());
  const PathMeasures m = measurePath(many, *checker);
  EXPECT_EQ(m.statesSampled, capped.getStateCount());
  EXPECT_TRUE(m.coarserThanResolution);
}

TEST(CertifiedMotion, ZeroLengthMotionIsOneQuery) {
  SceneFixture f = test::officeFixture();
  auto checker = std::make_shared<MeshValidityChecker>(f.si, f.scene);
  CertifiedMotionValidator certified(f.si, checker);
  ob::ScopedState<ob::SE2StateSpace> s(f.si);
  s->setXY(-6, 2.5);
  s->setYaw(0);
  EXPECT_TRUE(certified.checkMotion(s.get(), s.get()));
  EXPECT_EQ(certified.counts().clearanceSteps, 1u);
}

}  // namespace
}  // namespace adsd::planner
