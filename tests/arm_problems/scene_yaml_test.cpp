// MoveIt PlanningScene YAML (MotionBenchMaker's scene files): a hand-written scene with a box, a
// sphere, a cylinder and a mesh, whose world-frame vertices were worked out by hand below; and
// each failure mode as one adsd::InputError naming the file and the right line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "adsd/error.h"
#include "adsd/planner/planning_scene_yaml.h"
#include "reader_errors.h"
#include "scratch_dir.h"

namespace adsd::planner {
namespace {

// Line numbers matter: the error tests below name them.
const char* kScene = R"(name: hand_worked
robot_state:
  joint_state:
    name: [j1, j2]
    position: [0.5, -1.25]
world:
  collision_objects:
    - id: table
      header:
        frame_id: world
      pose:
        position: {x: 1, y: 0, z: 0}
        orientation: {x: 0, y: 0, z: 0.7071067811865476, w: 0.7071067811865476}
      primitives:
        - type: box
          dimensions: [0.4, 0.2, 0.1]
      primitive_poses:
        - position: {x: 0.5, y: 0, z: 0.2}
          orientation: {x: 0, y: 0, z: 0, w: 1}
    - id: ball
      primitives:
        - type: 2
          dimensions: [0.1]
      primitive_poses:
        - position: [0, -1, 0.5]
          orientation: [0, 0, 0, 1]
    - id: pole
      pose:
        position: [0, 0, 1]
        orientation: [0.7071067811865476, 0, 0, 0.7071067811865476]
      primitives:
        - type: cylinder
          dimensions: [0.6, 0.05]
      primitive_poses:
        - position: [0, 0, 0]
    - id: sheet
      meshes:
        - vertices: [[0, 0, 0], [1, 0, 0], {x: 0, y: 1, z: 0}]
          triangles:
            - vertex_indices: [0, 1, 2]
            - [2, 1, 0]
      mesh_poses:
        - position: [0, 0, 2]
          orientation: [0, 0, 1, 0]
)";

constexpr double kTol = 1e-12;

bool hasVertex(const Mesh& m, const Vec3& p, double tol = kTol) {
  return std::any_of(m.vertices().begin(), m.vertices().end(), [&](const Vec3& v) { return (v - p).norm() <= tol; });
}

TEST(PlanningSceneYaml, WorldFrameVerticesOfABoxSphereCylinderAndMesh) {
  const PlanningSceneYaml scene = parsePlanningSceneYaml(kScene, "scene.yaml");
  EXPECT_EQ(scene.name, "hand_worked");
  ASSERT_EQ(scene.defaultJointValues.size(), 2u);
  EXPECT_EQ(scene.defaultJointValues.at("j1"), 0.5);
  EXPECT_EQ(scene.defaultJointValues.at("j2"), -1.25);
  ASSERT_EQ(scene.objects.size(), 4u);
  EXPECT_EQ(scene.objects[0].name(), "table");
  EXPECT_EQ(scene.frames[0], "world");
  EXPECT_EQ(scene.frames[1], "");
  EXPECT_EQ(scene.lines[0], 8);
  EXPECT_EQ(scene.lines[3], 36);
  // The primitives, each on its own (the solids of convex_solids.h), named by their object; the
  // sheet, a mesh object, is none of them.
  ASSERT_EQ(scene.primitives.size(), 3u);
  EXPECT_EQ(scene.primitives[0].name(), "table");
  EXPECT_EQ(scene.primitives[2].name(), "pole");
  EXPECT_EQ(scene.primitives[0].vertices(), scene.objects[0].vertices());

  // table: object at (1, 0, 0) turned 90 degrees about z, (x, y, z) -> (-y, x, z); the box's centre
  // (0.5, 0, 0.2) goes to (1, 0.5, 0.2) and its half sides (0.2, 0.1, 0.05) become (0.1, 0.2, 0.05):
  // corners (1 +- 0.1, 0.5 +- 0.2, 0.2 +- 0.05).
  const Mesh& table = scene.objects[0];
  ASSERT_EQ(table.vertices().size(), 8u);
  for (double x : {0.9, 1.1})
    for (double y : {0.3, 0.7})
      for (double z : {0.15, 0.25}) EXPECT_TRUE(hasVertex(table, Vec3(x, y, z))) << x << " " << y << " " << z;

  // ball: no object pose (the older format), centre (0, -1, 0.5), radius 0.1; its containing mesh
  // (primitive_meshes.h) puts every vertex at one distance from the centre, a little beyond the
  // radius (at most 2 %: tests/arm checks the face planes), the poles on z.
  const Mesh& ball = scene.objects[1];
  const double out = (ball.vertices().front() - Vec3(0, -1, 0.5)).norm();
  EXPECT_GT(out, 0.1);
  EXPECT_LT(out, 0.102);
  for (const Vec3& v : ball.vertices()) EXPECT_NEAR((v - Vec3(0, -1, 0.5)).norm(), out, kTol);
  EXPECT_TRUE(hasVertex(ball, Vec3(0, -1, 0.5 + out)));
  EXPECT_TRUE(hasVertex(ball, Vec3(0, -1, 0.5 - out)));

  // pole: object at (0, 0, 1) turned 90 degrees about x, (x, y, z) -> (x, -z, y): the cylinder's
  // axis (z) lies along -y, the cap centres (0, 0, +-0.3) at (0, -+0.3, 1); the prism's corners at
  // 0.05 / cos(pi/32) from the axis, corner k=0 at local (r', 0, 0.3) -> (r', -0.3, 1).
  const Mesh& pole = scene.objects[2];
  const double corner = 0.05 / std::cos(M_PI / 32);
  EXPECT_TRUE(hasVertex(pole, Vec3(0, -0.3, 1)));
  EXPECT_TRUE(hasVertex(pole, Vec3(0, 0.3, 1)));
  EXPECT_TRUE(hasVertex(pole, Vec3(corner, -0.3, 1)));
  EXPECT_TRUE(hasVertex(pole, Vec3(corner, 0.3, 1)));
  for (const Vec3& v : pole.vertices()) {
    EXPECT_LE(std::abs(v.y()), 0.3 + kTol);
    EXPECT_LE(std::hypot(v.x(), v.z() - 1), corner + kTol);
  }

  // sheet: mesh pose at (0, 0, 2) turned 180 degrees about z, (x, y, z) -> (-x, -y, z).
  const Mesh& sheet = scene.objects[3];
  ASSERT_EQ(sheet.vertices().size(), 3u);
  EXPECT_TRUE(hasVertex(sheet, Vec3(0, 0, 2)));
  EXPECT_TRUE(hasVertex(sheet, Vec3(-1, 0, 2)));
  EXPECT_TRUE(hasVertex(sheet, Vec3(0, -1, 2)));
  EXPECT_EQ(sheet.triangleCount(), 2u);
}

TEST(PlanningSceneYaml, ReadsFromAFileAndWithoutAWorld) {
  test::ScratchDir dir;
  const PlanningSceneYaml scene = readPlanningSceneYaml(dir.write("s.yaml", kScene));
  EXPECT_EQ(scene.objects.size(), 4u);
  EXPECT_TRUE(parsePlanningSceneYaml("name: empty\n", "e.yaml").objects.empty());
  EXPECT_TRUE(parsePlanningSceneYaml("world: {}\n", "e.yaml").objects.empty());
}

// What MoveIt applies and we do not, and which changes which states are free, is warned of with
// its line (an outside review: a box held in the hand overlapped an obstacle at the start, and the
// plan was accepted without a word); the neutral values MoveIt writes for every link are not.
TEST(PlanningSceneYaml, UnappliedFieldsThatChangeWhatIsFreeAreWarnedOf) {
  const std::string neutral = "name: n\nlink_padding:\n  - link_name: a\n    padding: 0\n"
                              "link_scale:\n  - link_name: a\n    scale: 1\n"
                              "robot_state:\n  attached_collision_objects: []\n";
  EXPECT_TRUE(parsePlanningSceneYaml(neutral, "n.yaml").warnings.empty());
  const std::string text = "name: w\n"
                           "robot_state:\n"
                           "  attached_collision_objects:\n"
                           "    - link_name: hand\n"
                           "link_padding:\n"
                           "  - link_name: a\n"
                           "    padding: 0.3\n"
                           "link_scale:\n"
                           "  - link_name: a\n"
                           "    scale: 3\n"
                           "allowed_collision_matrix:\n"
                           "  entry_names: [a, b]\n";
  const std::vector<std::string> warnings = parsePlanningSceneYaml(text, "w.yaml").warnings;
  ASSERT_EQ(warnings.size(), 4u);
  EXPECT_EQ(warnings[0].rfind("w.yaml:4: robot_state.attached_collision_objects (1 object held by the robot) "
                              "not applied", 0), 0u)
      << warnings[0];
  EXPECT_EQ(warnings[1].rfind("w.yaml:6: link_padding other than 0 not applied", 0), 0u) << warnings[1];
  EXPECT_EQ(warnings[2].rfind("w.yaml:9: link_scale other than 1 not applied", 0), 0u) << warnings[2];
  EXPECT_EQ(warnings[3].rfind("w.yaml:12: allowed_collision_matrix", 0), 0u) << warnings[3];
}

/// The message of the InputError that reading \p text as "bad.yaml" raises, after the file name.
std::string errorOf(const std::string& text) {
  return test::errorAfterName([](const std::string& t) { parsePlanningSceneYaml(t, "bad.yaml"); }, text, "bad.yaml");
}

/// kScene with line \p line (1-based) replaced by \p replacement.
std::string withLine(int line, const std::string& replacement) {
  return test::withLineReplaced(kScene, line, replacement);
}

TEST(PlanningSceneYamlErrors, BrokenYamlNamesTheLine) {
  EXPECT_ERROR(withLine(16, "          dimensions: [0.4, 0.2, 0.1"), ":17:", "not valid YAML");
  EXPECT_ERROR("a:\n  - b\n  c: d\n", ":3:", "not valid YAML");
  EXPECT_ERROR("", ":1:", "expected a map");
  // A second document was dropped in silence (outside review); an empty one after `---`, as
  // `rostopic echo` ends each message, is none.
  EXPECT_ERROR("name: a\n---\nname: b\n", ":3:", "a second YAML document (after '---'): the file holds one");
  EXPECT_NO_THROW(parsePlanningSceneYaml(std::string(kScene) + "---\n", "s.yaml"));
  // Broken after the first: named at its line, as the first would be (an internal error before).
  EXPECT_ERROR("name: a\n---\nname: [b\n", ":4:", "not valid YAML");
}

TEST(PlanningSceneYamlErrors, MissingFieldAndWrongType) {
  EXPECT_ERROR(withLine(8, "    - idd: table"), ":8:",
               "field 'world.collision_objects[0].idd': not a field of a moveit_msgs/CollisionObject");
  EXPECT_ERROR(withLine(8, "    - operation: 0"), ":8:", "field 'world.collision_objects[0].id': is missing");
  EXPECT_ERROR(withLine(16, "          dimensions: abc"), ":16:", "expected a sequence");
  EXPECT_ERROR(withLine(15, "        - typo: box"), ":15:", "primitives[0].type': is missing");
  EXPECT_ERROR("world:\n  collision_objects: 3\n", ":2:", "expected a sequence");
  EXPECT_ERROR(withLine(16, "          dimensions: [0.4, [0.2], 0.1]"), ":16:", "expected a scalar");
}

TEST(PlanningSceneYamlErrors, NonFiniteNegativeOrZeroDimension) {
  EXPECT_ERROR(withLine(16, "          dimensions: [0.4, .inf, 0.1]"), ":16:", "dimensions[1]': expected a finite number");
  EXPECT_ERROR(withLine(16, "          dimensions: [0.4, .nan, 0.1]"), ":16:", "expected a finite number");
  EXPECT_ERROR(withLine(16, "          dimensions: [0.4, 1e999, 0.1]"), ":16:", "expected a finite number");
  EXPECT_ERROR(withLine(16, "          dimensions: [-0.4, 0.2, 0.1]"), ":16:", "must be > 0");
  EXPECT_ERROR(withLine(23, "          dimensions: [0]"), ":23:", "must be > 0");
  EXPECT_ERROR(withLine(23, "          dimensions: [0.1, 0.2]"), ":23:", "expected 1 dimensions [radius]");
  EXPECT_ERROR(withLine(12, "        position: {x: 1e7, y: 0, z: 0}"), ":12:", "beyond 1e6");
}

TEST(PlanningSceneYamlErrors, ZeroOrNonUnitQuaternion) {
  EXPECT_ERROR(withLine(13, "        orientation: {x: 0, y: 0, z: 0, w: 0}"), ":13:", "the quaternion is zero");
  EXPECT_ERROR(withLine(26, "          orientation: [0, 0, 0, 2]"), ":26:", "norm is 2");
  EXPECT_ERROR(withLine(26, "          orientation: [0, 0, 1]"), ":26:", "expected 4 components");
  // A rounding of a unit quaternion is accepted (and normalized).
  EXPECT_NO_THROW(parsePlanningSceneYaml(withLine(26, "          orientation: [0, 0, 0, 1.0004]"), "ok.yaml"));
}

// A mistyped key of a point or a quaternion left its value at 0: `W: 1` made (1, 0, 0, 0), a unit
// quaternion turning the object half a turn where a quarter was meant (adversarial sweep).
TEST(PlanningSceneYamlErrors, MistypedPointOrQuaternionKey) {
  EXPECT_ERROR(withLine(13, "        orientation: {x: 0.7071067811865476, y: 0, z: 0, W: 0.7071067811865476}"), ":13:",
               "field 'world.collision_objects[0].pose.orientation.W': not a component of a quaternion (x, y, z, w)");
  EXPECT_ERROR(withLine(12, "        position: {x: 1, yy: 0, z: 0}"), ":12:",
               "field 'world.collision_objects[0].pose.position.yy': not a coordinate of a point (x, y, z)");
}

// A mistyped key of a pose or an object: `orientaton:` left the object unturned, `positon:` and
// `pos:` (for `pose:`) put it at the origin, without a word (an outside review).
TEST(PlanningSceneYamlErrors, MistypedPoseOrObjectKey) {
  EXPECT_ERROR(withLine(13, "        orientaton: {x: 0, y: 0, z: 0.7071067811865476, w: 0.7071067811865476}"), ":13:",
               "field 'world.collision_objects[0].pose.orientaton': not a field of a pose (position, orientation)");
  EXPECT_ERROR(withLine(12, "        positon: {x: 1, y: 0, z: 0}"), ":12:",
               "field 'world.collision_objects[0].pose.positon': not a field of a pose (position, orientation)");
  EXPECT_ERROR(withLine(19, "          orientaton: {x: 0, y: 0, z: 0, w: 1}"), ":19:",
               "field 'world.collision_objects[0].primitive_poses[0].orientaton': not a field of a pose");
  EXPECT_ERROR(withLine(11, "      pos:"), ":11:",
               "field 'world.collision_objects[0].pos': not a field of a moveit_msgs/CollisionObject");
}

// A key a PlanningScene does not have: `wrld:` for `world:` read as a scene without obstacles, and
// a YAML file that is no scene at all as an empty one, without a word (adversarial sweep).
TEST(PlanningSceneYaml, UnknownKeysAreWarnedOf) {
  EXPECT_TRUE(parsePlanningSceneYaml(kScene, "s.yaml").warnings.empty());
  const std::vector<std::string> typo =
      parsePlanningSceneYaml("name: t\nwrld:\n  collision_objects: []\n", "t.yaml").warnings;
  ASSERT_EQ(typo.size(), 1u);
  EXPECT_EQ(typo[0], "t.yaml:2: unknown key 'wrld' ignored (not a field of a moveit_msgs/PlanningScene)");
  const std::vector<std::string> inWorld =
      parsePlanningSceneYaml("world:\n  collision_objects: []\n  colision_objects: []\n", "w.yaml").warnings;
  ASSERT_EQ(inWorld.size(), 1u);
  EXPECT_EQ(inWorld[0],
            "w.yaml:3: unknown key 'world.colision_objects' ignored (not a field of a moveit_msgs/PlanningSceneWorld)");
}

TEST(PlanningSceneYamlErrors, TriangleIndexOutOfRange) {
  EXPECT_ERROR(withLine(40, "            - vertex_indices: [0, 1, 3]"), ":40:",
               "vertex_indices[2]': '3' is out of range (at most 2)");
  EXPECT_ERROR(withLine(40, "            - vertex_indices: [0, 1, -1]"), ":40:", "expected a whole number");
  EXPECT_ERROR(withLine(40, "            - vertex_indices: [0, 1]"), ":40:", "expected 3 vertex indices");
}

TEST(PlanningSceneYamlErrors, PrimitivesAndPosesOfDifferentLengths) {
  EXPECT_ERROR(withLine(19, "          orientation: {x: 0, y: 0, z: 0, w: 1}\n        - position: [0, 0, 0]"), ":18:",
               "1 primitives but 2 primitive_poses");
  const std::string object = "world:\n  collision_objects:\n    - id: a\n";
  EXPECT_ERROR(object + "      primitives: [{type: box, dimensions: [1, 1, 1]}]\n      primitive_poses: []\n", ":5:",
               "1 primitives but 0 primitive_poses");
  EXPECT_ERROR(object + "      primitives: [{type: box, dimensions: [1, 1, 1]}]\n", ":4:",
               "1 primitives but 0 primitive_poses");
  EXPECT_ERROR(object + "      meshes: [{vertices: [[0, 0, 0]], triangles: [[0, 0, 0]]}]\n      mesh_poses: [{}, {}]\n",
               ":5:", "1 meshes but 2 mesh_poses");
}

TEST(PlanningSceneYamlErrors, UnknownOrUnsupportedPrimitiveType) {
  EXPECT_ERROR(withLine(15, "        - type: pyramid"), ":15:", "unknown primitive type 'pyramid'");
  EXPECT_ERROR(withLine(15, "        - type: 7"), ":15:", "unknown primitive type");
  EXPECT_ERROR(withLine(15, "        - type: cone"), ":15:", "cones are not supported");
}

TEST(PlanningSceneYamlErrors, JointStateListsOfDifferentLengths) {
  EXPECT_ERROR(withLine(5, "    position: [0.5]"), ":5:", "1 positions for 2 joint names");
}

TEST(PlanningSceneYamlErrors, RepeatedIdEmptyObjectPlanesAndMissingFile) {
  EXPECT_ERROR(withLine(20, "    - id: table"), ":20:", "id 'table' appears twice (first at line 8)");
  EXPECT_ERROR("world:\n  collision_objects:\n    - id: nothing\n", ":3:", "has no primitives and no meshes");
  EXPECT_ERROR("world:\n  collision_objects:\n    - id: p\n      planes: [{coef: [0, 0, 1, 0]}]\n", ":4:",
               "planes are not supported");
  // An id holding a line break is echoed on one line.
  const std::string box = ", primitives: [{type: box, dimensions: [1, 1, 1]}], primitive_poses: [{}]}\n";
  EXPECT_ERROR("world:\n  collision_objects:\n    - {id: \"a\\nb\"" + box + "    - {id: \"a\\nb\"" + box, ":4:",
               "id 'a?b' appears twice (first at line 3)");
  try {
    readPlanningSceneYaml("/nonexistent/scene.yaml");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "/nonexistent/scene.yaml: scene file does not exist");
  }
}

// yaml-cpp keeps the first of two equal keys: a second `primitives:` (a 100 m box) was ignored.
TEST(PlanningSceneYamlErrors, RepeatedKeyNamesItsLineAndTheFirst) {
  EXPECT_ERROR(withLine(19, "          orientation: {x: 0, y: 0, z: 0, w: 1}\n"
                            "      primitives: [{type: box, dimensions: [100, 100, 100]}]"),
               ":20:", "key 'primitives' appears twice in one map (first at line 14)");
  EXPECT_ERROR(withLine(12, "        position: {x: 1, y: 0, x: 2}"), ":12:", "key 'x' appears twice in one map (first at line 12)");
}

TEST(PlanningSceneYamlErrors, AliasesCannotMultiplyTheWork) {
  // 40 objects, each with one 4-vertex mesh repeated 32 times by alias: about 45 000 values from
  // a text of 3 KB; refused instead of expanded.
  std::string meshes = "l: &l [*m", poses = "q: &q [*p";
  for (int i = 1; i < 32; ++i) meshes += ", *m", poses += ", *p";
  std::string text = "m: &m {vertices: [[0,0,0],[1,0,0],[0,1,0],[0,0,1]], triangles: [[0,1,2]]}\n"
                     "p: &p {position: [0,0,0]}\n" + meshes + "]\n" + poses + "]\nworld:\n  collision_objects:\n";
  for (int i = 0; i < 40; ++i) text += "    - {id: o" + std::to_string(i) + ", meshes: *l, mesh_poses: *q}\n";
  EXPECT_ERROR(text, ":", "more values than a file of");
}

}  // namespace
}  // namespace adsd::planner
