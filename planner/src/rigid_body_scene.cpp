#include "adsd/planner/rigid_body_scene.h"

#include <algorithm>
#include <numeric>

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

std::vector<Mesh> splitIntoParts(const Mesh& mesh, std::size_t maxParts) {
  // Union-find over vertices: the corners of a triangle belong together.
  std::vector<std::uint32_t> parent(mesh.vertices().size());
  std::iota(parent.begin(), parent.end(), 0u);
  const auto root = [&parent](std::uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const TriangleIndices& t : mesh.triangles()) {
    for (int k = 1; k < 3; ++k) parent[root(t[k])] = root(t[0]);
  }
  // Components in order of first appearance, each with its triangles and box.
  std::vector<std::int64_t> componentOfRoot(parent.size(), -1);
  std::vector<std::vector<std::size_t>> components;
  std::vector<Eigen::AlignedBox3d> boxes;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const std::uint32_t r = root(mesh.triangles()[t][0]);
    if (componentOfRoot[r] < 0) {
      componentOfRoot[r] = static_cast<std::int64_t>(components.size());
      components.emplace_back();
      boxes.emplace_back();
    }
    components[componentOfRoot[r]].push_back(t);
    for (int k = 0; k < 3; ++k) boxes[componentOfRoot[r]].extend(mesh.corner(t, k));
  }
  if (components.size() <= 1) return {mesh};

  // Group neighbours when there are too many: sort by box centre along the longest axis, then cut
  // the sequence into maxParts runs of about equal size.
  std::vector<std::size_t> order(components.size());
  std::iota(order.begin(), order.end(), 0);
  std::size_t groups = components.size();
  if (groups > maxParts && maxParts > 0) {
    Eigen::Index axis = 0;
    mesh.bounds().sizes().maxCoeff(&axis);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return boxes[a].center()[axis] < boxes[b].center()[axis]; });
    groups = maxParts;
  }
  std::vector<Mesh> parts;
  for (std::size_t g = 0; g < groups; ++g) {
    const std::size_t begin = g * order.size() / groups, end = (g + 1) * order.size() / groups;
    std::vector<Vec3> vertices;
    std::vector<TriangleIndices> triangles;
    std::vector<std::int64_t> remap(mesh.vertices().size(), -1);
    for (std::size_t i = begin; i < end; ++i) {
      for (std::size_t t : components[order[i]]) {
        TriangleIndices out{};
        for (int k = 0; k < 3; ++k) {
          const std::uint32_t v = mesh.triangles()[t][k];
          if (remap[v] < 0) {
            remap[v] = static_cast<std::int64_t>(vertices.size());
            vertices.push_back(mesh.vertices()[v]);
          }
          out[k] = static_cast<std::uint32_t>(remap[v]);
        }
        triangles.push_back(out);
      }
    }
    parts.emplace_back(std::move(vertices), std::move(triangles), mesh.name() + " part " + std::to_string(g));
  }
  return parts;
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
