#pragma once
/// \file
/// \brief An arm problem made ready to solve (issue 17): a MotionBenchMaker-format problem
/// (motion_bench_maker_problem.h) read into an ArmScene, an ArmStateSpace, a checker, a motion
/// validator and an objective installed in an ompl::geometric::SimpleSetup. The arm counterpart of
/// PlanningProblem, with the same CheckingOptions.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <ompl/geometric/SimpleSetup.h>

#include "adsd/planner/arm_clearance_objective.h"
#include "adsd/planner/arm_motion_validator.h"
#include "adsd/planner/arm_scene.h"
#include "adsd/planner/arm_validity_checker_base.h"
#include "adsd/planner/motion_bench_maker_problem.h"
#include "adsd/planner/planning_problem.h"

namespace adsd::planner {

/// \brief The goal threshold used when the request's smallest joint tolerance is 0 (an exact joint
/// goal): 1e-6 in the space's distance (the sum of the joints' absolute changes, radians and
/// metres), PlanningProblem's default threshold; OMPL cannot reach a threshold of 0 exactly.
constexpr double kArmGoalThresholdFloor = 1e-6;

/// \brief Is \p path an arm problem `.cfg`? True when the file can be read and its `[problem]`
/// section has a `request` key (a MotionBenchMaker request YAML); OMPL.app's files have none.
/// Anything else (no such file, another layout) is false: the rigid-body reader then reports it.
bool isArmProblemFile(const std::string& path);

/// \brief Everything a planner run on an arm needs.
///
/// Start: the request's `start_state`, and for joints it omits the scene's `robot_state`; a model
/// joint with neither is an error naming the request file. Joints the request's start names but
/// the model lacks get a warning (MoveIt files often carry extra joints, e.g. a gripper's).
///
/// Joints planned: the request's `group_name` as the cfg's SRDF defines it (srdfGroupJoints), else
/// the joints the goal constrains (with a warning); the robot's other joints are held at the start
/// state (holdJointsOutside), as MoveIt plans a group, and model().dof() counts the planned ones.
///
/// Goal: the joint constraints' positions; a model joint without a constraint takes the start's
/// value; a constraint on a joint the model lacks is an error naming the constraint's line. The
/// goal is an OMPL GoalState with threshold the smallest tolerance of the constraints (floor
/// kArmGoalThresholdFloor): ArmStateSpace's distance is the sum of the joints' absolute changes,
/// so a state within that distance of the goal has every joint within its own tolerance.
class ArmPlanningProblem {
 public:
  /// \brief Reads the robot (URDF with the cfg's package path, SRDF), the scene and the request,
  /// builds the scene and the setup, and checks start and goal. Throws adsd::InputError naming
  /// the file and line for anything wrong in them, for a start or goal outside the joint limits
  /// ("FILE:LINE: the start state is outside the joint limits (joint J = V, limits [L, U])") or
  /// in collision ("FILE:LINE: the start state is in collision (clearance X, safety margin M):
  /// link 'A' and obstacle 'O', links 'A' and 'B'", up to three pairs, from pairsInContact), the
  /// line being that of the request's first joint of the start or goal. With
  /// CheckingOptions::keepEndpointsInCollision, the last is a warning instead.
  ArmPlanningProblem(const MotionBenchMakerProblem& file, const CheckingOptions& options);

  ompl::geometric::SimpleSetup& setup() { return *setup_; }
  const ompl::base::SpaceInformationPtr& spaceInformation() const { return setup_->getSpaceInformation(); }
  const std::shared_ptr<ArmValidityCheckerBase>& checker() const { return checker_; }
  /// \brief The certified validator, or null when OMPL's discrete one is in use.
  const std::shared_ptr<ArmMotionValidator>& certifiedValidator() const { return certified_; }
  const ArmModel& model() const { return *model_; }
  const ArmScene& scene() const { return *scene_; }
  const std::string& name() const { return name_; }
  /// \brief Joint vectors (model.dof() values, the model's joint order).
  const std::vector<double>& startJoints() const { return start_; }
  const std::vector<double>& goalJoints() const { return goal_; }
  /// \brief The GoalState's threshold (space distance; see the class comment).
  double goalThreshold() const { return goalThreshold_; }
  /// \brief The request's `allowed_planning_time` (seconds), when it has one.
  const std::optional<double>& allowedPlanningTime() const { return allowedPlanningTime_; }
  ObjectiveKind objective() const { return objective_; }
  /// \brief With the clearance objective, what it measures (ArmClearanceObjective, the clearance
  /// to the obstacles); null with the length objective.
  const std::shared_ptr<const ArmMotionClearance>& objectiveClearance() const { return objectiveClearance_; }
  const CheckingOptions& options() const { return options_; }
  /// \brief One line each: the cfg's unknown keys, start joints the model lacks.
  const std::vector<std::string>& warnings() const { return warnings_; }

 private:
  std::shared_ptr<const ArmModel> model_;
  std::shared_ptr<const ArmScene> scene_;
  std::string name_;
  CheckingOptions options_;
  ObjectiveKind objective_ = ObjectiveKind::length;
  std::shared_ptr<ompl::geometric::SimpleSetup> setup_;
  std::shared_ptr<ArmValidityCheckerBase> checker_;
  std::shared_ptr<ArmMotionValidator> certified_;
  std::shared_ptr<const ArmMotionClearance> objectiveClearance_;
  std::vector<double> start_, goal_;
  double goalThreshold_ = kArmGoalThresholdFloor;
  std::optional<double> allowedPlanningTime_;
  std::vector<std::string> warnings_;
};

}  // namespace adsd::planner
