// RigidBodyClearanceObjective: a path's cost is its least clearance at its states, start included,
// and a motion costs the same either way (OMPL's MaximizeMinClearanceObjective left out each
// motion's first state: an outside review).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>

#include <ompl/base/ScopedState.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/geometric/PathGeometric.h>

#include "adsd/planner/mesh_validity_checker.h"
#include "adsd/planner/rigid_body_clearance_objective.h"
#include "scene_fixtures.h"

namespace adsd::planner {
namespace {

using ompl::base::SE2StateSpace;

// The thin wall's bar leaves a start 1 cm from the wall's face straight away from it: the path's
// least clearance is the start's, 0.01 by construction (the faces are parallel). OMPL's objective
// costed the path by the states after the start, about 0.2 here.
TEST(RigidBodyClearanceObjective, APathsCostCountsItsStart) {
  const test::SceneFixture f = test::thinWallFixture();
  f.si->setStateValidityChecker(std::make_shared<MeshValidityChecker>(f.si, f.scene));
  f.si->setup();
  const RigidBodyClearanceObjective objective(f.si);
  ompl::base::ScopedState<SE2StateSpace> start(f.si), goal(f.si);
  start->setXY(-0.02 - 0.01, -1.0);  // the bar's face touches the wall's at x = -0.02
  start->setYaw(0.0);
  goal->setXY(-3.0, -1.0);
  goal->setYaw(0.0);
  ompl::geometric::PathGeometric path(f.si, start.get(), goal.get());
  EXPECT_NEAR(path.cost(std::make_shared<RigidBodyClearanceObjective>(f.si)).value(), 0.01, 1e-12);
  EXPECT_NEAR(objective.motionCost(start.get(), goal.get()).value(), 0.01, 1e-12);
  EXPECT_NEAR(objective.motionCost(goal.get(), start.get()).value(), 0.01, 1e-12);
}

// Random motions in the maze cost the same both ways, as the objective's isSymmetric() says
// (OMPL's: 182 of 200 differed, by up to 0.121), up to the rounding of the states sampled between
// (the same states, interpolated from either end).
TEST(RigidBodyClearanceObjective, MotionsCostTheSameEitherWay) {
  const test::SceneFixture f = test::mazeFixture();
  f.si->setStateValidityChecker(std::make_shared<MeshValidityChecker>(f.si, f.scene));
  f.si->setup();
  const RigidBodyClearanceObjective objective(f.si);
  ASSERT_TRUE(objective.isSymmetric());
  std::mt19937_64 rng(7);  // fixed seed
  std::uniform_real_distribution<double> x(f.volume.min().x(), f.volume.max().x()),
      y(f.volume.min().y(), f.volume.max().y()), yaw(-M_PI, M_PI), step(-1.0, 1.0);
  ompl::base::ScopedState<SE2StateSpace> a(f.si), b(f.si);
  int differentEnds = 0;
  for (int i = 0; i < 200; ++i) {
    a->setXY(x(rng), y(rng));
    a->setYaw(yaw(rng));
    b->setXY(a->getX() + step(rng), a->getY() + step(rng));
    b->setYaw(yaw(rng));
    f.si->enforceBounds(b.get());
    const double forward = objective.motionCost(a.get(), b.get()).value();
    const double backward = objective.motionCost(b.get(), a.get()).value();
    EXPECT_NEAR(forward, backward, 1e-9) << "motion " << i;
    const double ends = std::min(objective.stateCost(a.get()).value(), objective.stateCost(b.get()).value());
    EXPECT_LE(forward, ends);
    differentEnds += objective.stateCost(a.get()).value() != objective.stateCost(b.get()).value();
  }
  EXPECT_GT(differentEnds, 100);  // the ends' clearances differ, so leaving one out would show
}

}  // namespace
}  // namespace adsd::planner
