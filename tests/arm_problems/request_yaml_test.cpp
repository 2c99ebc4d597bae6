// MoveIt MotionPlanRequest YAML (MotionBenchMaker's request files): start state, joint goal and
// tolerances, group; each failure mode as one adsd::InputError naming the file and the line.
#include <gtest/gtest.h>

#include <string>

#include "adsd/error.h"
#include "adsd/planner/motion_plan_request_yaml.h"
#include "reader_errors.h"
#include "scratch_dir.h"

namespace adsd::planner {
namespace {

const char* kRequest = R"(planner_id: RRTConnect
group_name: manipulator
num_planning_attempts: 1
allowed_planning_time: 5.5
start_state:
  joint_state:
    header: {frame_id: world}
    name: [a, b, c]
    position: [0.1, -0.2, 3]
goal_constraints:
  - joint_constraints:
      - joint_name: a
        position: 1.5
        tolerance_above: 0.001
        tolerance_below: 0.002
        weight: 1
      - {joint_name: b, position: -1e-1, tolerance_above: 0, tolerance_below: 0}
)";

TEST(MotionPlanRequestYaml, ReadsStartGoalTolerancesAndGroup) {
  test::ScratchDir dir;
  const MotionPlanRequestYaml r = readMotionPlanRequestYaml(dir.write("request0001.yaml", kRequest));
  EXPECT_EQ(r.groupName, "manipulator");
  ASSERT_TRUE(r.allowedPlanningTime.has_value());
  EXPECT_EQ(*r.allowedPlanningTime, 5.5);
  ASSERT_EQ(r.start.size(), 3u);
  EXPECT_EQ(r.start.at("a"), 0.1);
  EXPECT_EQ(r.start.at("b"), -0.2);
  EXPECT_EQ(r.start.at("c"), 3.0);
  EXPECT_EQ(r.startLines.at("c"), 9);
  ASSERT_EQ(r.goal.size(), 2u);
  EXPECT_EQ(r.goal.at("a").position, 1.5);
  EXPECT_EQ(r.goal.at("a").toleranceAbove, 0.001);
  EXPECT_EQ(r.goal.at("a").toleranceBelow, 0.002);
  EXPECT_EQ(r.goal.at("a").line, 13);
  EXPECT_EQ(r.goal.at("b").position, -0.1);
  EXPECT_EQ(r.goal.at("b").line, 17);
}

std::string errorOf(const std::string& text) {
  return test::errorAfterName([](const std::string& t) { parseMotionPlanRequestYaml(t, "request.yaml"); }, text,
                              "request.yaml");
}

std::string withLine(int line, const std::string& replacement) {
  return test::withLineReplaced(kRequest, line, replacement);
}

TEST(MotionPlanRequestYamlErrors, StartNamesAndPositionsOfDifferentLengths) {
  EXPECT_ERROR(withLine(9, "    position: [0.1, -0.2]"), ":9:", "2 positions for 3 joint names");
  // The first name's line (was its position's: "first at line 9").
  EXPECT_ERROR(withLine(8, "    name: [a, b, a]"), ":8:", "joint 'a' appears twice (first at line 8)");
}

TEST(MotionPlanRequestYamlErrors, MissingFieldsWrongTypesAndBadNumbers) {
  EXPECT_ERROR(withLine(2, "group: manipulator"), ":1:", "field 'group_name': is missing");
  EXPECT_ERROR(withLine(12, "      - joint: a"), ":12:", "joint_constraints[0].joint_name': is missing");
  EXPECT_ERROR(withLine(13, "        position: [1.5]"), ":13:", "expected a scalar");
  EXPECT_ERROR(withLine(13, "        position: .nan"), ":13:", "expected a finite number");
  EXPECT_ERROR(withLine(13, "        position: 1,5"), ":13:", "expected a finite number, got '1,5'");
  EXPECT_ERROR(withLine(14, "        tolerance_above: -0.001"), ":14:", "a tolerance must be >= 0");
  EXPECT_ERROR(withLine(4, "allowed_planning_time: 0"), ":4:", "must be > 0");
  // As the .cfg reader's time_limit: 1e20 overflowed OMPL's deadline ("not solved" at once).
  EXPECT_ERROR(withLine(4, "allowed_planning_time: 1e20"), ":4:",
               "field 'allowed_planning_time': '1e20' seconds is longer than the clock can count (at most 1e8)");
  EXPECT_EQ(parseMotionPlanRequestYaml(withLine(4, "allowed_planning_time: 1e8"), "r.yaml").allowedPlanningTime, 1e8);
  EXPECT_ERROR("group_name: g\nstart_state: {joint_state: {name: [a], position: [0]}}\ngoal_constraints:\n"
               "  - joint_constraints: []\n",
               ":4:", "no joint constraints");
  EXPECT_ERROR(withLine(17, "      - {joint_name: a, position: 0, tolerance_above: 0, tolerance_below: 0}"), ":17:",
               "joint 'a' is constrained twice (first at line 13)");
  EXPECT_ERROR(std::string(kRequest) + "  - joint_constraints: []\n", ":11:", "several goal constraints");
  EXPECT_ERROR("group_name: g\nstart_state: {joint_state: {name: [a], position: [0]}}\ngoal_constraints:\n"
               "  - position_constraints: [{link_name: tool}]\n",
               ":4:", "only joint constraints");
  EXPECT_ERROR("group_name: [g\n", ":", "not valid YAML");
}

// yaml-cpp keeps the first of two equal keys: a second group_name or position list was ignored.
TEST(MotionPlanRequestYamlErrors, RepeatedKeyNamesItsLineAndTheFirst) {
  EXPECT_ERROR(withLine(3, "group_name: other"), ":3:", "key 'group_name' appears twice in one map (first at line 2)");
  EXPECT_ERROR(withLine(8, "    position: [1, 1, 1]"), ":9:", "key 'position' appears twice in one map (first at line 8)");
  // The same key in different maps, and a key repeated through an alias, are fine.
  EXPECT_NO_THROW(parseMotionPlanRequestYaml(withLine(7, "    header: &h {frame_id: world}\n    extra: *h"), "r.yaml"));
}

}  // namespace
}  // namespace adsd::planner
