#pragma once
/// \file
/// \brief MoveIt MotionPlanRequest YAML files (MotionBenchMaker's request0001.yaml): the start
/// joint state and a joint-space goal.
///
/// What is read (moveit_msgs/MotionPlanRequest): `group_name` (required), `start_state.joint_state`
/// name[] and position[] (required), `goal_constraints[0].joint_constraints[]` each with
/// joint_name, position, tolerance_above, tolerance_below (required; a request with several goal
/// constraints is refused, as are position, orientation and visibility constraints), and
/// `allowed_planning_time` (optional). Everything else (planner_id, num_planning_attempts,
/// workspace_parameters, velocity scaling, ...) is ignored. Every error is one adsd::InputError
/// "FILE:LINE: field 'PATH': what is wrong".

#include <map>
#include <optional>
#include <string>

namespace adsd::planner {

/// \brief One joint's goal: position and the tolerance either side (goal region
/// [position - below, position + above]).
struct JointGoal {
  double position = 0.0;        ///< radians (revolute) or metres (prismatic)
  double toleranceAbove = 0.0;  ///< >= 0
  double toleranceBelow = 0.0;  ///< >= 0
  int line = 0;                 ///< the line of `position`, for messages about this goal
};

/// \brief What a request file says.
struct MotionPlanRequestYaml {
  std::string path;       ///< the file as given
  std::string groupName;  ///< `group_name` (the SRDF group to plan for)
  std::map<std::string, double> start;      ///< joint name to position
  std::map<std::string, int> startLines;    ///< joint name to the line of its position
  std::map<std::string, JointGoal> goal;    ///< joint name to goal
  std::optional<double> allowedPlanningTime;  ///< seconds, > 0
};

/// \brief Reads a request file; throws adsd::InputError for a missing or unreadable file, broken
/// YAML, a missing field, a value of the wrong type, a non-finite number, a negative tolerance, a
/// non-positive planning time, start name and position lists of different lengths, a joint named
/// twice, no joint constraints, or more than one goal constraint.
MotionPlanRequestYaml readMotionPlanRequestYaml(const std::string& path);

/// \brief The same from text; \p sourceName names it in messages.
MotionPlanRequestYaml parseMotionPlanRequestYaml(const std::string& text, const std::string& sourceName);

}  // namespace adsd::planner
