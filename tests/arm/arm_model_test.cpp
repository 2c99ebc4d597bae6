// The arm model (issue 17): URDF reading, primitives, forward kinematics against poses worked out
// by hand (the small URDF) and composed independently from the URDF's numbers (the KR5), joint
// order, disabled pairs (adjacency, SRDF), and one InputError naming the file per bad input.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <iostream>
#include <iterator>
#include <random>

#include "adsd/error.h"
#include "adsd/planner/arm_collision_pairs.h"
#include "adsd/planner/arm_kinematics.h"
#include "adsd/planner/arm_model.h"
#include "adsd/planner/arm_motion_bound.h"
#include "adsd/planner/arm_pair_sampling.h"
#include "adsd/planner/arm_state_space.h"
#include "adsd/planner/primitive_meshes.h"
#include "adsd/planner/srdf_groups.h"
#include "arm_test_data.h"
#include "scratch_dir.h"

namespace adsd::planner {
namespace {

using test::armTestData;
constexpr double kPi = 3.14159265358979323846;

TEST(ArmModel, SmallUrdfHasItsLinksJointsAndOrder) {
  const ArmModel m = readUrdf(armTestData("slider_arm.urdf"));
  EXPECT_EQ(m.name, "slider_arm");
  ASSERT_EQ(m.links.size(), 4u);
  EXPECT_EQ(m.links[0].name, "base");
  EXPECT_EQ(m.links[1].name, "carriage");
  EXPECT_EQ(m.links[2].name, "arm");
  EXPECT_EQ(m.links[3].name, "tip");
  ASSERT_EQ(m.dof(), 2u);
  EXPECT_EQ(m.jointIndex("slide"), 0u);
  EXPECT_EQ(m.jointIndex("turn"), 1u);
  EXPECT_THROW(m.jointIndex("tip_mount"), InputError);  // fixed: not in the joint vector
  const ArmJoint& slide = m.joints[m.activeJoints[0]];
  EXPECT_EQ(slide.type, ArmJointType::prismatic);
  EXPECT_DOUBLE_EQ(slide.lower, -0.1);
  EXPECT_DOUBLE_EQ(slide.upper, 0.2);
  const ArmJoint& turn = m.joints[m.activeJoints[1]];
  EXPECT_EQ(turn.type, ArmJointType::continuous);
  EXPECT_TRUE(turn.axis.isApprox(Vec3::UnitZ()));  // <axis xyz="0 0 2"/>, normalized
  for (const ArmLink& l : m.links) ASSERT_TRUE(l.collision.has_value()) << l.name;
  // Only collision geometry: the base's 9 m visual box is ignored.
  const Eigen::AlignedBox3d base = m.links[0].collision->bounds();
  EXPECT_TRUE(base.min().isApprox(Vec3(-0.2, -0.1, 0.0)));
  EXPECT_TRUE(base.max().isApprox(Vec3(0.2, 0.1, 0.1)));
}

// Closed form for q = (s, theta): carriage at (s, 0, 0.1); arm frame at (s, 0, 0.2) turned by
// pi/2 + theta about z; tip at the arm frame + R (0.5, 0, 0.025) = (s - 0.5 sin theta, 0.5 cos theta, 0.225).
TEST(ArmModel, SmallUrdfForwardKinematicsMatchesTheClosedForm) {
  const ArmModel m = readUrdf(armTestData("slider_arm.urdf"));
  std::vector<Pose> poses;
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> s(-0.1, 0.2), theta(-4.0, 4.0);
  for (int i = 0; i < 100; ++i) {
    const double q[2] = {s(rng), theta(rng)};
    forwardKinematics(m, q, poses);
    ASSERT_EQ(poses.size(), 4u);
    EXPECT_TRUE(poses[0].isApprox(Pose::Identity()));
    EXPECT_LT((poses[1].translation() - Vec3(q[0], 0, 0.1)).norm(), 1e-14);
    EXPECT_LT((poses[1].linear() - Eigen::Matrix3d::Identity()).norm(), 1e-14);
    const double a = kPi / 2 + q[1];
    Eigen::Matrix3d r;
    r << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
    EXPECT_LT((poses[2].translation() - Vec3(q[0], 0, 0.2)).norm(), 1e-14);
    EXPECT_LT((poses[2].linear() - r).norm(), 1e-14);
    EXPECT_LT((poses[3].translation() - Vec3(q[0] - 0.5 * std::sin(q[1]), 0.5 * std::cos(q[1]), 0.225)).norm(), 1e-14);
    EXPECT_LT((poses[3].linear() - r).norm(), 1e-14);
  }
}

TEST(ArmModel, StateSpaceBoundsTheSliderAndWrapsTheTurn) {
  const ArmModel m = readUrdf(armTestData("slider_arm.urdf"));
  ArmStateSpace space(m);
  ASSERT_EQ(space.dof(), 2u);
  ompl::base::State* a = space.allocState();
  ompl::base::State* b = space.allocState();
  const double qa[2] = {0.0, 3.0}, qb[2] = {0.3, -3.0};
  space.fromJoints(qa, a);
  space.fromJoints(qb, b);
  EXPECT_FALSE(space.satisfiesBounds(b));  // 0.3 > the slider's upper limit 0.2
  double dq[2];
  space.jointSteps(a, b, dq);
  EXPECT_NEAR(dq[0], 0.3, 1e-15);
  EXPECT_NEAR(dq[1], 2 * kPi - 6.0, 1e-12);  // the shorter arc, through pi
  // Interpolation follows jointSteps: halfway, the angle is 3 + (2 pi - 6)/2, wrapped.
  ompl::base::State* mid = space.allocState();
  space.interpolate(a, b, 0.5, mid);
  double qm[2];
  space.toJoints(mid, qm);
  EXPECT_NEAR(qm[0], 0.15, 1e-15);
  EXPECT_NEAR(std::remainder(qm[1] - (3.0 + 0.5 * dq[1]), 2 * kPi), 0.0, 1e-12);
  // Halfway from 3 to -3 the shorter arc is at pi exactly, which OMPL's SO(2) bounds test refuses
  // ([-pi, pi)): the state is -pi, the same angle, and within bounds (outside review: the
  // straight motion through it was refused by every checker).
  const double from[2] = {0.0, 3.0}, to[2] = {0.0, -3.0};
  space.fromJoints(from, a);
  space.fromJoints(to, b);
  space.interpolate(a, b, 0.5, mid);
  space.toJoints(mid, qm);
  EXPECT_EQ(qm[1], -kPi);
  EXPECT_TRUE(space.satisfiesBounds(mid));
  space.freeState(a), space.freeState(b), space.freeState(mid);
}

TEST(PrimitiveMeshes, HaveTheStatedSizesAndContainThePrimitive) {
  const Mesh box = boxMesh(Vec3(0.4, 0.2, 0.1));
  EXPECT_EQ(box.triangleCount(), 12u);
  EXPECT_TRUE(box.bounds().sizes().isApprox(Vec3(0.4, 0.2, 0.1)));
  // Cylinder: kCylinderSegments sides, corners at r / cos(pi / n), so the side faces touch r.
  const Mesh cyl = cylinderMesh(0.05, 0.1);
  EXPECT_EQ(cyl.triangleCount(), 4u * kCylinderSegments);
  EXPECT_NEAR(cyl.bounds().min().z(), -0.05, 1e-15);
  EXPECT_NEAR(cyl.bounds().max().z(), 0.05, 1e-15);
  double cornerRadius = 0.0;
  for (const Vec3& v : cyl.vertices()) cornerRadius = std::max(cornerRadius, v.head<2>().norm());
  EXPECT_NEAR(cornerRadius, 0.05 / std::cos(kPi / kCylinderSegments), 1e-15);
  // Sphere: every face's plane at least r from the centre (contains the ball), none more than
  // 1 % beyond (the documented resolution).
  const double r = 0.03;
  const Mesh sphere = sphereMesh(r);
  EXPECT_EQ(sphere.triangleCount(), static_cast<std::size_t>(2 * kSphereSegments * (kSphereRings - 1)));
  double nearest = 1e9, farthest = 0.0;
  for (std::size_t t = 0; t < sphere.triangleCount(); ++t) {
    const Vec3 n = (sphere.corner(t, 1) - sphere.corner(t, 0)).cross(sphere.corner(t, 2) - sphere.corner(t, 0)).normalized();
    nearest = std::min(nearest, std::abs(n.dot(sphere.corner(t, 0))));
  }
  for (const Vec3& v : sphere.vertices()) farthest = std::max(farthest, v.norm());
  EXPECT_GE(nearest, r * (1 - 1e-12));
  EXPECT_LE(farthest, 1.01 * r);
  EXPECT_THROW(boxMesh(Vec3(1, 0, 1)), InputError);
  EXPECT_THROW(cylinderMesh(-1, 1), InputError);
}

TEST(ArmCollisionPairs, AdjacencyDisablesParentChildAndRigidGroups) {
  const ArmModel m = readUrdf(armTestData("slider_arm.urdf"));
  const ArmCollisionPairs pairs(m);
  // base-carriage and carriage-arm: parent and child; arm-tip: one rigid group. Left: base-arm,
  // base-tip, and carriage-tip (the tip is fixed to the arm, not to the carriage).
  const std::vector<std::pair<std::size_t, std::size_t>> expected = {{0, 2}, {0, 3}, {1, 3}};
  EXPECT_EQ(pairs.enabledPairs(), expected);
  EXPECT_EQ(pairs.disabled().size(), 3u);
  EXPECT_FALSE(pairs.enabled(2, 1));
  EXPECT_TRUE(pairs.enabled(3, 1));
}

// A gripper fixed to a wrist that pitches on a forearm folds into the forearm at a pitch of 2.9:
// the pair must stay checked (an outside review found it disabled as "Adjacent", and the folded
// state accepted with 2.47 m of clearance). A hand hung from the forearm through a link without
// geometry is adjacent to it, as in MoveIt's setup assistant.
TEST(ArmCollisionPairs, AFixedGripperStaysCheckedAgainstTheForearmAndBareLinksAreSteppedOver) {
  test::ScratchDir dir;
  const std::string urdf = dir.write("tool.urdf", R"(<?xml version="1.0"?>
<robot name="tool">
  <link name="forearm"><collision><origin xyz="0.5 0 0"/><geometry><box size="1 0.1 0.1"/></geometry></collision></link>
  <link name="wrist"><collision><geometry><sphere radius="0.06"/></geometry></collision></link>
  <link name="gripper"><collision><origin xyz="0.3 0 0"/><geometry><box size="0.4 0.08 0.08"/></geometry>
    </collision></link>
  <link name="bare"/>
  <link name="hand"><collision><origin xyz="0 0.3 0"/><geometry><box size="0.05 0.2 0.05"/></geometry>
    </collision></link>
  <joint name="pitch" type="revolute"><parent link="forearm"/><child link="wrist"/><origin xyz="1.1 0 0"/>
    <axis xyz="0 0 1"/><limit lower="-2.9" upper="2.9" effort="1" velocity="1"/></joint>
  <joint name="mount" type="fixed"><parent link="wrist"/><child link="gripper"/></joint>
  <joint name="spin" type="continuous"><parent link="forearm"/><child link="bare"/><axis xyz="1 0 0"/></joint>
  <joint name="reach" type="prismatic"><parent link="bare"/><child link="hand"/><axis xyz="1 0 0"/>
    <limit lower="0" upper="0.5" effort="1" velocity="1"/></joint>
</robot>
)");
  const ArmModel m = readUrdf(urdf);
  const ArmCollisionPairs pairs(m);
  const std::size_t forearm = m.linkIndex("forearm"), wrist = m.linkIndex("wrist"),
                    gripper = m.linkIndex("gripper"), hand = m.linkIndex("hand");
  EXPECT_FALSE(pairs.enabled(forearm, wrist));   // parent and child
  EXPECT_FALSE(pairs.enabled(wrist, gripper));   // one rigid group
  EXPECT_TRUE(pairs.enabled(forearm, gripper));  // two joints apart: it can fold in
  EXPECT_FALSE(pairs.enabled(forearm, hand));    // only a link without geometry between them
  EXPECT_TRUE(pairs.enabled(wrist, hand));
  EXPECT_TRUE(pairs.enabled(gripper, hand));
  // Folded at the limit, a point of the gripper's box (0.2 along it) lies inside the forearm's box
  // (x in [0, 1], |y| and |z| below 0.05) while the gripper's far end sticks out of it: the two
  // boxes' surfaces cross.
  std::vector<Pose> poses;
  ASSERT_EQ(m.dof(), 3u);
  double q[3] = {0.0, 0.0, 0.0};
  q[m.jointIndex("pitch")] = 2.9;
  forwardKinematics(m, q, poses);
  const Vec3 inside = poses[gripper] * Vec3(0.2, 0.0, 0.0);
  EXPECT_GT(inside.x(), 0.0);
  EXPECT_LT(inside.x(), 1.0);
  EXPECT_LT(std::abs(inside.y()), 0.05);
  EXPECT_LT(std::abs(inside.z()), 0.05);
  EXPECT_GT(std::abs((poses[gripper] * Vec3(0.5, 0.0, 0.0)).y()), 0.05);
}

TEST(ArmCollisionPairs, SrdfDisablesItsPairsAndRoundTrips) {
  const ArmModel m = readUrdf(armTestData("slider_arm.urdf"));
  test::ScratchDir dir;
  const std::string srdf = dir.write("slider.srdf", R"(<?xml version="1.0"?>
<robot name="slider_arm">
  <group name="all"><joint name="slide"/></group>
  <disable_collisions link1="tip" link2="base" reason="Never"/>
</robot>
)");
  ArmCollisionPairs pairs(m);
  disablePairsFromSrdf(m, srdf, pairs);
  const std::vector<std::pair<std::size_t, std::size_t>> expected = {{0, 2}, {1, 3}};
  EXPECT_EQ(pairs.enabledPairs(), expected);
  writeSrdf(m, pairs, dir.path("written.srdf"));
  ArmCollisionPairs again(m);
  disablePairsFromSrdf(m, dir.path("written.srdf"), again);
  EXPECT_EQ(again.enabledPairs(), expected);
  // A link the model lacks, and a file that is not XML: errors naming the file.
  const std::string bad = dir.write("bad.srdf", "<robot><disable_collisions link1=\"tip\" link2=\"nope\"/></robot>");
  try {
    disablePairsFromSrdf(m, bad, pairs);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.srdf:1"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("nope"), std::string::npos) << e.what();
  }
  EXPECT_THROW(disablePairsFromSrdf(m, dir.write("junk.srdf", "<robot"), pairs), InputError);
  EXPECT_THROW(disablePairsFromSrdf(m, dir.path("absent.srdf"), pairs), InputError);
}

// MoveIt's SRDF elements for a link unchecked by default (an outside review: they were ignored
// without a word, so a goal MoveIt takes was refused as in collision):
// <disable_default_collisions> leaves every pair of the link unchecked but those
// <enable_collisions> names; <disable_collisions> pairs stay unchecked whatever else is said.
TEST(ArmCollisionPairs, SrdfDefaultDisabledLinksAndReenabledPairs) {
  const ArmModel m = readUrdf(armTestData("slider_arm.urdf"));  // base 0, carriage 1, arm 2, tip 3
  test::ScratchDir dir;
  const auto enabledWith = [&](const std::string& body) {
    ArmCollisionPairs pairs(m);
    disablePairsFromSrdf(m, dir.write("d.srdf", "<robot name=\"slider_arm\">" + body + "</robot>"), pairs);
    return pairs.enabledPairs();
  };
  using Pairs = std::vector<std::pair<std::size_t, std::size_t>>;
  EXPECT_EQ(enabledWith(""), Pairs({{0, 2}, {0, 3}, {1, 3}}));  // all but the adjacent pairs
  EXPECT_EQ(enabledWith(R"(<disable_default_collisions link="tip"/>)"), Pairs({{0, 2}}));
  EXPECT_EQ(enabledWith(R"(<disable_default_collisions link="tip"/><enable_collisions link1="tip" link2="carriage"/>)"),
            Pairs({{0, 2}, {1, 3}}));
  EXPECT_EQ(enabledWith(R"(<enable_collisions link1="base" link2="arm"/><disable_collisions link1="arm" )"
                        R"(link2="base"/>)"),
            Pairs({{0, 3}, {1, 3}}));
  const std::string bad = dir.write("bad.srdf", "<robot>\n<disable_default_collisions link=\"nope\"/></robot>");
  ArmCollisionPairs pairs(m);
  try {
    disablePairsFromSrdf(m, bad, pairs);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.srdf:2: <disable_default_collisions> names a link"), std::string::npos)
        << e.what();
  }
}

// An SRDF <chain> is the tree's path between its two links, up through their common ancestor when
// neither is below the other (MoveIt's hand-to-hand chains: an outside review found one refused).
TEST(SrdfGroups, ChainIsThePathBetweenItsLinks) {
  test::ScratchDir dir;
  const auto joint = [](const char* name, const char* parent, const char* child) {
    return std::string("<joint name=\"") + name + "\" type=\"revolute\"><parent link=\"" + parent +
           "\"/><child link=\"" + child + "\"/><axis xyz=\"0 0 1\"/><limit lower=\"-1\" upper=\"1\" "
           "effort=\"1\" velocity=\"1\"/></joint>\n";
  };
  std::string urdf = "<robot name=\"y\">\n";
  for (const char* link : {"torso", "upperL", "handL", "upperR", "handR", "head"}) {
    urdf += std::string("<link name=\"") + link + "\"/>\n";
  }
  urdf += joint("shoulderL", "torso", "upperL") + joint("elbowL", "upperL", "handL") +
          joint("shoulderR", "torso", "upperR") + joint("elbowR", "upperR", "handR") + joint("neck", "torso", "head");
  const ArmModel m = readUrdf(dir.write("y.urdf", urdf + "</robot>\n"));
  const auto chain = [&](const std::string& base, const std::string& tip) {
    const std::string srdf = dir.write("y.srdf", "<robot name=\"y\"><group name=\"g\"><chain base_link=\"" + base +
                                                     "\" tip_link=\"" + tip + "\"/></group></robot>\n");
    std::vector<std::string> names = srdfGroupJoints(m, srdf, "g").value();
    std::sort(names.begin(), names.end());
    return names;
  };
  using Names = std::vector<std::string>;
  EXPECT_EQ(chain("torso", "handL"), Names({"elbowL", "shoulderL"}));
  EXPECT_EQ(chain("handL", "handR"), Names({"elbowL", "elbowR", "shoulderL", "shoulderR"}));
  EXPECT_EQ(chain("upperL", "handR"), Names({"elbowR", "shoulderL", "shoulderR"}));
  EXPECT_THROW(chain("head", "head"), InputError);  // no joint: a group that moves nothing
}

// Groups including groups: a chain of them deeper than 100 is refused at the inclusion that goes
// too deep (30 000 crashed the expansion's recursion), and a group included many times over is
// expanded once (40 groups each including the next twice were expanded 2^40 times, never ending).
TEST(SrdfGroups, DeepAndRepeatedInclusionsAreBounded) {
  test::ScratchDir dir;
  const ArmModel m = readUrdf(armTestData("slider_arm.urdf"));
  const std::string joint = m.joints[m.activeJoints.front()].name;
  const auto groups = [&](int count, int includes) {
    std::string text = "<robot name=\"slider_arm\">\n";
    for (int i = 0; i < count; ++i) {
      text += "<group name=\"g" + std::to_string(i) + "\">";
      for (int k = 0; k < includes; ++k) text += "<group name=\"g" + std::to_string(i + 1) + "\"/>";
      text += "</group>\n";
    }
    return text + "<group name=\"g" + std::to_string(count) + "\"><joint name=\"" + joint + "\"/></group>\n</robot>\n";
  };
  EXPECT_EQ(srdfGroupJoints(m, dir.write("repeated.srdf", groups(40, 2)), "g0").value(),
            std::vector<std::string>({joint}));
  EXPECT_EQ(srdfGroupJoints(m, dir.write("deepest.srdf", groups(100, 1)), "g0").value(),
            std::vector<std::string>({joint}));
  const std::string tooDeep = dir.write("too_deep.srdf", groups(2000, 1));
  try {
    srdfGroupJoints(m, tooDeep, "g0");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), tooDeep + ":102: groups include groups more than 100 deep");
  }
}

// A URDF named as the SRDF was read as an SRDF disabling nothing, and an SRDF of another robot
// without a word (adversarial sweep): the first is refused, the second warned of, as MoveIt does.
TEST(ArmCollisionPairs, SrdfThatIsAUrdfOrOfAnotherRobot) {
  const ArmModel m = readUrdf(armTestData("slider_arm.urdf"));
  test::ScratchDir dir;
  ArmCollisionPairs pairs(m);
  const std::string urdf = armTestData("slider_arm.urdf");
  try {
    disablePairsFromSrdf(m, urdf, pairs);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(": a <link> element: this is a URDF, not an SRDF"), std::string::npos)
        << e.what();
  }
  const std::string other = dir.write("other.srdf", "<robot name=\"other\">\n"
                                                    "<disable_collisions link1=\"tip\" link2=\"base\"/>\n</robot>\n");
  const std::vector<std::string> warnings = disablePairsFromSrdf(m, other, pairs);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], other + ":1: the SRDF is for robot 'other', the URDF " + m.sourceFile +
                             " is robot 'slider_arm' (read on, as MoveIt does)");
  EXPECT_TRUE(disablePairsFromSrdf(m, dir.write("own.srdf", "<robot name=\"slider_arm\"/>"), pairs).empty());
}

// The small arm's three enabled pairs can never touch (the arm turns 0.1 above the base's top and
// holds the tip 0.5 from the carriage), so the sampling pass disables all as "Never"; the SRDF it
// writes says so.
TEST(ArmCollisionPairs, SamplingPassDisablesPairsNeverInContact) {
  const ArmModel m = readUrdf(armTestData("slider_arm.urdf"));
  ArmCollisionPairs pairs(m);
  const PairSamplingResult r = disablePairsBySampling(m, pairs, 200, 7);
  EXPECT_EQ(r.states, 200u);
  EXPECT_EQ(r.pairsTested, 3u);
  EXPECT_EQ(r.neverInContact, 3u);
  EXPECT_EQ(r.alwaysInContact, 0u);
  EXPECT_TRUE(pairs.enabledPairs().empty());
  test::ScratchDir dir;
  writeSrdf(m, pairs, dir.path("sampled.srdf"));
  std::ifstream in(dir.path("sampled.srdf"));
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find(R"(link1="base" link2="arm" reason="Never")"), std::string::npos) << text;
  EXPECT_THROW(disablePairsBySampling(m, pairs, 0), InputError);
}

TEST(ArmCollisionPairs, SamplingPassOnTheKr5KeepsPairsThatSometimesTouch) {
  ADSD_REQUIRE_ROBOTS();
  const ArmModel m = readUrdf(test::kr5Urdf());
  ArmCollisionPairs pairs(m);
  const std::size_t before = pairs.enabledPairs().size();
  const PairSamplingResult r = disablePairsBySampling(m, pairs, 300, 3);
  EXPECT_EQ(r.pairsTested, before);
  EXPECT_EQ(pairs.enabledPairs().size(), before - r.alwaysInContact - r.neverInContact);
  std::cout << "KR5 sampling pass, 300 states: " << before << " pairs tested, " << r.alwaysInContact << " always, "
            << r.neverInContact << " never in contact, " << pairs.enabledPairs().size() << " left\n";
}

// Each failure mode of readUrdf: one InputError whose message names the file and what is wrong.
/// A URDF file and what its InputError must say.
struct BadUrdf {
  std::string file, text, mustSay;
};

/// Writes each case into \p dir and expects readUrdf to refuse it in one line naming the file and
/// saying the case's words.
void expectRefused(test::ScratchDir& dir, const std::vector<BadUrdf>& cases) {
  for (const BadUrdf& c : cases) {
    const std::string path = dir.write(c.file, c.text);
    try {
      readUrdf(path);
      ADD_FAILURE() << c.file << ": no error";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(c.file), std::string::npos) << c.file << ": " << what;
      EXPECT_NE(what.find(c.mustSay), std::string::npos) << c.file << ": " << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << c.file << ": one line: " << what;
    }
  }
}

TEST(ArmModel, BadUrdfsGiveOneInputErrorNamingTheFile) {
  test::ScratchDir dir;
  dir.write("garbage.stl", "solid x\nthis is not an STL file\n");
  const std::string link = R"(<link name="a"><collision><geometry><box size="1 1 1"/></geometry></collision></link>)";
  const auto robot = [&](const std::string& body) { return "<robot name=\"r\">" + body + "</robot>"; };
  const auto joint = [](const std::string& name, const std::string& type, const std::string& parent,
                        const std::string& child) {
    return "<joint name=\"" + name + "\" type=\"" + type + "\"><parent link=\"" + parent + "\"/><child link=\"" +
           child + "\"/><axis xyz=\"0 0 1\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/></joint>";
  };
  const std::vector<BadUrdf> cases = {
      {"not_xml.urdf", "<robot name=\"r\"><link name=\"a\">", "not XML"},
      {"no_robot.urdf", "<model/>", "no <robot>"},
      {"missing_mesh.urdf", robot(R"(<link name="a"><collision><geometry><mesh filename="absent.stl"/></geometry></collision></link>)"), "absent.stl"},
      {"unreadable_mesh.urdf", robot(R"(<link name="a"><collision><geometry><mesh filename="garbage.stl"/></geometry></collision></link>)"), "link 'a'"},
      {"missing_package.urdf", robot(R"(<link name="a"><collision><geometry><mesh filename="package://pkg/m.stl"/></geometry></collision></link>)"), "package://pkg/m.stl"},
      {"unknown_type.urdf", robot(link + "<link name=\"b\"/>" + joint("j", "hinge", "a", "b")), "unknown type 'hinge'"},
      {"floating.urdf", robot(link + "<link name=\"b\"/>" + joint("j", "floating", "a", "b")), "joint 'j' is floating"},
      {"planar.urdf", robot(link + "<link name=\"b\"/>" + joint("j", "planar", "a", "b")), "joint 'j' is planar"},
      {"cycle.urdf", robot(link + "<link name=\"b\"/><link name=\"c\"/>" + joint("j1", "revolute", "a", "b") +
                           joint("j2", "revolute", "b", "c") + joint("j3", "revolute", "c", "b")), "cycle"},
      {"loop.urdf", robot(link + "<link name=\"b\"/>" + joint("j1", "revolute", "a", "b") + joint("j2", "revolute", "b", "a")), "cycle"},
      {"two_roots.urdf", robot(link + "<link name=\"b\"/>"), "root links"},
      // A second <robot> after the first was dropped in silence (outside review).
      {"two_robots.urdf", robot(link) + "\n<robot name=\"s\">" + link + "</robot>",
       "two_robots.urdf:2: not XML: a second root element <robot> after <robot> (line 1)"},
      {"no_links.urdf", "<robot name=\"r\"/>", "no <link> elements"},
      {"two_links_a.urdf", robot(link + link), "two links are named 'a'"},
      {"undefined_link.urdf", robot(link + joint("j", "revolute", "a", "zz")), "'zz'"},
      {"bad_limits.urdf", robot(link + "<link name=\"b\"/>" + "<joint name=\"j\" type=\"revolute\"><parent link=\"a\"/><child link=\"b\"/><limit lower=\"1\" upper=\"-1\" effort=\"1\" velocity=\"1\"/></joint>"), "joint 'j'"},
  };
  expectRefused(dir, cases);
  EXPECT_THROW(readUrdf(dir.path("absent.urdf")), InputError);
}

// A gripper whose second finger mimics the first (URDF <mimic>), as MoveIt moves it: one
// coordinate drives both fingers, the second at multiplier x the first's position + offset.
// Poses worked out by hand from the URDF's numbers.
const char* kGripper = R"(<robot name="gripper">
  <link name="palm"><collision><geometry><box size="0.1 0.1 0.02"/></geometry></collision></link>
  <link name="left"><collision><geometry><box size="0.01 0.01 0.05"/></geometry></collision></link>
  <link name="right"><collision><geometry><box size="0.01 0.01 0.05"/></geometry></collision></link>
  <link name="thumb"><collision><origin xyz="0.05 0 0"/><geometry><box size="0.1 0.01 0.01"/></geometry>
    </collision></link>
  <joint name="left_finger" type="prismatic"><parent link="palm"/><child link="left"/>
    <origin xyz="0.02 0 0.04"/><axis xyz="1 0 0"/><limit lower="0" upper="0.03" effort="1" velocity="1"/></joint>
  <joint name="right_finger" type="prismatic"><parent link="palm"/><child link="right"/>
    <origin xyz="-0.02 0 0.04"/><axis xyz="-1 0 0"/><limit lower="0" upper="0.03" effort="1" velocity="1"/>
    <mimic joint="left_finger"/></joint>
  <joint name="thumb_turn" type="revolute"><parent link="palm"/><child link="thumb"/>
    <origin xyz="0 0.05 0"/><axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/>
    <mimic joint="right_finger" multiplier="-20" offset="0.1"/></joint>
</robot>
)";

TEST(ArmModel, MimicJointsFollowTheirLeader) {
  test::ScratchDir dir;
  const ArmModel m = readUrdf(dir.write("gripper.urdf", kGripper));
  ASSERT_EQ(m.dof(), 1u);  // the two followers are not coordinates
  EXPECT_EQ(m.jointIndex("left_finger"), 0u);
  EXPECT_THROW(m.jointIndex("right_finger"), InputError);
  const double q = 0.02;
  std::vector<Pose> poses;
  forwardKinematics(m, &q, poses);
  // left: 0.02 along x from its origin at x 0.02; right: 0.02 along -x from x -0.02.
  EXPECT_NEAR((poses[m.linkIndex("left")].translation() - Vec3(0.04, 0, 0.04)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((poses[m.linkIndex("right")].translation() - Vec3(-0.04, 0, 0.04)).norm(), 0.0, 1e-15);
  // The thumb follows the right finger (which follows the left): -20 x 0.02 + 0.1 = -0.3 rad.
  const Eigen::Matrix3d turn = poses[m.linkIndex("thumb")].linear();
  EXPECT_NEAR(std::atan2(turn(1, 0), turn(0, 0)), -0.3, 1e-15);
}

// The certified motion bound counts each follower: a step of the one coordinate moves both
// fingers, so they part by twice the step, and the thumb's tip (0.1 from its axis) turns by 20x.
TEST(ArmMotionBound, MimicJointsMoveWithTheCoordinateTheyFollow) {
  test::ScratchDir dir;
  const ArmModel m = readUrdf(dir.write("gripper.urdf", kGripper));
  const ArmMotionBound bound(m);
  const double dq = 0.01;
  const std::size_t left = m.linkIndex("left"), right = m.linkIndex("right"), thumb = m.linkIndex("thumb");
  EXPECT_NEAR(bound.pairDisplacement(left, right, &dq), 2 * dq, 1e-15);
  std::vector<double> moved(m.links.size());
  bound.linkDisplacements(&dq, moved.data());
  EXPECT_NEAR(moved[right], dq, 1e-15);
  // The thumb's box reaches 0.1 along x and 0.005 across from its axis: |(0.1, 0.005)| x 20 x dq.
  EXPECT_NEAR(moved[thumb], std::hypot(0.1, 0.005) * 20 * dq, 1e-15);
  EXPECT_NEAR(bound.pairDisplacement(left, thumb, &dq), dq + std::hypot(0.1, 0.005) * 20 * dq, 1e-15);
}

TEST(ArmModel, MimicJointsThatCannotFollowAreRefusedNamingTheJoint) {
  test::ScratchDir dir;
  const std::string palm = R"(<link name="a"><collision><geometry><box size="1 1 1"/></geometry></collision></link>)"
                           R"(<link name="b"/><link name="c"/>)";
  const auto joint = [](const std::string& name, const std::string& type, const std::string& child,
                        const std::string& mimic) {
    return "<joint name=\"" + name + "\" type=\"" + type + "\"><parent link=\"a\"/><child link=\"" + child +
           "\"/><axis xyz=\"0 0 1\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>" + mimic +
           "</joint>";
  };
  const auto robot = [](const std::string& body) { return "<robot name=\"r\">" + body + "</robot>"; };
  expectRefused(dir, {
      {"no_leader.urdf",
       robot(palm + joint("j1", "revolute", "b", "<mimic joint=\"zz\"/>") + joint("j2", "revolute", "c", "")),
       "joint 'j1': <mimic joint='zz'> of joint 'j1' names no movable joint"},
      {"mimic_cycle.urdf", robot(palm + joint("j1", "revolute", "b", "<mimic joint=\"j2\"/>") +
                                 joint("j2", "revolute", "c", "<mimic joint=\"j1\"/>")),
       "comes back to itself"},
      {"wrapping.urdf", robot(palm + joint("j1", "continuous", "b", "") +
                              joint("j2", "revolute", "c", "<mimic joint=\"j1\" multiplier=\"0.5\"/>")),
       "joint 'j2': follows continuous joint 'j1' with multiplier 0.5"},
      {"huge_multiplier.urdf", robot(palm + joint("j1", "revolute", "b", "") +
                                     joint("j2", "revolute", "c", "<mimic joint=\"j1\" multiplier=\"1e300\"/>")),
       "multiplier and offset must be finite"},
      // Each within 1e75, but composed 1e150: the poses overflowed (an outside review).
      {"chained_multipliers.urdf",
       robot(palm + "<link name=\"d\"/>" + joint("j1", "revolute", "b", "") +
             joint("j2", "revolute", "c", "<mimic joint=\"j1\" multiplier=\"1e75\"/>") +
             joint("j3", "revolute", "d", "<mimic joint=\"j2\" multiplier=\"1e75\"/>")),
       "joint 'j3': its <mimic> chain to joint 'j1' composes to multiplier 1e+150 and offset 0"},
  });
  // A whole multiple of a continuous joint's angle turns by whole turns where it wraps: accepted.
  EXPECT_NO_THROW(readUrdf(dir.write("whole.urdf", robot(palm + joint("j1", "continuous", "b", "") +
                                                             joint("j2", "revolute", "c",
                                                                   "<mimic joint=\"j1\" multiplier=\"-2\"/>")))));
}

// A chain of followers composes its multipliers and offsets whichever way the URDF orders it:
// here j4 follows j2, which follows j3, which follows the one coordinate j1, and a follower comes
// both before and after its leader. Each joint's chain is composed once and reused by the joints
// that reach it. By hand, for the leader at q: j3 = 3q - 0.1, j2 = -0.5 j3 + 0.2 = -1.5q + 0.25,
// j4 = 2 j2 + 0.1 = -3q + 0.6.
TEST(ArmModel, MimicChainsComposeWhicheverOrderTheirJointsComeIn) {
  test::ScratchDir dir;
  const auto joint = [](const std::string& name, const std::string& parent, const std::string& child,
                        const std::string& mimic) {
    return "<joint name=\"" + name + "\" type=\"revolute\"><parent link=\"" + parent + "\"/><child link=\"" +
           child + "\"/><axis xyz=\"0 0 1\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>" +
           mimic + "</joint>";
  };
  const ArmModel m = readUrdf(dir.write(
      "chain.urdf",
      "<robot name=\"r\"><link name=\"a\"><collision><geometry><box size=\"1 1 1\"/></geometry></collision>"
      "</link><link name=\"b\"/><link name=\"c\"/><link name=\"d\"/><link name=\"e\"/>" +
          joint("j4", "a", "b", "<mimic joint=\"j2\" multiplier=\"2\" offset=\"0.1\"/>") +
          joint("j2", "a", "c", "<mimic joint=\"j3\" multiplier=\"-0.5\" offset=\"0.2\"/>") +
          joint("j1", "a", "d", "") + joint("j3", "a", "e", "<mimic joint=\"j1\" multiplier=\"3\" offset=\"-0.1\"/>") +
          "</robot>"));
  ASSERT_EQ(m.dof(), 1u);
  const struct {
    const char* name;
    double multiplier, offset;
  } expected[] = {{"j2", -1.5, 0.25}, {"j3", 3.0, -0.1}, {"j4", -3.0, 0.6}};
  for (const auto& e : expected) {
    SCOPED_TRACE(e.name);
    const auto found =
        std::find_if(m.joints.begin(), m.joints.end(), [&](const ArmJoint& j) { return j.name == e.name; });
    ASSERT_NE(found, m.joints.end());
    EXPECT_EQ(found->mimicCoordinate, 0);
    EXPECT_NEAR(found->mimicMultiplier, e.multiplier, 1e-15);
    EXPECT_NEAR(found->mimicOffset, e.offset, 1e-15);
  }
}

// urdfdom logs and drops a <collision> element it cannot read, and reads on: the link went
// unchecked for collisions with exit 0 (adversarial sweep). Each is refused, naming the link's line.
TEST(ArmModel, CollisionElementsUrdfdomCannotReadAreRefused) {
  test::ScratchDir dir;
  const auto robot = [](const std::string& collision) {
    return "<robot name=\"r\">\n<link name=\"a\">\n"
           "<collision><geometry><box size=\"1 1 1\"/></geometry></collision>\n" +
           collision + "\n</link>\n</robot>\n";
  };
  const std::vector<std::string> unreadable = {
      R"(<collision><origin xyz="nan 0 0"/><geometry><box size="1 1 1"/></geometry></collision>)",
      R"(<collision><origin rpy="0 nan 0"/><geometry><box size="1 1 1"/></geometry></collision>)",
      R"(<collision><geometry><box size="nan 1 1"/></geometry></collision>)",
      R"(<collision><geometry><mesh filename="m.stl" scale="nan 1 1"/></geometry></collision>)",
      R"(<collision><geometry><mesh filename="m.stl" scale="1 1"/></geometry></collision>)",
      R"(<collision><geometry/></collision>)",
  };
  for (const std::string& collision : unreadable) {
    const std::string path = dir.write("dropped.urdf", robot(collision));
    // urdfdom's reason joins the one line, on no other line.
    testing::internal::CaptureStderr();
    try {
      readUrdf(path);
      ADD_FAILURE() << collision << ": no error";
    } catch (const InputError& e) {
      const std::string what = e.what();
      const std::string start = path + ":2: link 'a': urdfdom read 1 of its 2 <collision> elements (urdfdom: ";
      const std::string end = "); refused rather than leave the link unchecked";
      EXPECT_EQ(what.rfind(start, 0), 0u) << collision << ": " << what;
      EXPECT_GT(what.size(), start.size() + end.size()) << "urdfdom's reason is left out: " << what;
      EXPECT_EQ(what.compare(what.size() - end.size(), end.size(), end), 0) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "") << collision;
  }
  // Two shapes in one <geometry>: urdfdom keeps the first and drops the second without a word.
  const std::string twoShapes = dir.write(
      "two.urdf", robot("<collision><geometry><sphere radius=\"0.1\"/>\n<box size=\"2 2 2\"/></geometry></collision>"));
  try {
    readUrdf(twoShapes);
    ADD_FAILURE() << "two shapes in one <geometry>: no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), twoShapes + ":5: link 'a': a second shape in one <geometry>, which urdfdom "
                                                 "would drop; give each shape a <collision> element of its own");
  }
}

// Collision geometry placed or scaled out of range, or scaled to nothing: named by the URDF, the
// <collision> element's line and the field (was: the link alone, by Mesh: "l2: vertex 0 has
// coordinate x = 1e+200"; the mesh file for a scale of 1e80; a scale of 0 accepted as a point).
TEST(ArmModel, CollisionOriginAndMeshScaleOutOfRangeAreRefusedNamingTheField) {
  test::ScratchDir dir;
  dir.write("t.stl", "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
                     "endloop\nendfacet\nendsolid t\n");
  const auto robot = [](const std::string& inside) {
    return "<robot name=\"r\">\n<link name=\"a\">\n<collision>" + inside + "</collision>\n</link>\n</robot>\n";
  };
  struct Case {
    std::string collision, mustSay;
  };
  const std::vector<Case> cases = {
      {R"(<origin xyz="1e200 0 0"/><geometry><box size="1 1 1"/></geometry>)", "<collision> <origin xyz> must be finite and within 1e75"},
      {R"(<origin xyz="1e75 0 0"/><geometry><box size="1e70 1 1"/></geometry>)", "the collision geometry reaches"},
      {R"(<geometry><mesh filename="t.stl" scale="0 1 1"/></geometry>)", "<mesh scale> must be finite"},
      {R"(<geometry><mesh filename="t.stl" scale="1 1e-320 1"/></geometry>)", "<mesh scale> must be finite"},
      {R"(<geometry><mesh filename="t.stl" scale="1e80 1 1"/></geometry>)", "<mesh scale> (1e+80, 1, 1) takes a vertex beyond 1e75"},
  };
  for (const Case& c : cases) {
    const std::string path = dir.write("out_of_range.urdf", robot(c.collision));
    try {
      readUrdf(path);
      ADD_FAILURE() << c.collision << ": no error";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(path + ":3: link 'a': ", 0), 0u) << what;
      EXPECT_NE(what.find(c.mustSay), std::string::npos) << what;
    }
  }
  // A mirroring scale is kept: left and right arms share one mesh.
  const ArmModel mirrored = readUrdf(dir.write("mirrored.urdf", robot(R"(<geometry><mesh filename="t.stl" scale="1 -1 1"/></geometry>)")));
  EXPECT_TRUE(mirrored.links[0].collision->bounds().min().isApprox(Vec3(0, -1, 0)));
}

// A joint origin beyond 1e75 was accepted; limits of +-1e308 overflowed the range, so that every
// state came out invalid ("not solved"). Refused, naming the URDF, the joint's line and the field.
TEST(ArmModel, JointOriginAndLimitsOutOfRangeAreRefusedNamingTheJoint) {
  test::ScratchDir dir;
  const auto robot = [](const std::string& origin, const std::string& limit) {
    return "<robot name=\"r\">\n<link name=\"a\"/>\n<link name=\"b\"/>\n"
           "<joint name=\"j\" type=\"prismatic\">\n<parent link=\"a\"/><child link=\"b\"/>\n" +
           origin + "<axis xyz=\"1 0 0\"/>\n" + limit + "\n</joint>\n</robot>\n";
  };
  const std::string limit = R"(<limit lower="-1" upper="1" effort="1" velocity="1"/>)";
  struct Case {
    std::string text, mustSay;
  };
  const std::vector<Case> cases = {
      {robot(R"(<origin xyz="1e100 0 0"/>)", limit), "<origin xyz> must be finite and within 1e75, got (1e+100, 0, 0)"},
      {robot("", R"(<limit lower="-1e308" upper="1e308" effort="1" velocity="1"/>)"),
       "<limit lower= upper=> must be finite, within 1e75, with lower <= upper, got [-1e+308, 1e+308]"},
      {robot("", R"(<limit lower="0" upper="1e76" effort="1" velocity="1"/>)"),
       "<limit lower= upper=> must be finite, within 1e75, with lower <= upper, got [0, 1e+76]"},
  };
  for (const Case& c : cases) {
    const std::string path = dir.write("joint.urdf", c.text);
    try {
      readUrdf(path);
      ADD_FAILURE() << c.text << ": no error";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()), path + ":4: joint 'j': " + c.mustSay);
    }
  }
  EXPECT_EQ(readUrdf(dir.write("fine.urdf", robot(R"(<origin xyz="1e6 0 0"/>)", limit))).joints[0].upper, 1.0);
}

// MoveIt bounds a joint by its <safety_controller>'s soft limits within <limit> (an outside
// review: a goal between the two, which MoveIt would refuse, was planned to). An absent soft limit
// reads 0 (urdfdom), and soft limits that leave nothing of <limit> are refused.
TEST(ArmModel, SafetyControllerSoftLimitsBoundTheJoint) {
  test::ScratchDir dir;
  const auto robot = [](const std::string& type, const std::string& safety) {
    return "<robot name=\"r\">\n<link name=\"a\"/>\n<link name=\"b\"/>\n<joint name=\"j\" type=\"" + type +
           "\">\n<parent link=\"a\"/><child link=\"b\"/>\n<axis xyz=\"1 0 0\"/>\n"
           "<limit lower=\"-0.4\" upper=\"2.5\" effort=\"1\" velocity=\"1\"/>\n" + safety + "\n</joint>\n</robot>\n";
  };
  const auto range = [&](const std::string& type, const std::string& safety) {
    const ArmModel m = readUrdf(dir.write("safe.urdf", robot(type, safety)));
    return std::make_pair(m.joints[0].lower, m.joints[0].upper);
  };
  using Range = std::pair<double, double>;
  EXPECT_EQ(range("revolute", ""), Range(-0.4, 2.5));
  EXPECT_EQ(range("revolute", R"(<safety_controller soft_lower_limit="0.9" soft_upper_limit="3" k_velocity="1"/>)"),
            Range(0.9, 2.5));
  EXPECT_EQ(range("prismatic", R"(<safety_controller soft_lower_limit="-2" soft_upper_limit="1" k_velocity="1"/>)"),
            Range(-0.4, 1.0));
  EXPECT_EQ(range("revolute", R"(<safety_controller soft_upper_limit="1" k_velocity="1"/>)"), Range(0.0, 1.0));
  const std::string path =
      dir.write("apart.urdf", robot("revolute", R"(<safety_controller soft_lower_limit="3" soft_upper_limit="4" )"
                                                R"(k_velocity="1"/>)"));
  try {
    readUrdf(path);
    ADD_FAILURE() << "soft limits beyond <limit>: no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), path + ":4: joint 'j': its <safety_controller soft_lower_limit= "
                                            "soft_upper_limit=> and <limit> must share a range (MoveIt plans within "
                                            "both), got [3, 4] and [-0.4, 2.5]");
  }
}

// MoveIt's default state, which `adsd srdf` tests for reason Default and `adsd plan` starts
// unnamed joints at, puts a joint whose limits exclude 0 at their midpoint (an outside review:
// the nearer limit, where two links overlapped that the midpoint keeps apart, disabled a pair that
// does collide).
TEST(ArmModel, DefaultPositionIsZeroOrTheMidpointOfTheLimits) {
  ArmJoint joint;
  joint.type = ArmJointType::revolute;
  joint.lower = 0.5, joint.upper = 2.5;
  EXPECT_EQ(defaultPosition(joint), 1.5);
  joint.lower = -3.07, joint.upper = -0.07;
  EXPECT_DOUBLE_EQ(defaultPosition(joint), -1.57);
  joint.lower = -1.0, joint.upper = 2.0;
  EXPECT_EQ(defaultPosition(joint), 0.0);
  joint.type = ArmJointType::continuous;
  joint.lower = -kPi, joint.upper = kPi;
  EXPECT_EQ(defaultPosition(joint), 0.0);
  // A bar that dips into the base's box at its lower limit (0.6 rad: its tip 0.578 out, 0.005 up)
  // and hangs clear of it at the midpoint (1.5 rad): the pair is in contact only at the limit.
  test::ScratchDir dir;
  const ArmModel m = readUrdf(dir.write("dip.urdf", R"(<robot name="dip">
  <link name="base"><collision><origin xyz="0.5 0 0.05"/><geometry><box size="0.3 0.3 0.1"/></geometry></collision>
  </link>
  <joint name="turn" type="revolute"><parent link="base"/><child link="post"/><origin xyz="0 0 0.4"/>
    <axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <link name="post"><collision><geometry><sphere radius="0.02"/></geometry></collision></link>
  <joint name="tilt" type="revolute"><parent link="post"/><child link="bar"/>
    <axis xyz="0 1 0"/><limit lower="0.6" upper="2.4" effort="1" velocity="1"/></joint>
  <link name="bar"><collision><origin xyz="0.35 0 0"/><geometry><box size="0.7 0.03 0.03"/></geometry></collision>
  </link>
</robot>
)"));
  EXPECT_EQ(defaultJointVector(m), std::vector<double>({0.0, 1.5}));
  ArmCollisionPairs atDefault(m), atLimit(m);
  const std::size_t base = m.linkIndex("base"), bar = m.linkIndex("bar");
  EXPECT_EQ(disablePairsInContactAt(m, atDefault, defaultJointVector(m)), 0u);
  EXPECT_TRUE(atDefault.enabled(base, bar));
  EXPECT_EQ(disablePairsInContactAt(m, atLimit, {0.0, 0.6}), 1u);
  EXPECT_FALSE(atLimit.enabled(base, bar));
}

// Adversarial review: offsets of 1e75 each, down a chain of three joints, placed the tip at 3e75.
// The distance query refused it naming neither the file nor the joint, after `adsd plan` had
// printed "solved yes". The sum is bounded when the URDF is read; so is a prismatic joint's travel.
TEST(ArmModel, OffsetsAddingUpBeyond1e75DownAChainAreRefusedNamingTheJoint) {
  test::ScratchDir dir;
  const auto chain = [](const std::string& x, const std::string& upper) {
    std::string text = "<robot name=\"r\">\n<link name=\"l0\"/>\n<link name=\"l1\"/>\n<link name=\"l2\"/>\n"
                       "<link name=\"l3\"/>\n";
    for (int k = 1; k <= 3; ++k) {
      text += "<joint name=\"j" + std::to_string(k) + "\" type=\"prismatic\">\n<parent link=\"l" +
              std::to_string(k - 1) + "\"/><child link=\"l" + std::to_string(k) + "\"/>\n<origin xyz=\"" + x +
              " 0 0\"/><axis xyz=\"1 0 0\"/>\n<limit lower=\"0\" upper=\"" + upper +
              "\" effort=\"1\" velocity=\"1\"/>\n</joint>\n";
    }
    return text + "</robot>\n";
  };
  const std::string far = dir.write("far.urdf", chain("1e75", "0"));
  try {
    readUrdf(far);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), far + ":11: joint 'j2': its link 'l2' may lie 2e+75 from the root link (the "
                                           "joints' offsets and prismatic travel down the chain added up), beyond 1e75");
  }
  const std::string sliding = dir.write("sliding.urdf", chain("1", "4e74"));
  try {
    readUrdf(sliding);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(sliding + ":16: joint 'j3': its link 'l3' may lie 1.2e+75"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(readUrdf(dir.write("near.urdf", chain("3e74", "0"))).links.size(), 4u);
}

// An axis's norm overflowed (0 0 1e300: a zero axis, then "pose is not rigid" from the distance
// query, naming no file) or underflowed (0 -1e-170 0: refused as a zero vector); both name a
// direction.
TEST(ArmModel, JointAxisOfAnyFiniteScaleIsADirection) {
  test::ScratchDir dir;
  const auto robot = [](const std::string& axis) {
    return "<robot name=\"r\">\n<link name=\"a\"/>\n<link name=\"b\"/>\n"
           "<joint name=\"j\" type=\"revolute\">\n<parent link=\"a\"/><child link=\"b\"/>\n<axis xyz=\"" +
           axis + "\"/>\n<limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>\n</joint>\n</robot>\n";
  };
  EXPECT_EQ(readUrdf(dir.write("huge.urdf", robot("0 0 1e300"))).joints[0].axis, Vec3::UnitZ());
  EXPECT_EQ(readUrdf(dir.write("tiny.urdf", robot("0 -1e-170 0"))).joints[0].axis, -Vec3::UnitY());
  EXPECT_TRUE(readUrdf(dir.write("diagonal.urdf", robot("1e300 1e300 0"))).joints[0].axis.isApprox(
      Vec3(1, 1, 0).normalized()));
  // urdfdom refuses inf and nan components itself: its reason joins our one line, where it was
  // printed above it on several lines with urdfdom's own source lines ("at line 440 in
  // ./urdf_parser/src/joint.cpp", easily taken for a line of the URDF).
  const std::string infinite = dir.write("infinite.urdf", robot("0 0 inf"));
  testing::internal::CaptureStderr();
  try {
    readUrdf(infinite);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(infinite + ": urdfdom cannot read this URDF: ", 0), 0u) << what;
    EXPECT_NE(what.find("joint [j]"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
  const std::string zero = dir.write("zero.urdf", robot("0 0 0"));
  try {
    readUrdf(zero);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), zero + ":4: joint 'j': the axis must be a non-zero vector");
  }
}

// TinyXML parses an element by a recursive call: a deep enough file overflowed the stack (SIGSEGV,
// adversarial sweep). Refused first, naming the file; markup inside comments, CDATA and attribute
// values, and self-closing elements, do not count as nesting.
TEST(ArmModel, XmlNestedTooDeeplyIsRefusedBeforeParsing) {
  test::ScratchDir dir;
  std::string deep;
  for (int i = 0; i < 200000; ++i) deep += "<z>";
  for (int i = 0; i < 200000; ++i) deep += "</z>";
  const std::string urdf = dir.write("deep.urdf", "<robot name=\"x\">\n<link name=\"a\"/>" + deep + "</robot>");
  try {
    readUrdf(urdf);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(urdf + ":2: elements nested more than 500 deep", 0), 0u) << e.what();
  }
  const ArmModel m = readUrdf(armTestData("slider_arm.urdf"));
  ArmCollisionPairs pairs(m);
  const std::string srdf = dir.write("deep.srdf", "<robot name=\"slider_arm\">" + deep + "</robot>");
  try {
    disablePairsFromSrdf(m, srdf, pairs);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(srdf + ":1: elements nested more than 500 deep", 0), 0u) << e.what();
  }

  std::string notNesting = "<!-- ";
  for (int i = 0; i < 600; ++i) notNesting += "<z>";
  notNesting += " --><![CDATA[";
  for (int i = 0; i < 600; ++i) notNesting += "<z>";
  notNesting += "]]>";
  for (int i = 0; i < 600; ++i) notNesting += "<z a=\"/><y>\"/>";
  const ArmModel shallow = readUrdf(dir.write("shallow.urdf", "<?xml version=\"1.0\"?><robot name=\"x\">" + notNesting +
                                                                 "<link name=\"a\"/></robot>"));
  EXPECT_EQ(shallow.links.size(), 1u);
}

// A chain of fixed links as long as the reader takes is read; one more link is refused before
// urdfdom parses the file (a chain of 200 000 crashed urdfdom's recursive parse).
TEST(ArmModel, MoreLinksThanTheReaderTakesAreRefusedBeforeUrdfdom) {
  test::ScratchDir dir;
  auto chain = [](int links) {
    std::string text = "<robot name=\"chain\">\n<link name=\"l0\"/>\n";
    for (int i = 1; i < links; ++i) {
      const std::string n = std::to_string(i), parent = std::to_string(i - 1);
      text += "<link name=\"l" + n + "\"/><joint name=\"j" + n + "\" type=\"fixed\"><parent link=\"l" + parent +
              "\"/><child link=\"l" + n + "\"/></joint>\n";
    }
    return text + "</robot>\n";
  };
  EXPECT_EQ(readUrdf(dir.write("longest.urdf", chain(10000))).links.size(), 10000u);
  const std::string tooLong = dir.write("too_long.urdf", chain(10001));
  try {
    readUrdf(tooLong);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), tooLong + ": 10001 <link> elements, more than the 10000 the reader takes (a robot "
                                                "has tens)");
  }
}

// TinyXML reports row 0 where it does not know the place (an empty file, one cut off): the line is
// left out then, and given where it is known (was ":0:" for both).
TEST(ArmModel, XmlErrorsGiveTheLineWhenTinyXmlKnowsIt) {
  test::ScratchDir dir;
  const auto errorOf = [](const std::function<void()>& read) {
    try {
      read();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string empty = dir.write("empty.urdf", "");
  EXPECT_EQ(errorOf([&] { readUrdf(empty); }), empty + ": not XML: Error document empty.");
  const std::string badEnd = dir.write("bad_end.urdf", "<robot name=\"r\">\n<link name=\"a\">\n</robot>\n");
  EXPECT_EQ(errorOf([&] { readUrdf(badEnd); }).rfind(badEnd + ":3: not XML: ", 0), 0u);
  const ArmModel m = readUrdf(armTestData("slider_arm.urdf"));
  ArmCollisionPairs pairs(m);
  const std::string emptySrdf = dir.write("empty.srdf", "\n\n");
  EXPECT_EQ(errorOf([&] { disablePairsFromSrdf(m, emptySrdf, pairs); }), emptySrdf + ": not XML: Error document empty.");
  const std::string cut = dir.write("cut.srdf", "<robot name=\"slider_arm\">\n<disable_collisions link1=\"a\"\n");
  EXPECT_EQ(errorOf([&] { disablePairsFromSrdf(m, cut, pairs); }).rfind(cut + ":2: not XML: ", 0), 0u);
}

TEST(ArmModel, MeshScaleAndFileUrisAndPackageSearchPath) {
  test::ScratchDir dir;
  std::filesystem::create_directories(dir.root() / "share" / "pkg" / "meshes");
  std::filesystem::create_directories(dir.root() / "flat" / "meshes");
  const std::string stl = "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n";
  dir.write("share/pkg/meshes/t.stl", stl);
  dir.write("flat/meshes/t.stl", stl);
  const auto urdf = [](const std::string& uri, const std::string& scale) {
    return "<robot name=\"r\"><link name=\"a\"><collision><geometry><mesh filename=\"" + uri + "\"" + scale +
           "/></geometry></collision></link></robot>";
  };
  // DIR/NAME/REST first, then DIR/REST.
  const ArmModel viaName = readUrdf(dir.write("a.urdf", urdf("package://pkg/meshes/t.stl", " scale=\"2 3 4\"")),
                                    {dir.path("nowhere"), dir.path("share")});
  EXPECT_TRUE(viaName.links[0].collision->bounds().max().isApprox(Vec3(2, 3, 0)));
  const ArmModel viaRest = readUrdf(dir.write("b.urdf", urdf("package://other/meshes/t.stl", "")), {dir.path("flat")});
  EXPECT_TRUE(viaRest.links[0].collision->bounds().max().isApprox(Vec3(1, 1, 0)));
  const ArmModel viaFile = readUrdf(dir.write("c.urdf", urdf("file://" + dir.path("flat/meshes/t.stl"), "")));
  EXPECT_EQ(viaFile.links[0].collision->triangleCount(), 1u);
  const ArmModel relative = readUrdf(dir.write("d.urdf", urdf("flat/meshes/t.stl", "")));
  EXPECT_EQ(relative.links[0].collision->triangleCount(), 1u);
}

// The KR5's palm pose composed by hand from the URDF's numbers (not by forwardKinematics):
//   world -> base_link:  T(0, -0.5, 0) Rx(-1.57)
//   base_link -> shoulder: T(0, 0, 0.203) Rz(q1)
//   shoulder -> bicep:   T(0.075, 0.0735, 0.13) Ry(q2)
//   bicep -> elbow:      T(0, -0.00549999999999999, 0.27) Ry(q3)
//   elbow -> forearm:    T(0.10599996023205, -0.0680006418263501, 0.0900000000000001) Rx(q4)
//   forearm -> wrist:    T(0.187000000000001, -0.0289999999999998, 0) Ry(q5)
//   wrist -> palm:       T(0.0519999999999999, 0.0289999999999996, 0) Rx(q6)
TEST(ArmModel, Kr5ForwardKinematicsMatchesTransformsComposedFromTheUrdf) {
  ADSD_REQUIRE_ROBOTS();
  const ArmModel m = readUrdf(test::kr5Urdf());
  ASSERT_EQ(m.dof(), 6u);
  const char* names[] = {"shoulder_yaw", "shoulder_pitch", "elbow_pitch", "elbow_roll", "wrist_pitch", "wrist_roll"};
  for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(m.jointIndex(names[i]), i);
  EXPECT_EQ(m.links[0].name, "world");
  EXPECT_FALSE(m.links[0].collision.has_value());  // no geometry: never checked
  const auto T = [](double x, double y, double z) { return Pose(Eigen::Translation3d(x, y, z)); };
  const auto R = [](double a, const Vec3& axis) { return Pose(Eigen::AngleAxisd(a, axis)); };
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  std::vector<Pose> poses;
  for (int i = 0; i < 50; ++i) {
    double q[6];
    for (double& v : q) v = u(rng);
    forwardKinematics(m, q, poses);
    const Pose base = T(0, -0.5, 0) * R(-1.57, Vec3::UnitX());
    const Pose shoulder = base * T(0, 0, 0.203) * R(q[0], Vec3::UnitZ());
    const Pose bicep = shoulder * T(0.075, 0.0735, 0.13) * R(q[1], Vec3::UnitY());
    const Pose elbow = bicep * T(0, -0.00549999999999999, 0.27) * R(q[2], Vec3::UnitY());
    const Pose forearm = elbow * T(0.10599996023205, -0.0680006418263501, 0.0900000000000001) * R(q[3], Vec3::UnitX());
    const Pose wrist = forearm * T(0.187000000000001, -0.0289999999999998, 0) * R(q[4], Vec3::UnitY());
    const Pose palm = wrist * T(0.0519999999999999, 0.0289999999999996, 0) * R(q[5], Vec3::UnitX());
    const Pose expected[] = {base, shoulder, bicep, elbow, forearm, wrist, palm};
    for (std::size_t l = 1; l < 8; ++l) {
      EXPECT_LT((poses[l].matrix() - expected[l - 1].matrix()).norm(), 1e-12) << m.links[l].name;
    }
  }
}

TEST(ArmModel, WamReadsThroughThePackageSearchPath) {
  ADSD_REQUIRE_ROBOTS();
  EXPECT_THROW(readUrdf(test::wamUrdf()), InputError);  // package://herb_description/ without a search path
  const ArmModel m = readUrdf(test::wamUrdf(), {test::wamSearchDir()});
  EXPECT_EQ(m.dof(), 7u);
  std::size_t withGeometry = 0;
  for (const ArmLink& l : m.links) withGeometry += l.collision.has_value();
  EXPECT_GE(withGeometry, 8u);
  const ArmCollisionPairs pairs(m);
  EXPECT_FALSE(pairs.enabledPairs().empty());
}

}  // namespace
}  // namespace adsd::planner
