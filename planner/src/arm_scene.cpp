#include "adsd/planner/arm_scene.h"

#include <algorithm>

#include "adsd/planner/rigid_body_scene.h"

namespace adsd::planner {

ArmScene makeArmScene(std::shared_ptr<const ArmModel> model, const std::vector<Mesh>& environment,
                      const std::string& srdfPath, const std::vector<Mesh>& solids) {
  ArmScene scene{model, ArmCollisionPairs(*model), {}, {}, {}};
  if (!srdfPath.empty()) scene.warnings = disablePairsFromSrdf(*model, srdfPath, scene.selfPairs);
  // Obstacle pieces about the size of the largest link (kPieceDiagonalPerRobotDiameter): the
  // broad phase then skips the pieces far from every link (rigid_body_scene.h says why).
  double linkDiameter = 0.0;
  for (const ArmLink& link : model->links) {
    if (link.collision) linkDiameter = std::max(linkDiameter, link.collision->bounds().diagonal().norm());
  }
  const double piece = linkDiameter > 0.0 ? kPieceDiagonalPerRobotDiameter * linkDiameter
                                          : std::numeric_limits<double>::infinity();
  for (const Mesh& mesh : environment) {
    std::vector<Mesh> parts = splitIntoParts(mesh, kMaxEnvironmentParts, piece);
    for (Mesh& p : parts) scene.environment.push_back(std::move(p));
  }
  // A flat one (a box of no thickness) holds nothing, and stays a surface.
  for (const Mesh& mesh : solids) {
    if (std::optional<ConvexSolid> solid = convexSolidOf(mesh)) scene.solids.push_back(std::move(*solid));
  }
  return scene;
}

}  // namespace adsd::planner
