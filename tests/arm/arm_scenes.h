#pragma once
/// \file
/// \brief The arm scenes tests/arm shares: the small URDF before one box, and the KR5 among a few
/// boxes (a table slab, a 1 cm thin wall, a pillar, an overhead plate) or among 40 posts, placed in
/// the KR5's base_link frame (z up) and moved into the world with it; uniform joint vectors and
/// the brute-force clearance the tests compare with.

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <memory>
#include <random>
#include <vector>

#include "adsd/distance.h"
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

/// The world pose of the KR5's base_link (z up), where its test scenes are placed.
inline Pose kr5BasePose(const ArmModel& kr5) {
  std::vector<Pose> poses;
  const std::vector<double> zero(kr5.dof(), 0.0);
  forwardKinematics(kr5, zero.data(), poses);
  return poses[kr5.linkIndex("base_link")];
}

/// A joint vector drawn uniformly within the limits into \p q (model.dof() values).
inline void uniformJoints(const ArmModel& model, std::mt19937_64& rng, double* q) {
  for (std::size_t j = 0; j < model.dof(); ++j) {
    const ArmJoint& joint = model.joints[model.activeJoints[j]];
    q[j] = std::uniform_real_distribution<double>(joint.lower, joint.upper)(rng);
  }
}

/// The brute force, the tests' reference: the least exact distance from every link with geometry
/// to every obstacle part and, with \p linkPairs, between the enabled link pairs, at joint vector
/// \p q, pair by pair (no broad phase).
inline double bruteForceClearance(const ArmScene& scene, const double* q, bool linkPairs = true) {
  const ArmModel& m = *scene.model;
  std::vector<Pose> poses;
  forwardKinematics(m, q, poses);
  DistanceScratch scratch;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t l = 0; l < m.links.size(); ++l) {
    if (!m.links[l].collision) continue;
    for (const Mesh& e : scene.environment) {
      best = std::min(best, distance(*m.links[l].collision, poses[l], e, Pose::Identity(),
                                     DistanceOptions::exactDistance(), scratch).distance);
    }
  }
  if (!linkPairs) return best;
  for (const auto& [a, b] : scene.selfPairs.enabledPairs()) {
    best = std::min(best, distance(*m.links[a].collision, poses[a], *m.links[b].collision, poses[b],
                                   DistanceOptions::exactDistance(), scratch).distance);
  }
  return best;
}

/// The KR5 among four boxes (needs the robot cache: ADSD_REQUIRE_ROBOTS first).
inline ArmScene kr5BoxScene() {
  auto model = std::make_shared<const ArmModel>(readUrdf(kr5Urdf()));
  const Pose base = kr5BasePose(*model);
  return makeArmScene(model, {
                                 placedBox(Vec3(0.4, 0.8, 0.02), Vec3(0.5, 0.0, -0.03), base, "table"),
                                 placedBox(Vec3(0.6, 0.01, 0.5), Vec3(0.0, 0.45, 0.35), base, "thin_wall"),
                                 placedBox(Vec3(0.08, 0.08, 0.6), Vec3(-0.4, -0.3, 0.3), base, "pillar"),
                                 placedBox(Vec3(0.3, 0.3, 0.01), Vec3(0.3, -0.3, 0.7), base, "plate"),
                             });
}

/// The KR5 among posts 0.8 m high and \p side square, \p spacing apart on a grid reaching
/// \p rings posts out from its base (the robot's own square left free), in its base_link frame.
/// By default 40 posts (8 cm, 0.2 m apart): enough obstacle parts for the broad phase's box tree
/// to have several levels.
inline ArmScene kr5PostsScene(int rings = 3, double spacing = 0.2, double side = 0.08) {
  auto model = std::make_shared<const ArmModel>(readUrdf(kr5Urdf()));
  const Pose base = kr5BasePose(*model);
  std::vector<Mesh> posts;
  for (int i = -rings; i <= rings; ++i) {
    for (int j = -rings; j <= rings; ++j) {
      if (std::abs(i) <= 1 && std::abs(j) <= 1) continue;  // the robot's own square
      posts.push_back(placedBox(Vec3(side, side, 0.8), Vec3(spacing * i, spacing * j, 0.4), base, "post"));
    }
  }
  return makeArmScene(model, posts);
}

}  // namespace adsd::planner::test
