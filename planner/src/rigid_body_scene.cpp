#include "adsd/planner/rigid_body_scene.h"

#include <algorithm>

namespace adsd::planner {

double robotRadius(const RigidBodyScene& scene) {
  double radius = 0.0;
  for (const Mesh& part : scene.robot) {
    for (const TriangleIndices& t : part.triangles()) {
      for (std::uint32_t v : t) radius = std::max(radius, part.vertices()[v].norm());
    }
  }
  return radius;
}

Eigen::AlignedBox3d environmentBounds(const RigidBodyScene& scene) {
  Eigen::AlignedBox3d box;
  for (const Mesh& part : scene.environment) box.extend(part.bounds());
  return box;
}

double sceneScale(const RigidBodyScene& scene) {
  Eigen::AlignedBox3d box = environmentBounds(scene);
  const double reach = robotRadius(scene);
  if (box.isEmpty()) return 2.0 * reach;
  box.min().array() -= reach;
  box.max().array() += reach;
  return box.diagonal().norm();
}

Mesh recentreRobot(const Mesh& robot, RigidBodySpace space) {
  // OMPL.app takes the mean of all the (joined) vertices, not of the triangles' area: the classic
  // start poses were written against that mean (shared/OMPLAPP-CFG.md).
  Vec3 mean = Vec3::Zero();
  for (const Vec3& v : robot.vertices()) mean += v;
  mean /= static_cast<double>(robot.vertices().size());
  if (space == RigidBodySpace::se2) mean.z() = 0.0;
  std::vector<Vec3> moved = robot.vertices();
  for (Vec3& v : moved) v -= mean;
  return Mesh(std::move(moved), robot.triangles(), robot.name());
}

}  // namespace adsd::planner
