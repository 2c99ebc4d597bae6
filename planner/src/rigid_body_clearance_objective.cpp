#include "adsd/planner/rigid_body_clearance_objective.h"

namespace adsd::planner {

RigidBodyClearanceObjective::RigidBodyClearanceObjective(const ompl::base::SpaceInformationPtr& si)
    : MaximizeMinClearanceObjective(si) {}

ompl::base::Cost RigidBodyClearanceObjective::motionCost(const ompl::base::State* s1,
                                                         const ompl::base::State* s2) const {
  return combineCosts(stateCost(s1), MaximizeMinClearanceObjective::motionCost(s1, s2));
}

}  // namespace adsd::planner
