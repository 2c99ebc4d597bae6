#pragma once
/// \file
/// \brief Clearance-optimal planning for a rigid body: OMPL's MaximizeMinClearanceObjective, with
/// each motion's cost counting both of its ends.

#include <ompl/base/objectives/MaximizeMinClearanceObjective.h>

namespace adsd::planner {

/// \brief Maximizes a path's least clearance at its states: the checker's clearance() at both ends
/// of each motion and at the states OMPL's MinimaxObjective samples between them (the
/// validity-checking resolution apart); larger is better, identity +infinity, infinite -infinity.
///
/// OMPL's MinimaxObjective::motionCost leaves out a motion's first state. A path's cost then never
/// counted its start (a path leaving a start 1 cm from a wall cost 0.216), and a motion cost
/// differently each way (182 of 200 motions in the maze, by up to 0.121) although the objective
/// says it is symmetric, so planners that reuse a motion's cost for the reverse motion (RRT* and
/// its kin) reported costs their paths did not have: SORRT* 0.0797 for a path of 0.0683 (an
/// outside review). Counting the first state costs one more clearance query per motion.
class RigidBodyClearanceObjective : public ompl::base::MaximizeMinClearanceObjective {
 public:
  explicit RigidBodyClearanceObjective(const ompl::base::SpaceInformationPtr& si);

  /// \brief The worse (smaller) of the clearance at \p s1 and OMPL's motion cost (the clearance at
  /// \p s2 and at the states sampled between).
  ompl::base::Cost motionCost(const ompl::base::State* s1, const ompl::base::State* s2) const override;
};

}  // namespace adsd::planner
