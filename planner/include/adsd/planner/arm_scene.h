#pragma once
/// \file
/// \brief What an arm planning problem's collision checking is made of: the robot, the pairs of
/// its links that are checked, and a static environment.

#include <memory>
#include <string>
#include <vector>

#include "adsd/mesh.h"
#include "adsd/planner/arm_collision_pairs.h"
#include "adsd/planner/arm_model.h"
#include "adsd/planner/convex_solids.h"

namespace adsd::planner {

/// \brief An arm among fixed obstacles. The arm's root link frame is the world frame.
///
/// Read-only once built, so any number of threads may query it.
struct ArmScene {
  std::shared_ptr<const ArmModel> model;
  /// Link pairs checked against each other; ArmCollisionPairs(*model) when built by makeArmScene.
  ArmCollisionPairs selfPairs;
  /// Obstacles, world frame. May be empty (self-collision only).
  std::vector<Mesh> environment;
  /// What reading the SRDF warned of (disablePairsFromSrdf), one line each.
  std::vector<std::string> warnings;
  /// Obstacles that are solids (a scene's primitives: convex_solids.h): a link inside one is in
  /// collision. Filled by makeArmScene.
  std::vector<ConvexSolid> solids;
};

/// \brief An ArmScene with adjacency-disabled self pairs (and an SRDF's, when \p srdfPath is not
/// empty); the environment's meshes are split into parts for the broad phase (splitIntoParts,
/// pieces about the size of the arm's largest link). \p solids: the obstacles among them that are
/// solids, each a closed convex mesh (PlanningSceneYaml::primitives; convexSolidOf); one that is
/// not, or is flat, stays a surface only.
ArmScene makeArmScene(std::shared_ptr<const ArmModel> model, const std::vector<Mesh>& environment,
                      const std::string& srdfPath = "", const std::vector<Mesh>& solids = {});

}  // namespace adsd::planner
