// `adsd srdf ROBOT.urdf --out ROBOT.srdf` run as a user runs it, on a robot of primitives built so
// that every link pair's fate is known by hand (the geometry is in the comments below): which
// pairs are adjacent, in contact in the default pose, in every state, in some, or in none. The
// written SRDF must list exactly the expected pairs with MoveIt's reasons, an arm problem must
// read it, and bad input must write nothing.
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>
#include <tinyxml.h>

#include "run_adsd.h"

namespace {

using namespace adsd_test;
namespace fs = std::filesystem;

// World z up; the base's top face at z = 0.05.
//   base    box 2 x 2 x 0.1 at the origin (the root).
//   slider  prismatic `slide` along x from (0, 0, 0.5), s in [-1, 1]: a cube of side 0.2 there.
//   rider   revolute `tilt` about x at the slider's origin, [-0.3, 0.3]: a ball of radius 0.05
//           0.3 below it, so at z 0.2-0.215: never near the base's top (0.05), the sleeve
//           (z 0.45-0.55) or the flag (z 0.375-0.425).
//   inner   revolute `wrist` about z at the rider's origin, [-1, 1]: a ball of radius 0.05 0.1 up
//           its z axis, on the slider's top face (z 0.6) at tilt 0 and at most 0.0045 below it at
//           tilt +-0.3: across that face in every state. (Contact is between surfaces, as in FCL's
//           mesh queries: a ball wholly inside the cube would not touch it.)
//   sleeve  revolute `yaw` about z from (0, 0, 0.5), [0, 2]: a bar 3 x 0.1 x 0.1 along x, 0.8 off
//           the axis (y = 0.8 at yaw 0). It meets the slider and the inner ball only when the
//           slider is far out and the yaw near pi/2 (never at the default pose, yaw 0).
//   flag    revolute `wave` about z from (0.8, 0, 0.05), [0.02, 0.12] (its default, MoveIt's
//           midpoint of limits that exclude 0, is 0.07): a bar 0.8 x 0.05 x 0.05 pointing back
//           towards the origin at z 0.375-0.425. At the default pose it reaches under the slider's
//           bottom face (z 0.4) 0.056 off the x axis; with the slider moved out, it clears it.
const char* kRobot = R"(<?xml version="1.0"?>
<robot name="judged">
  <link name="base"><collision><geometry><box size="2 2 0.1"/></geometry></collision></link>
  <link name="slider"><collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision></link>
  <link name="rider"><collision><origin xyz="0 0 -0.3"/><geometry><sphere radius="0.05"/></geometry></collision></link>
  <link name="inner"><collision><origin xyz="0 0 0.1"/><geometry><sphere radius="0.05"/></geometry></collision></link>
  <link name="sleeve"><collision><origin xyz="0 0.8 0"/><geometry><box size="3 0.1 0.1"/></geometry></collision></link>
  <link name="flag"><collision><origin xyz="-0.4 0 0.35"/><geometry><box size="0.8 0.05 0.05"/></geometry>
    </collision></link>
  <joint name="slide" type="prismatic"><parent link="base"/><child link="slider"/><origin xyz="0 0 0.5"/>
    <axis xyz="1 0 0"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <joint name="tilt" type="revolute"><parent link="slider"/><child link="rider"/>
    <axis xyz="1 0 0"/><limit lower="-0.3" upper="0.3" effort="1" velocity="1"/></joint>
  <joint name="wrist" type="revolute"><parent link="rider"/><child link="inner"/>
    <axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <joint name="yaw" type="revolute"><parent link="base"/><child link="sleeve"/><origin xyz="0 0 0.5"/>
    <axis xyz="0 0 1"/><limit lower="0" upper="2" effort="1" velocity="1"/></joint>
  <joint name="wave" type="revolute"><parent link="base"/><child link="flag"/><origin xyz="0.8 0 0.05"/>
    <axis xyz="0 0 1"/><limit lower="0.02" upper="0.12" effort="1" velocity="1"/></joint>
</robot>
)";

using Entry = std::tuple<std::string, std::string, std::string>;  // link1 < link2, reason

/// The <disable_collisions> entries of an SRDF file, each pair's links in name order.
std::set<Entry> disabledPairs(const fs::path& srdf) {
  TiXmlDocument doc(srdf.string().c_str());
  EXPECT_TRUE(doc.LoadFile()) << srdf;
  std::set<Entry> out;
  const TiXmlElement* robot = doc.FirstChildElement("robot");
  if (!robot) return out;
  for (const TiXmlElement* e = robot->FirstChildElement("disable_collisions"); e;
       e = e->NextSiblingElement("disable_collisions")) {
    std::string a = e->Attribute("link1"), b = e->Attribute("link2");
    if (b < a) std::swap(a, b);
    out.emplace(a, b, e->Attribute("reason"));
  }
  return out;
}

const std::set<Entry> kAdjacent = {{"base", "slider", "Adjacent"},
                                   {"base", "sleeve", "Adjacent"},
                                   {"base", "flag", "Adjacent"},
                                   {"rider", "slider", "Adjacent"},
                                   {"inner", "rider", "Adjacent"}};
const std::set<Entry> kNever = {{"base", "rider", "Never"},  {"base", "inner", "Never"},
                                {"rider", "sleeve", "Never"}, {"flag", "rider", "Never"},
                                {"flag", "inner", "Never"},   {"flag", "sleeve", "Never"}};

std::set<Entry> joined(std::set<Entry> a, const std::set<Entry>& b) {
  a.insert(b.begin(), b.end());
  return a;
}

fs::path writeRobot(const fs::path& dir) {
  std::ofstream(dir / "judged.urdf") << kRobot;
  return dir / "judged.urdf";
}

// The setup assistant's order: a pair in contact in the default pose is disabled as Default before
// the sampling could find it in contact in every state (the inner ball), so Always shows only
// without the default pose's rule.
TEST(SrdfCommand, WritesTheAdjacentAndDefaultPairs) {
  const fs::path dir = workDirectory();
  const fs::path urdf = writeRobot(dir);
  const PlanRun r = runAdsd("srdf", {urdf.string(), "--out", (dir / "judged.srdf").string(), "--states", "2000"}, dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(disabledPairs(dir / "judged.srdf"),
            joined(kAdjacent, {{"flag", "slider", "Default"}, {"inner", "slider", "Default"}}));
  EXPECT_NE(r.out.find("in contact in the default pose: 'slider' and 'flag'"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("in contact in the default pose: 'slider' and 'inner'"), std::string::npos) << r.out;
  // The two pairs that touch in some states only, and the six that never do, stay checked.
  EXPECT_NE(r.out.find("checked     8 pairs"), std::string::npos) << r.out;
}

TEST(SrdfCommand, NeverAndNoDefaultChangeWhatIsDisabled) {
  const fs::path dir = workDirectory();
  const fs::path urdf = writeRobot(dir);
  PlanRun r =
      runAdsd("srdf", {urdf.string(), "--out", (dir / "never.srdf").string(), "--states", "2000", "--never"}, dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(disabledPairs(dir / "never.srdf"),
            joined(joined(kAdjacent, kNever), {{"flag", "slider", "Default"}, {"inner", "slider", "Default"}}));
  // Without the default pose's rule, the slider and the flag are apart in some states: checked;
  // the inner ball crosses the slider's face in every state: Always.
  r = runAdsd("srdf", {urdf.string(), "--out", (dir / "kept.srdf").string(), "--states", "2000", "--no-default"}, dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(disabledPairs(dir / "kept.srdf"), joined(kAdjacent, {{"inner", "slider", "Always"}}));
  EXPECT_NE(r.out.find("in contact in every state: 'slider' and 'inner'"), std::string::npos) << r.out;
}

// The SRDF written is what an arm problem names: planning from the default pose, in contact
// there, is refused without it and solved with it.
TEST(SrdfCommand, ArmProblemStartingInTheDefaultPoseIsSolvedWithTheWrittenSrdf) {
  const fs::path dir = workDirectory();
  writeRobot(dir);
  std::ofstream(dir / "scene.yaml") << "name: empty\nworld:\n  collision_objects: []\n";
  std::ofstream(dir / "request.yaml")
      << "group_name: all\nstart_state:\n  joint_state:\n    name: [slide, tilt, wrist, yaw, wave]\n"
         "    position: [0, 0, 0, 0, 0.07]\ngoal_constraints:\n  - joint_constraints:\n"
         "      - {joint_name: slide, position: -0.9, tolerance_above: 0.001, tolerance_below: 0.001}\n";
  const std::string cfg = "[problem]\nname = judged\nrobot = judged.urdf\nscene = scene.yaml\nrequest = request.yaml\n";
  std::ofstream(dir / "without.cfg") << cfg;
  std::ofstream(dir / "with.cfg") << cfg << "srdf = judged.srdf\n";
  PlanRun r = runAdsd("plan", {(dir / "without.cfg").string(), "--time", "2"}, dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("the start state is in collision"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("links 'slider' and 'flag'"), std::string::npos) << r.err;
  r = runAdsd("srdf", {(dir / "judged.urdf").string(), "--out", (dir / "judged.srdf").string(), "--states", "500"},
              dir);
  ASSERT_EQ(r.status, 0) << r.err;
  r = runAdsd("plan", {(dir / "with.cfg").string(), "--time", "2"}, dir);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("solved      yes"), std::string::npos) << r.out;
}

TEST(SrdfCommand, BadInputWritesNothing) {
  const fs::path dir = workDirectory();
  const fs::path urdf = writeRobot(dir);
  const std::string out = (dir / "out.srdf").string();
  PlanRun r = runAdsd("srdf", {(dir / "missing.urdf").string(), "--out", out}, dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find((dir / "missing.urdf").string()), std::string::npos) << r.err;
  r = runAdsd("srdf", {urdf.string(), "--out", out, "--states", "0"}, dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--states"), std::string::npos) << r.err;
  r = runAdsd("srdf", {urdf.string()}, dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--out"), std::string::npos) << r.err;
  std::ofstream(dir / "broken.urdf") << "<robot name='x'><link name='a'/><joint name='j' type='revolute'>";
  r = runAdsd("srdf", {(dir / "broken.urdf").string(), "--out", out}, dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("broken.urdf"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(out + ".partial"));
  // An existing file that is not an SRDF (a mesh the robot reads, named by mistake) is kept.
  std::ofstream(dir / "mesh.stl") << "solid s\nendsolid s\n";
  r = runAdsd("srdf", {urdf.string(), "--out", (dir / "mesh.stl").string()}, dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("exists and is not an SRDF"), std::string::npos) << r.err;
  EXPECT_EQ(readAll(dir / "mesh.stl"), "solid s\nendsolid s\n");
  // Nor is another URDF, though it has a <robot> element too (an outside review overwrote one).
  const fs::path other = dir / "other.urdf";
  fs::copy_file(urdf, other, fs::copy_options::overwrite_existing);
  const std::string before = readAll(other);
  r = runAdsd("srdf", {urdf.string(), "--out", other.string()}, dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("exists and is a URDF"), std::string::npos) << r.err;
  EXPECT_EQ(readAll(other), before);
  // Nor a URDF of bare links, with no <parent>, <child>, <visual>, <collision> or <inertial> to tell
  // it by (an adversarial review replaced one): its <link> stands directly in <robot>.
  const std::string bare = "<?xml version=\"1.0\"?>\n<robot name=\"x\">\n<link name=\"world\"/>\n</robot>\n";
  std::ofstream(dir / "bare.urdf") << bare;
  r = runAdsd("srdf", {urdf.string(), "--out", (dir / "bare.urdf").string()}, dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("exists and is a URDF (its <robot> has <link> elements of its own)"), std::string::npos)
      << r.err;
  EXPECT_EQ(readAll(dir / "bare.urdf"), bare);
  // An SRDF MoveIt's assistant wrote, groups naming links and joints, is replaced.
  std::ofstream(dir / "moveit.srdf") << "<?xml version=\"1.0\"?>\n<robot name=\"judged\">\n"
                                        "  <group name=\"arm\"><joint name=\"slide\"/><link name=\"slider\"/></group>\n"
                                        "  <virtual_joint name=\"v\" type=\"fixed\" parent_frame=\"world\" "
                                        "child_link=\"base\"/>\n"
                                        "</robot>\n";
  r = runAdsd("srdf", {urdf.string(), "--out", (dir / "moveit.srdf").string(), "--states", "50"}, dir);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(readAll(dir / "moveit.srdf").find("disable_collisions"), std::string::npos);
}

}  // namespace
