#pragma once
/// \file
/// \brief OMPL geometric planners by their OMPL.app lower-case names.

#include <optional>
#include <string>
#include <vector>

#include <ompl/base/OptimizationObjective.h>
#include <ompl/base/Planner.h>
#include <ompl/base/SpaceInformation.h>

#include "adsd/planner/problem_file.h"

namespace adsd::planner {

/// \brief The names makePlanner knows, in a stable order.
const std::vector<std::string>& knownPlannerNames();

/// \brief A new planner, or nullptr when \p name is not a known planner.
ompl::base::PlannerPtr makePlanner(const std::string& name, const ompl::base::SpaceInformationPtr& si);

/// \brief True for planners that keep improving a solution until the time runs out (they are the
/// ones that use an optimization objective).
bool isOptimizingPlanner(const std::string& name);

/// \brief Why planner \p name cannot plan for \p objective in state space \p space, or nullopt
/// when it can:
///  - OMPL's FMT* and BFMT* with a clearance objective (one to maximize: OMPL's
///    MaximizeMinClearanceObjective, or the arms' ArmClearanceObjective) end in a segmentation
///    fault, in 1.5.2 as planned or benchmarked here;
///  - TRRT and BiTRRT take the objective's cost as a cost map to keep low along the tree, while
///    the clearance objective's is a clearance to keep high: with it they solved no problem tried;
///  - InformedRRT*, BIT* and CForest sample the path-length objective's informed set with OMPL's
///    PathLengthDirectInfSampler, which throws in any space but real vectors, SE(2) and SE(3) (an
///    arm's joint space, with its circular joints), and in CForest's threads the throw aborted
///    the program.
std::optional<std::string> plannerConflict(const std::string& name, const ompl::base::OptimizationObjective* objective,
                                           const ompl::base::StateSpace& space);

/// \brief Sets a problem file's \p settings on \p planner (named \p name in messages), in the file's
/// order but `ordered_sampling` last: OMPL's RRT* takes it only once informed or rejection
/// sampling is on, whichever line says so. Returns a warning for each parameter the planner does
/// not have (ignored). Throws InputError naming the line of a value the planner rejects (OMPL
/// returns false or throws) or does not keep (a switch that reads otherwise once all are set),
/// and of ordered sampling left with neither informed nor rejection sampling, with which OMPL
/// 1.5.2's RRT* dereferences a null sampler when it sets up (an adversarial review).
std::vector<std::string> configurePlanner(ompl::base::Planner& planner, const std::string& name,
                                          const std::vector<Setting>& settings);

}  // namespace adsd::planner
