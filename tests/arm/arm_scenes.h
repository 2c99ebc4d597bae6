#pragma once
/// \file
/// \brief The arm scenes tests/arm shares: the small URDF before one box, and the KR5 among a few
/// boxes (a table slab, a 1 cm thin wall, a pillar, an overhead plate), placed in the KR5's
/// base_link frame (z up) and moved into the world with it.

#include <cstdlib>
#include <memory>
#include <vector>

#include "adsd/planner/arm_kinematics.h"
#include "adsd/planner/arm_scene.h"
#include "adsd/planner/primitive_meshes.h"
#include "arm_test_data.h"

namespace adsd::planner::test {

/// A box mesh of \p size centred at \p centre, then moved by \p frame.
inline Mesh placedBox(const Vec3& size, const Vec3& centre, const Pose& frame = Pose::Identity(),
                      const std::string& name = "box") {
  const Mesh box = boxMesh(size, name);
  std::vector<Vec3> v;
  for (const Vec3& p : box.vertices()) v.push_back(frame * (p + centre));
  return Mesh(std::move(v), box.triangles(), name);
}

/// The small arm (tests/arm/data/slider_arm.urdf) with a box whose near face is at y = \p wallY,
/// facing the tip (which is at y = 0.5 for turn = 0; its sphere reaches y = 0.53).
inline ArmScene sliderScene(double wallY) {
  auto model = std::make_shared<const ArmModel>(readUrdf(armTestData("slider_arm.urdf")));
  return makeArmScene(model, {placedBox(Vec3(0.2, 0.1, 0.2), Vec3(0.0, wallY + 0.05, 0.225))});
}

/// The KR5 among four boxes (needs the robot cache: ADSD_REQUIRE_ROBOTS first).
inline ArmScene kr5BoxScene() {
  auto model = std::make_shared<const ArmModel>(readUrdf(kr5Urdf()));
  std::vector<Pose> poses;
  const std::vector<double> zero(model->dof(), 0.0);
  forwardKinematics(*model, zero.data(), poses);
  const Pose base = poses[model->linkIndex("base_link")];
  return makeArmScene(model, {
                                 placedBox(Vec3(0.4, 0.8, 0.02), Vec3(0.5, 0.0, -0.03), base, "table"),
                                 placedBox(Vec3(0.6, 0.01, 0.5), Vec3(0.0, 0.45, 0.35), base, "thin_wall"),
                                 placedBox(Vec3(0.08, 0.08, 0.6), Vec3(-0.4, -0.3, 0.3), base, "pillar"),
                                 placedBox(Vec3(0.3, 0.3, 0.01), Vec3(0.3, -0.3, 0.7), base, "plate"),
                             });
}

/// The KR5 among 40 posts (8 cm square, 0.8 m high) on a 0.2 m grid around its base, in its
/// base_link frame: enough obstacle parts for the broad phase's box tree to have several levels.
inline ArmScene kr5PostsScene() {
  auto model = std::make_shared<const ArmModel>(readUrdf(kr5Urdf()));
  std::vector<Pose> poses;
  const std::vector<double> zero(model->dof(), 0.0);
  forwardKinematics(*model, zero.data(), poses);
  const Pose base = poses[model->linkIndex("base_link")];
  std::vector<Mesh> posts;
  for (int i = -3; i <= 3; ++i) {
    for (int j = -3; j <= 3; ++j) {
      if (std::abs(i) <= 1 && std::abs(j) <= 1) continue;  // the robot's own square
      posts.push_back(placedBox(Vec3(0.08, 0.08, 0.8), Vec3(0.2 * i, 0.2 * j, 0.4), base, "post"));
    }
  }
  return makeArmScene(model, posts);
}

}  // namespace adsd::planner::test
