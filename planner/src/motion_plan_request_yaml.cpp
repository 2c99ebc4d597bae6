#include "adsd/planner/motion_plan_request_yaml.h"

#include "adsd/error.h"
#include "adsd/planner/problem_file.h"
#include "input_file.h"
#include "yaml_input.h"

// The format, as relied on here: moveit_msgs/MotionPlanRequest (workspace_parameters, start_state
// (a moveit_msgs/RobotState: joint_state is a sensor_msgs/JointState with name[] and position[]),
// goal_constraints[] (moveit_msgs/Constraints: joint_constraints[] with joint_name, position,
// tolerance_above, tolerance_below, weight; position_, orientation_ and visibility_constraints),
// path_constraints, trajectory_constraints, planner_id, group_name, num_planning_attempts,
// allowed_planning_time, max_velocity_scaling_factor, ...), as robowflex's YAML conversion writes
// it for MotionBenchMaker (the same field names, lists as flow sequences).

namespace adsd::planner {

using yaml::Document;
using yaml::Field;

MotionPlanRequestYaml parseMotionPlanRequestYaml(const std::string& text, const std::string& sourceName) {
  const Document doc(text, sourceName);
  const Field root = doc.root();
  doc.requireMap(root);
  MotionPlanRequestYaml request;
  request.path = sourceName;
  request.groupName = doc.text(doc.required(root, "group_name"));
  if (request.groupName.empty()) doc.fail(doc.required(root, "group_name"), "an empty group name");

  const Field start = doc.required(doc.required(root, "start_state"), "joint_state");
  const yaml::JointValues startValues = yaml::jointState(doc, start);
  if (startValues.values.empty()) doc.fail(start, "no joints in the start state");
  request.start = startValues.values;
  request.startLines = startValues.lines;

  const Field goals = doc.required(root, "goal_constraints");
  const std::size_t goalCount = doc.sequenceLength(goals);
  if (goalCount == 0) doc.fail(goals, "no goal constraints");
  if (goalCount > 1) doc.fail(goals, "several goal constraints (one joint-space goal is supported)");
  const Field goal = doc.element(goals, 0);
  doc.requireMap(goal);
  for (const char* other : {"position_constraints", "orientation_constraints", "visibility_constraints"}) {
    const Field f = doc.child(goal, other);
    if (f.node.IsDefined() && !f.node.IsNull() && doc.sequenceLength(f) > 0) {
      doc.fail(f, "only joint constraints are supported as a goal");
    }
  }
  const Field joints = doc.required(goal, "joint_constraints");
  const std::size_t n = doc.sequenceLength(joints);
  if (n == 0) doc.fail(joints, "no joint constraints");
  for (std::size_t i = 0; i < n; ++i) {
    const Field c = doc.element(joints, i);
    doc.requireMap(c);
    const Field nameField = doc.required(c, "joint_name");
    const std::string name = doc.text(nameField);
    if (name.empty()) doc.fail(nameField, "an empty joint name");
    JointGoal g;
    const Field position = doc.required(c, "position");
    g.position = doc.number(position);
    g.line = position.line;
    const Field above = doc.required(c, "tolerance_above");
    const Field below = doc.required(c, "tolerance_below");
    g.toleranceAbove = doc.number(above);
    g.toleranceBelow = doc.number(below);
    if (!(g.toleranceAbove >= 0.0)) doc.fail(above, "a tolerance must be >= 0");
    if (!(g.toleranceBelow >= 0.0)) doc.fail(below, "a tolerance must be >= 0");
    if (const auto [it, inserted] = request.goal.emplace(name, g); !inserted) {
      doc.fail(nameField, "joint " + yaml::quoted(name) + " is constrained twice (first at line " +
                              std::to_string(it->second.line) + ")");
    }
  }

  if (const Field time = doc.child(root, "allowed_planning_time"); time.node.IsDefined()) {
    const double t = doc.number(time);
    if (!(t > 0.0)) doc.fail(time, "the planning time must be > 0");
    // Far beyond it the deadline overflowed: 1e20 s was "not solved" after 4 ms.
    if (t > kMaxTimeLimitSeconds) {
      doc.fail(time, yaml::quoted(time.node.Scalar()) + " seconds is longer than the clock can count (at most 1e8)");
    }
    request.allowedPlanningTime = t;
  }
  return request;
}

MotionPlanRequestYaml readMotionPlanRequestYaml(const std::string& path) {
  return parseMotionPlanRequestYaml(readInputFile(path, "request file"), path);
}

}  // namespace adsd::planner
