#pragma once
/// \file
/// \brief A problem made ready to solve: meshes loaded, state space bounded, checker, motion
/// validator and objective installed in an ompl::geometric::SimpleSetup.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <ompl/geometric/SimpleSetup.h>

#include "adsd/distance.h"
#include "adsd/planner/certified_motion_validator.h"
#include "adsd/planner/problem_file.h"
#include "adsd/planner/rigid_body_validity_checker.h"

namespace adsd::planner {

/// \brief Which distance engine checks states.
enum class CheckerKind { adsd, fcl };
/// \brief Which motion validator checks motions.
enum class MotionKind {
  discrete,   ///< OMPL's DiscreteMotionValidator: states at the space's resolution
  certified,  ///< CertifiedMotionValidator: proven by clearance
};

/// \brief How to check; the defaults are the product's defaults.
struct CheckingOptions {
  CheckerKind checker = CheckerKind::adsd;
  MotionKind motion = MotionKind::discrete;
  double safetyMargin = 0.0;
  /// For the adsd checker's clearance (exact, tolerance or cap).
  DistanceOptions clearance = DistanceOptions::exactDistance();
  /// Replaces the file's objective when set.
  std::optional<ObjectiveKind> objective;
  /// A start or goal in collision is a warning (warnings()) instead of an error. For showing a
  /// problem (adsd view): the user whose start is refused wants to see where it touches. A planner
  /// given such a problem finds nothing.
  bool keepEndpointsInCollision = false;
};

/// \brief Everything a planner run needs, built from a problem file or from a scene in memory.
class PlanningProblem {
 public:
  /// \brief Loads the robot and world meshes (robot re-centred on its vertex mean), bounds the
  /// space (the file's volume, or the environment's box widened to contain start and goal), sets
  /// the parameters of `[problem]` and the objective, and checks start and goal. Throws
  /// adsd::InputError naming the file, line and key for a missing mesh, an unknown space
  /// parameter value, or a start or goal that is outside the bounds or invalid (in collision: a
  /// warning instead with CheckingOptions::keepEndpointsInCollision).
  PlanningProblem(const ProblemFile& file, const CheckingOptions& options);

  /// \brief A problem from meshes already in memory (tests, demos); bounds as for a file without
  /// a volume when \p volume is empty.
  PlanningProblem(std::shared_ptr<const RigidBodyScene> scene, const Pose& start, const Pose& goal,
                  const std::optional<Eigen::AlignedBox3d>& volume, const CheckingOptions& options,
                  ObjectiveKind objective = ObjectiveKind::length);

  ompl::geometric::SimpleSetup& setup() { return *setup_; }
  const ompl::base::SpaceInformationPtr& spaceInformation() const { return setup_->getSpaceInformation(); }
  const std::shared_ptr<RigidBodyValidityChecker>& checker() const { return checker_; }
  /// \brief The certified validator, or null when the discrete one is in use.
  const std::shared_ptr<CertifiedMotionValidator>& certifiedValidator() const { return certified_; }
  const RigidBodyScene& scene() const { return *scene_; }
  ObjectiveKind objective() const { return objective_; }
  const CheckingOptions& options() const { return options_; }
  /// \brief One line each: `[problem]` parameters OMPL did not accept, and similar.
  const std::vector<std::string>& warnings() const { return warnings_; }

 private:
  void build(const Pose& start, const Pose& goal, const std::optional<Eigen::AlignedBox3d>& volume,
             const ProblemFile* file);

  std::shared_ptr<const RigidBodyScene> scene_;
  CheckingOptions options_;
  ObjectiveKind objective_ = ObjectiveKind::length;
  std::shared_ptr<ompl::geometric::SimpleSetup> setup_;
  std::shared_ptr<RigidBodyValidityChecker> checker_;
  std::shared_ptr<CertifiedMotionValidator> certified_;
  std::vector<std::string> warnings_;
};

}  // namespace adsd::planner
