#pragma once
/// \file
/// \brief The FCL side of the comparisons: our meshes as FCL 0.7 models, and FCL's distance,
/// asked for exactly what our exact query answers.
///
/// FCL's vector and pose types are Eigen's (fcl::Vector3d is Eigen::Vector3d, fcl::Transform3d is
/// Eigen::Isometry3d), so vertices and poses pass through without conversion; only the triangle
/// index type differs, and it is converted once per mesh (topology never changes, not even for
/// deforming meshes), outside any timing.

#include <limits>
#include <memory>
#include <vector>

#include <fcl/fcl.h>
#include <fcl/narrowphase/detail/traversal/distance/mesh_distance_traversal_node.h>
#include <fcl/narrowphase/detail/traversal/collision_node.h>

#include "adsd/mesh.h"

namespace adsd::bench {

using FclObbrssModel = fcl::BVHModel<fcl::OBBRSSd>;

static_assert(std::is_same_v<fcl::Vector3d, adsd::Vec3>, "FCL and adsd share Eigen's vector type");
static_assert(std::is_same_v<fcl::Transform3d, adsd::Pose>, "FCL and adsd share Eigen's isometry type");

/// \brief The triangles of \p mesh in FCL's index type.
inline std::vector<fcl::Triangle> fclTriangles(const Mesh& mesh) {
  std::vector<fcl::Triangle> out;
  out.reserve(mesh.triangleCount());
  for (const TriangleIndices& t : mesh.triangles()) out.emplace_back(t[0], t[1], t[2]);
  return out;
}

/// \brief Builds FCL's OBBRSS hierarchy over the vertices and triangles (what a user of FCL pays
/// whenever the geometry is new or has deformed).
inline std::shared_ptr<FclObbrssModel> buildObbrss(const std::vector<Vec3>& vertices,
                                                   const std::vector<fcl::Triangle>& triangles) {
  auto model = std::make_shared<FclObbrssModel>();
  model->beginModel(static_cast<int>(triangles.size()), static_cast<int>(vertices.size()));
  model->addSubModel(vertices, triangles);
  model->endModel();
  return model;
}

/// \brief FCL's answer for deforming geometry without a rebuild: new vertex positions, then the
/// existing hierarchy's volumes refitted (same tree topology, volumes refitted to the primitives
/// below each node).
///
/// Top-down, not FCL's default bottom-up: with OBBRSS (and RSS), FCL 0.7's bottom-up refit
/// merges child volumes into parents that do not contain them; measured on a rippled cow pair in
/// contact, fcl::distance then returned 0.43 where the rebuilt models (and the oracle) give 0
/// (bench_scenes showed the same on the teddies: 3 of 3 oracle queries wrong). The top-down refit fits each node to its primitives again and answers correctly.
inline void refitObbrss(FclObbrssModel& model, const std::vector<Vec3>& vertices) {
  model.beginUpdateModel();
  model.updateSubModel(vertices);
  model.endUpdateModel(/*refit=*/true, /*bottomup=*/false);
}

/// \brief FCL's boolean collision check (first contact ends it): the validity question.
inline bool fclCollide(const FclObbrssModel& a, const Pose& poseA, const FclObbrssModel& b, const Pose& poseB) {
  fcl::CollisionRequestd request;  // one contact suffices for a yes/no answer
  fcl::CollisionResultd result;
  fcl::collide(&a, poseA, &b, poseB, request, result);
  return result.isCollision();
}

/// \brief FCL's exact mesh–mesh distance: nearest points on, no error allowance (rel_err =
/// abs_err = 0, the defaults, stated here because they are what makes the comparison fair).
inline fcl::DistanceResultd fclDistance(const FclObbrssModel& a, const Pose& poseA,
                                        const FclObbrssModel& b, const Pose& poseB) {
  fcl::DistanceRequestd request(/*enable_nearest_points=*/true);
  request.rel_err = 0.0;
  request.abs_err = 0.0;
  fcl::DistanceResultd result;
  fcl::distance(&a, poseA, &b, poseB, request, result);
  return result;
}

/// \brief What FCL's exact distance query did: its bounding-volume pair tests and its triangle pair
/// tests (the traversal's own statistics), beside its answer: the counters to set against ours
/// (DistanceCounters::subMeshPairs and trianglePairsTested) when a ratio needs explaining.
struct FclDistanceWork {
  double distance = 0.0;
  int boundingVolumeTests = 0;
  int triangleTests = 0;
};

/// \brief fclDistance with the traversal's statistics on: the same path fcl::distance takes for two
/// OBBRSS models (its traversal node, initialised and recursed as FCL's distance function does),
/// untimed (the statistics cost a little). \p relativeError is FCL's rel_err: 0 for the exact
/// query, 0.01 for the counterpart of our 1 % tolerance. FCL 0.7's mesh traversal node copies
/// rel_err and abs_err from a default request in its constructor and initialize() leaves them
/// there, so fcl::distance between two meshes ignores them: the tolerance is set on the node
/// itself, to count what FCL's rule would skip. That rule (MeshDistanceTraversalNode::canStop)
/// drops a pair only when its bound passes both the absolute and the relative test, so a
/// relative tolerance alone takes abs_err = infinity.
inline FclDistanceWork fclDistanceWork(const FclObbrssModel& a, const Pose& poseA, const FclObbrssModel& b,
                                       const Pose& poseB, double relativeError = 0.0) {
  fcl::DistanceRequestd request(/*enable_nearest_points=*/true);
  request.rel_err = relativeError;
  request.abs_err = relativeError > 0.0 ? std::numeric_limits<double>::infinity() : 0.0;
  fcl::DistanceResultd result;
  fcl::detail::MeshDistanceTraversalNodeOBBRSS<double> node;
  fcl::detail::initialize(node, a, poseA, b, poseB, request, result);
  node.rel_err = request.rel_err;
  node.abs_err = request.abs_err;
  node.enable_statistics = true;
  fcl::detail::distance(&node);
  return {result.min_distance, node.num_bv_tests, node.num_leaf_tests};
}

/// \brief The convex hull of a mesh's vertices as an FCL Convex, for hull-overlap checks.
///
/// FCL 0.7's Convex walks vertex adjacency to find support points when its faces describe a
/// closed surface; on a non-convex mesh that walk stops at local maxima. Giving it a single face
/// leaves most vertices unconnected, which makes FCL fall back to scanning every vertex
/// (Convex::ValidateMesh disables the walk), so its support mapping is that of the true hull.
inline std::shared_ptr<fcl::Convexd> fclHull(const Mesh& mesh) {
  auto vertices = std::make_shared<std::vector<fcl::Vector3d>>(mesh.vertices());
  const TriangleIndices& t = mesh.triangles().front();
  auto faces = std::make_shared<std::vector<int>>(
      std::vector<int>{3, static_cast<int>(t[0]), static_cast<int>(t[1]), static_cast<int>(t[2])});
  return std::make_shared<fcl::Convexd>(vertices, 1, faces, /*throw_if_invalid=*/false);
}

/// \brief Whether the convex hulls of the two placed meshes intersect (FCL's GJK on the hulls).
inline bool fclHullsOverlap(const fcl::Convexd& hullA, const Pose& poseA, const fcl::Convexd& hullB,
                            const Pose& poseB) {
  fcl::CollisionRequestd request;
  fcl::CollisionResultd result;
  fcl::collide(&hullA, poseA, &hullB, poseB, request, result);
  return result.isCollision();
}

}  // namespace adsd::bench
