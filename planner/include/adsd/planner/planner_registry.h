#pragma once
/// \file
/// \brief OMPL geometric planners by their OMPL.app lower-case names.

#include <optional>
#include <string>
#include <vector>

#include <ompl/base/OptimizationObjective.h>
#include <ompl/base/Planner.h>
#include <ompl/base/SpaceInformation.h>

namespace adsd::planner {

/// \brief The names makePlanner knows, in a stable order.
const std::vector<std::string>& knownPlannerNames();

/// \brief A new planner, or nullptr when \p name is not a known planner.
ompl::base::PlannerPtr makePlanner(const std::string& name, const ompl::base::SpaceInformationPtr& si);

/// \brief True for planners that keep improving a solution until the time runs out (they are the
/// ones that use an optimization objective).
bool isOptimizingPlanner(const std::string& name);

/// \brief Why planner \p name cannot plan for \p objective, or nullopt when it can. OMPL's FMT*
/// and BFMT* with the clearance objective (MaximizeMinClearanceObjective) end in a segmentation
/// fault when the planner is freed, in 1.5.2 as planned or benchmarked here.
std::optional<std::string> plannerObjectiveConflict(const std::string& name,
                                                    const ompl::base::OptimizationObjective* objective);

}  // namespace adsd::planner
