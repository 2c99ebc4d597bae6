// The arm checkers (issue 17): clearance worked out by hand on the small arm; on the KR5 among
// boxes, ours against the brute force (every checked pair's exact distance, no broad phase) and
// against FCL behind the same broad phase; the query modes.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <random>

#include <ompl/base/ScopedState.h>
#include <ompl/base/SpaceInformation.h>

#include "adsd/error.h"
#include "adsd/mesh_hierarchy.h"
#include "adsd/planner/arm_validity_checker.h"
#include "adsd/planner/features.h"
#if ADSD_PLANNER_HAS_FCL
#include "adsd/planner/fcl_arm_validity_checker.h"
#endif
#include "arm_scenes.h"

namespace adsd::planner {
namespace {

ompl::base::SpaceInformationPtr spaceFor(const ArmModel& model) {
  auto si = std::make_shared<ompl::base::SpaceInformation>(std::make_shared<ArmStateSpace>(model));
  return si;
}

/// The small arm with the box's face at y = 0.55 (test::sliderScene), its space set up with our checker.
struct SmallArm {
  ArmScene scene = test::sliderScene(0.55);
  ompl::base::SpaceInformationPtr si = spaceFor(*scene.model);
  std::shared_ptr<ArmValidityChecker> checker = std::make_shared<ArmValidityChecker>(si, scene);
  SmallArm() {
    si->setStateValidityChecker(checker);
    si->setup();
  }
};

// turn = 0: the tip sphere (radius 0.03, its mesh at most 1 % larger) reaches y = 0.53, the box's
// face is at y = 0.55: clearance 0.02 less at most 0.0003; everything else is farther (the arm's
// box ends at y = 0.5, 0.05 away; base to arm: 0.1 vertically).
TEST(ArmValidityChecker, SmallArmClearanceAsWorkedOutByHand) {
  const SmallArm arm;
  const ArmScene& scene = arm.scene;
  const ompl::base::SpaceInformationPtr& si = arm.si;
  const std::shared_ptr<ArmValidityChecker>& checker = arm.checker;
  ompl::base::ScopedState<> s(si->getStateSpace());
  const double q[2] = {0.0, 0.0};
  si->getStateSpace()->as<ArmStateSpace>()->fromJoints(q, s.get());
  const double c = checker->clearance(s.get());
  EXPECT_LE(c, 0.02 + 1e-12);
  EXPECT_GE(c, 0.02 - 0.0003 - 1e-12);
  EXPECT_TRUE(checker->isValid(s.get()));
  EXPECT_EQ(checker->getSpecs().clearanceComputationType, ompl::base::StateValidityCheckerSpecs::EXACT);
  // Turned by pi: the arm points to -y, 0.45 + 0.1 from the box; the base-arm pair stays 0.1 apart.
  const double away[2] = {0.0, 3.14159265358979};
  si->getStateSpace()->as<ArmStateSpace>()->fromJoints(away, s.get());
  EXPECT_NEAR(checker->clearance(s.get()), 0.1, 1e-9);
  // The box moved into the tip's sphere: invalid, clearance 0.
  const ArmScene touching = test::sliderScene(0.52);
  auto checker2 = std::make_shared<ArmValidityChecker>(si, touching);
  si->getStateSpace()->as<ArmStateSpace>()->fromJoints(q, s.get());
  EXPECT_FALSE(checker2->isValid(s.get()));
  EXPECT_EQ(checker2->clearance(s.get()), 0.0);
  // A margin above the clearance makes the first scene's state invalid.
  auto careful = std::make_shared<ArmValidityChecker>(si, scene, 0.021);
  EXPECT_FALSE(careful->isValid(s.get()));
  EXPECT_THROW(ArmValidityChecker(si, scene, -1.0), InputError);
  EXPECT_THROW(ArmValidityChecker(si, scene, 0.0, DistanceOptions::aboveThreshold(0.1)), InputError);
}

// A NaN joint value passes OMPL's bounds test for a revolute joint; the checker threw the distance
// query's InputError into the planner for it. It is invalid, at clearance 0.
TEST(ArmValidityChecker, JointValuesThatAreNotNumbersAreInvalidAtClearanceZero) {
  const SmallArm arm;
  const ompl::base::SpaceInformationPtr& si = arm.si;
  const std::shared_ptr<ArmValidityChecker>& checker = arm.checker;
  ompl::base::ScopedState<> s(si->getStateSpace());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const auto& q : {std::array<double, 2>{nan, 0.0}, std::array<double, 2>{0.0, nan}}) {
    si->getStateSpace()->as<ArmStateSpace>()->fromJoints(q.data(), s.get());
    double dist = 1.0;
    EXPECT_NO_THROW(EXPECT_FALSE(checker->isValid(s.get())));
    EXPECT_NO_THROW(EXPECT_FALSE(checker->isValid(s.get(), dist)));
    EXPECT_EQ(dist, 0.0);
    EXPECT_NO_THROW(EXPECT_EQ(checker->clearance(s.get()), 0.0));
    EXPECT_NO_THROW(EXPECT_EQ(checker->obstacleClearanceUpTo(s.get(), 1.0), 0.0));
  }
}

// The message of a start or goal in collision names the pairs in contact (arm_planning_problem.cpp).
TEST(ArmValidityChecker, PairsInContactNameTheLinkAndTheObstacle) {
  const ArmScene touching = test::sliderScene(0.52);
  auto si = spaceFor(*touching.model);
  auto checker = std::make_shared<ArmValidityChecker>(si, touching);
  ompl::base::ScopedState<> s(si->getStateSpace());
  const double q[2] = {0.0, 0.0};
  si->getStateSpace()->as<ArmStateSpace>()->fromJoints(q, s.get());
  EXPECT_EQ(checker->pairsInContact(s.get()), std::vector<std::string>{"link 'tip' and obstacle 'box'"});
  EXPECT_EQ(checker->pairsInContact(s.get(), 0), std::vector<std::string>{"and 1 more pair"});
  // Turned away from the box: nothing touches.
  const double away[2] = {0.0, 3.14159265358979};
  si->getStateSpace()->as<ArmStateSpace>()->fromJoints(away, s.get());
  EXPECT_TRUE(checker->pairsInContact(s.get()).empty());
  // The box's face through the tip's sphere, most of it inside: touching, not inside (it was said
  // to be both, though the box is a solid and its inside a collision too: outside review).
  const ArmScene crossing = test::sliderScene(0.49);
  auto crossed = std::make_shared<ArmValidityChecker>(si, crossing);
  si->getStateSpace()->as<ArmStateSpace>()->fromJoints(q, s.get());
  EXPECT_EQ(crossed->pairsInContact(s.get()),
            (std::vector<std::string>{"link 'arm' and obstacle 'box'", "link 'tip' and obstacle 'box'"}));
}

// A primitive obstacle is a solid, as in MoveIt, whose FCL primitives are: the small arm wholly
// inside a box is in collision, though no surfaces meet (surface distance about 4.5). The same box
// as a mesh object is a surface, as MoveIt's meshes are (FCL's triangle trees), and the arm inside
// it free; so is a box of no thickness given as a solid (a quad in both windings, the back split
// along the other diagonal: closed and convex, it held half of its bounding box, an outside review).
TEST(ArmValidityChecker, ALinkInsideAPrimitiveObstacleIsInCollision) {
  auto model = std::make_shared<const ArmModel>(readUrdf(test::armTestData("slider_arm.urdf")));
  const Mesh shell = test::placedBox(Vec3(10.0, 10.0, 10.0), Vec3::Zero(), Pose::Identity(), "shell");
  std::vector<TriangleIndices> opened = shell.triangles();
  opened.pop_back();
  const ArmScene inside = makeArmScene(model, {shell}, "", {shell});
  const ArmScene insideMesh = makeArmScene(model, {shell});
  const ArmScene insideOpen = makeArmScene(model, {Mesh(shell.vertices(), opened, "open shell")}, "",
                                           {Mesh(shell.vertices(), opened, "open shell")});
  const Mesh sheet(std::vector<Vec3>{{-5, -5, 0}, {5, -5, 0.1}, {5, 5, 0.2}, {-5, 5, 0.1}},
                   std::vector<TriangleIndices>{{0, 1, 2}, {0, 2, 3}, {1, 0, 3}, {1, 3, 2}}, "sheet");
  ASSERT_TRUE(isClosedConvex(sheet));  // closed and convex, but it holds nothing
  const ArmScene beside = makeArmScene(model, {sheet}, "", {sheet});
  ASSERT_EQ(inside.solids.size(), 1u);
  EXPECT_TRUE(insideMesh.solids.empty());
  EXPECT_TRUE(insideOpen.solids.empty());
  EXPECT_TRUE(beside.solids.empty());
  auto si = spaceFor(*model);
  ompl::base::ScopedState<> s(si->getStateSpace());
  const double q[2] = {0.0, 0.0};
  si->getStateSpace()->as<ArmStateSpace>()->fromJoints(q, s.get());
  auto checkSolid = [&](const ArmValidityCheckerBase& checker, const std::string& which) {
    SCOPED_TRACE(which);
    EXPECT_FALSE(checker.isValid(s.get()));
    double dist = 1.0;
    EXPECT_FALSE(checker.isValid(s.get(), dist));
    EXPECT_EQ(dist, 0.0);
    EXPECT_EQ(checker.clearance(s.get()), 0.0);
    EXPECT_EQ(checker.clearanceUpTo(s.get(), 0.5), 0.0);
    EXPECT_EQ(checker.obstacleClearanceUpTo(s.get(), 0.5), 0.0);
    const std::vector<double> linkWeights(model->links.size(), 2.0);
    const std::vector<double> pairWeights(inside.selfPairs.enabledPairs().size(), 1.0);
    EXPECT_LE(checker.weightedClearanceUpTo(s.get(), linkWeights.data(), pairWeights.data(), 0.0, 1.0), 0.0);
    const std::vector<std::string> contacts = checker.pairsInContact(s.get(), 10);
    EXPECT_NE(std::find(contacts.begin(), contacts.end(), "link 'tip' inside obstacle 'shell'"), contacts.end());
  };
  checkSolid(ArmValidityChecker(si, inside), "ours");
#if ADSD_PLANNER_HAS_FCL
  checkSolid(FclArmValidityChecker(si, inside), "FCL's");
#endif
  for (const ArmScene* surface : {&insideMesh, &insideOpen}) {
    const ArmValidityChecker checker(si, *surface);
    EXPECT_TRUE(checker.isValid(s.get()));
    EXPECT_GT(checker.obstacleClearanceUpTo(s.get(), std::numeric_limits<double>::infinity()), 4.0);
    EXPECT_TRUE(checker.pairsInContact(s.get()).empty());
  }
}

// The other way round: a link's primitive <collision> elements are solids too (MoveIt's FCL
// shapes), so a 2 cm box inside the small arm's base box (surfaces 4 cm apart) is in collision,
// in both checkers, and named; moved out, it is not. Before, the state was valid at clearance
// 0.04 (an outside review: a sphere inside a SCARA's base, 265 of 300 colliding states valid).
TEST(ArmValidityChecker, AnObstacleInsideAPrimitiveLinkIsInCollision) {
  auto model = std::make_shared<const ArmModel>(readUrdf(test::armTestData("slider_arm.urdf")));
  for (const ArmLink& link : model->links) EXPECT_EQ(link.solids.size(), 1u) << link.name;  // one primitive each
  // The base box spans x in [-0.2, 0.2], y in [-0.1, 0.1], z in [0, 0.1] (its origin z = 0.05).
  const ArmScene held = makeArmScene(model, {test::placedBox(Vec3(0.02, 0.02, 0.02), Vec3(0.1, 0.0, 0.05),
                                                             Pose::Identity(), "grain")});
  const ArmScene apart = makeArmScene(model, {test::placedBox(Vec3(0.02, 0.02, 0.02), Vec3(0.1, 0.2, 0.05),
                                                              Pose::Identity(), "grain")});
  auto si = spaceFor(*model);
  ompl::base::ScopedState<> s(si->getStateSpace());
  const double q[2] = {0.0, 0.0};
  si->getStateSpace()->as<ArmStateSpace>()->fromJoints(q, s.get());
  const std::vector<double> linkWeights(model->links.size(), 2.0);
  const std::vector<double> pairWeights(held.selfPairs.enabledPairs().size(), 1.0);
  auto check = [&](const ArmValidityCheckerBase& inside, const ArmValidityCheckerBase& outside,
                   const std::string& which) {
    SCOPED_TRACE(which);
    EXPECT_FALSE(inside.isValid(s.get()));
    EXPECT_EQ(inside.clearance(s.get()), 0.0);
    EXPECT_EQ(inside.clearanceUpTo(s.get(), 0.5), 0.0);
    EXPECT_EQ(inside.obstacleClearanceUpTo(s.get(), 0.5), 0.0);
    EXPECT_LE(inside.weightedClearanceUpTo(s.get(), linkWeights.data(), pairWeights.data(), 0.0, 1.0), 0.0);
    const std::vector<std::string> contacts = inside.pairsInContact(s.get(), 10);
    ASSERT_EQ(contacts.size(), 1u);
    EXPECT_EQ(contacts[0], "obstacle 'grain' inside link 'base'");
    EXPECT_TRUE(outside.isValid(s.get()));
    EXPECT_NEAR(outside.clearance(s.get()), 0.09, 1e-12);  // the grain's face at y = 0.19, the base's at 0.1
  };
  check(ArmValidityChecker(si, held), ArmValidityChecker(si, apart), "ours");
#if ADSD_PLANNER_HAS_FCL
  check(FclArmValidityChecker(si, held), FclArmValidityChecker(si, apart), "FCL's");
#endif
}

// And a link inside another's primitive: a small box on a prismatic joint, two links away from a
// large box (so the pair is checked), slid into it and out of it.
TEST(ArmValidityChecker, ALinkInsideAnotherLinksPrimitiveIsInCollision) {
  const std::string path = testing::TempDir() + "adsd_link_in_link.urdf";
  {
    std::ofstream urdf(path);
    urdf << R"(<robot name="nested">
  <link name="hull"><collision><geometry><box size="1 1 1"/></geometry></collision></link>
  <joint name="mount" type="fixed"><parent link="hull"/><child link="arm"/><origin xyz="3 0 0"/></joint>
  <link name="arm"><collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision></link>
  <joint name="slide" type="prismatic"><parent link="arm"/><child link="pin"/><origin xyz="-3 0 0"/>
    <axis xyz="1 0 0"/><limit lower="0" upper="2" effort="1" velocity="1"/></joint>
  <link name="pin"><collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision></link>
</robot>
)";
  }
  auto model = std::make_shared<const ArmModel>(readUrdf(path));
  const ArmScene scene = makeArmScene(model, {});
  ASSERT_EQ(scene.selfPairs.enabledPairs().size(), 1u);  // hull and pin; arm is adjacent to both
  auto si = spaceFor(*model);
  ompl::base::ScopedState<> in(si->getStateSpace()), out(si->getStateSpace());
  const double qIn = 0.0, qOut = 1.0;
  si->getStateSpace()->as<ArmStateSpace>()->fromJoints(&qIn, in.get());
  si->getStateSpace()->as<ArmStateSpace>()->fromJoints(&qOut, out.get());
  auto check = [&](const ArmValidityCheckerBase& checker, const std::string& which) {
    SCOPED_TRACE(which);
    EXPECT_FALSE(checker.isValid(in.get()));
    EXPECT_EQ(checker.clearance(in.get()), 0.0);
    EXPECT_GT(checker.obstacleClearanceUpTo(in.get(), 1.0), 0.0);  // no obstacle: the link pair is not one
    const std::vector<std::string> contacts = checker.pairsInContact(in.get(), 10);
    ASSERT_EQ(contacts.size(), 1u);
    EXPECT_EQ(contacts[0], "link 'pin' inside link 'hull'");
    EXPECT_TRUE(checker.isValid(out.get()));
    EXPECT_NEAR(checker.clearance(out.get()), 0.45, 1e-12);
  };
  check(ArmValidityChecker(si, scene), "ours");
#if ADSD_PLANNER_HAS_FCL
  check(FclArmValidityChecker(si, scene), "FCL's");
#endif
}

/// States to compare with the brute force: \p regular, or \p sanitized in sanitizer builds, where
/// the brute force costs several times more.
int statesToCheck(int regular, int sanitized) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  (void)regular;
  return sanitized;
#else
  (void)sanitized;
  return regular;
#endif
}

// With a clearance that is a lower bound below the margin (here a cap of half of it), isValid(state,
// dist) called every state invalid, the bound never passing the margin: the threshold query
// decides there, so both calls give the brute force's answer (an outside review found the rigid
// checker's twin of this).
TEST(ArmValidityChecker, ValidityWithABoundedClearanceIsTheThresholdQuerysToo) {
  ADSD_REQUIRE_ROBOTS();
  const ArmScene scene = test::kr5BoxScene();
  auto si = spaceFor(*scene.model);
  const double margin = 0.002;
  auto capped = std::make_shared<ArmValidityChecker>(si, scene, margin, DistanceOptions::cappedAt(0.5 * margin));
  const auto* space = si->getStateSpace()->as<ArmStateSpace>();
  ompl::base::ScopedState<> s(si->getStateSpace());
  std::vector<double> q(space->dof());
  std::mt19937_64 rng(5);
  int valid = 0;
  for (int i = 0; i < statesToCheck(80, 20); ++i) {
    test::uniformJoints(*scene.model, rng, q.data());
    space->fromJoints(q.data(), s.get());
    const bool expected = test::bruteForceClearance(scene, q.data()) > margin;
    double dist = -1.0;
    EXPECT_EQ(capped->isValid(s.get()), expected) << "state " << i;
    EXPECT_EQ(capped->isValid(s.get(), dist), expected) << "state " << i << ", clearance bound " << dist;
    EXPECT_LE(dist, 0.5 * margin);
    valid += expected;
  }
  EXPECT_GT(valid, 0);
}

TEST(ArmValidityChecker, Kr5ClearanceEqualsTheBruteForceAndFcl) {
  ADSD_REQUIRE_ROBOTS();
  const ArmScene scene = test::kr5BoxScene();
  auto si = spaceFor(*scene.model);
  auto ours = std::make_shared<ArmValidityChecker>(si, scene);
  auto capped = std::make_shared<ArmValidityChecker>(si, scene, 0.0, DistanceOptions::cappedAt(0.05));
  auto tolerant = std::make_shared<ArmValidityChecker>(si, scene, 0.0, DistanceOptions::withTolerance(1e-3, 0.0));
#if ADSD_PLANNER_HAS_FCL
  auto fcl = std::make_shared<FclArmValidityChecker>(si, scene);
#endif
  const auto* space = si->getStateSpace()->as<ArmStateSpace>();
  ompl::base::ScopedState<> s(si->getStateSpace());
  std::vector<double> q(space->dof());
  std::mt19937_64 rng(3);  // uniform joint vectors within the limits, fixed seed
  const ArmModel& model = *scene.model;
  int valid = 0, invalid = 0;
  const int states = statesToCheck(300, 60);
  for (int i = 0; i < states; ++i) {
    test::uniformJoints(model, rng, q.data());
    space->fromJoints(q.data(), s.get());
    const double expected = test::bruteForceClearance(scene, q.data());
    const double got = ours->clearance(s.get());
    EXPECT_NEAR(got, expected, 1e-9 + 1e-10 * ours->scale()) << "state " << i;
    EXPECT_EQ(ours->isValid(s.get()), expected > 0.0) << "state " << i;
    (expected > 0.0 ? valid : invalid)++;
    const double c = capped->clearance(s.get());
    EXPECT_LE(c, expected + 1e-12);
    EXPECT_GE(c, std::min(expected, 0.05) - 1e-9);
    const double t = tolerant->clearance(s.get());
    EXPECT_LE(t, expected + 1e-12);
    EXPECT_GE(t, expected - 1e-3 - 1e-9);
#if ADSD_PLANNER_HAS_FCL
    EXPECT_NEAR(fcl->clearance(s.get()), expected, 1e-6) << "state " << i;
    EXPECT_EQ(fcl->isValid(s.get()), expected > 0.0) << "state " << i;
#endif
  }
  // The sample holds both kinds of states.
  EXPECT_GT(valid, states / 10);
  EXPECT_GT(invalid, states / 10);
  std::cout << "KR5 among boxes: " << valid << " valid, " << invalid << " invalid of " << states << " uniform states\n";
}

// The broad phase's box tree over many obstacle parts misses no pair: among 40 posts, our
// checker's clearance, obstacle clearance and validity equal the brute force's (no broad phase).
TEST(ArmValidityChecker, Kr5AmongManyPartsEqualsTheBruteForce) {
  ADSD_REQUIRE_ROBOTS();
  const ArmScene scene = test::kr5PostsScene();
  ASSERT_GE(scene.environment.size(), 40u);
  auto si = spaceFor(*scene.model);
  auto ours = std::make_shared<ArmValidityChecker>(si, scene);
  const auto* space = si->getStateSpace()->as<ArmStateSpace>();
  ompl::base::ScopedState<> s(si->getStateSpace());
  std::vector<double> q(space->dof());
  std::mt19937_64 rng(5);
  const ArmModel& model = *scene.model;
  int valid = 0;
  const int states = statesToCheck(50, 20);
  for (int i = 0; i < states; ++i) {
    test::uniformJoints(model, rng, q.data());
    space->fromJoints(q.data(), s.get());
    const double expected = test::bruteForceClearance(scene, q.data());
    const double obstacles = test::bruteForceClearance(scene, q.data(), false);
    const double tolerance = 1e-9 + 1e-10 * ours->scale();
    EXPECT_NEAR(ours->clearance(s.get()), expected, tolerance) << "state " << i;
    EXPECT_NEAR(ours->obstacleClearanceUpTo(s.get(), std::numeric_limits<double>::infinity()), obstacles, tolerance)
        << "state " << i;
    EXPECT_EQ(ours->isValid(s.get()), expected > 0.0) << "state " << i;
    valid += expected > 0.0;
  }
  EXPECT_GT(valid, states / 10);
  EXPECT_LT(valid, states);
}

// Among more obstacle parts than the first-pair threshold (64), the clearance queries measure one
// link-post pair before their broad phase and cull by it: their answers still equal the brute
// force's, pair by pair, weighted ones (the certified motion check's) included.
TEST(ArmValidityChecker, Kr5AmongMorePartsThanTheFirstPairThresholdEqualsTheBruteForce) {
  ADSD_REQUIRE_ROBOTS();
  // 216 posts, 4 cm square, 0.25 m apart: more parts than the threshold (kPartsForAFirstPair).
  const ArmScene scene = test::kr5PostsScene(7, 0.25, 0.04);
  ASSERT_GE(scene.environment.size(), 64u);
  auto si = spaceFor(*scene.model);
  auto ours = std::make_shared<ArmValidityChecker>(si, scene);
  const auto* space = si->getStateSpace()->as<ArmStateSpace>();
  ompl::base::ScopedState<> s(si->getStateSpace());
  const ArmModel& model = *scene.model;
  const std::vector<std::pair<std::size_t, std::size_t>> selfPairs = scene.selfPairs.enabledPairs();
  std::vector<double> q(space->dof()), linkWeights(model.links.size()), pairWeights(selfPairs.size());
  std::vector<Pose> poses;
  DistanceScratch scratch;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int valid = 0;
  const int states = statesToCheck(40, 15);
  for (int i = 0; i < states; ++i) {
    test::uniformJoints(model, rng, q.data());
    space->fromJoints(q.data(), s.get());
    // Random weights (a fifth of them 0) and subtrahend for the weighted query.
    for (double& w : linkWeights) w = unit(rng) < 0.2 ? 0.0 : 0.05 + 5.0 * unit(rng);
    for (double& w : pairWeights) w = unit(rng) < 0.2 ? 0.0 : 0.05 + 5.0 * unit(rng);
    const double subtract = 0.01 * unit(rng), cap = 0.5;
    // The brute force: every link against every post, every enabled link pair, exactly.
    forwardKinematics(model, q.data(), poses);
    const auto exact = [&](std::size_t link, const Mesh& other, const Pose& otherPose) {
      return distance(*model.links[link].collision, poses[link], other, otherPose, DistanceOptions::exactDistance(),
                      scratch).distance;
    };
    double obstacles = std::numeric_limits<double>::infinity(), links = obstacles, weighted = obstacles;
    for (std::size_t l = 0; l < model.links.size(); ++l) {
      if (!model.links[l].collision) continue;
      for (const Mesh& post : scene.environment) {
        const double d = exact(l, post, Pose::Identity());
        obstacles = std::min(obstacles, d);
        if (linkWeights[l] > 0.0) weighted = std::min(weighted, (d - subtract) / linkWeights[l]);
      }
    }
    for (std::size_t k = 0; k < selfPairs.size(); ++k) {
      const auto [a, b] = selfPairs[k];
      const double d = exact(a, *model.links[b].collision, poses[b]);
      links = std::min(links, d);
      if (pairWeights[k] > 0.0) weighted = std::min(weighted, (d - subtract) / pairWeights[k]);
    }
    const double expected = std::min(obstacles, links);
    const double tolerance = 1e-9 + 1e-10 * ours->scale();
    EXPECT_NEAR(ours->clearance(s.get()), expected, tolerance) << "state " << i;
    EXPECT_NEAR(ours->obstacleClearanceUpTo(s.get(), std::numeric_limits<double>::infinity()), obstacles, tolerance)
        << "state " << i;
    valid += expected > 0.0;
    const double got = ours->weightedClearanceUpTo(s.get(), linkWeights.data(), pairWeights.data(), subtract, cap);
    if (weighted <= 0.0) {  // the check rejects at once: any pair's value at or below 0 is the answer
      EXPECT_LE(got, 4.0 * tolerance) << "state " << i;
      EXPECT_GE(got, weighted - 4.0 * tolerance) << "state " << i;
    } else if (weighted < cap) {
      EXPECT_NEAR(got, weighted, 4.0 * tolerance) << "state " << i;
    } else {
      EXPECT_GE(got, cap - 4.0 * tolerance) << "state " << i;
    }
  }
  EXPECT_GT(valid, states / 10);
  EXPECT_LT(valid, states);
}

}  // namespace
}  // namespace adsd::planner
