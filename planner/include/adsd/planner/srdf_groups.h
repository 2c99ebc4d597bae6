#pragma once
/// \file
/// \brief The planning groups of an SRDF file: which of an arm's joints a request's `group_name`
/// plans for, the others held at the start state (as MoveIt plans).

#include <optional>
#include <string>
#include <vector>

#include "adsd/planner/arm_model.h"

namespace adsd::planner {

/// \brief The joint-vector joints of \p model in planning group \p group as the SRDF file
/// \p srdfPath defines it (MoveIt's `<group name="">`: each `<joint name="">`, the joints along each
/// `<chain base_link="" tip_link="">`, the tree's path between the two, through their common
/// ancestor when neither is below the other, the joint that carries each `<link name="">`, and the
/// joints of each `<group name="">` it includes), in joint-vector order; std::nullopt when the file
/// defines no group of that name. Throws adsd::InputError naming the file and line for a joint,
/// link or group that the robot or the file lacks, groups that include each other, or a group with
/// no movable joint.
std::optional<std::vector<std::string>> srdfGroupJoints(const ArmModel& model, const std::string& srdfPath,
                                                        const std::string& group);

}  // namespace adsd::planner
