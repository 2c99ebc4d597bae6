#pragma once
// FCL's model of a mesh, as both FCL baselines build it (fcl_validity_checker.cpp for rigid bodies,
// fcl_arm_validity_checker.cpp for arms): an OBBRSS hierarchy, FCL's choice for distance queries.

#include <memory>
#include <vector>

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/OBBRSS.h>

#include "adsd/error.h"
#include "adsd/mesh.h"

namespace adsd::planner::detail {

using FclModel = fcl::BVHModel<fcl::OBBRSSd>;

/// FCL's OBBRSS hierarchy of \p mesh, built once. Throws adsd::InputError when FCL refuses it.
inline std::shared_ptr<FclModel> buildFclModel(const Mesh& mesh) {
  std::vector<fcl::Vector3d> vertices(mesh.vertices().begin(), mesh.vertices().end());
  std::vector<fcl::Triangle> triangles;
  triangles.reserve(mesh.triangleCount());
  for (const TriangleIndices& t : mesh.triangles()) triangles.emplace_back(t[0], t[1], t[2]);
  auto model = std::make_shared<FclModel>();
  if (model->beginModel() != fcl::BVH_OK || model->addSubModel(vertices, triangles) != fcl::BVH_OK ||
      model->endModel() != fcl::BVH_OK) {
    throw InputError(mesh.name() + ": FCL could not build its OBBRSS hierarchy");
  }
  return model;
}

}  // namespace adsd::planner::detail
