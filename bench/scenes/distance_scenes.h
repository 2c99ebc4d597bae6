#pragma once
/// \file
/// \brief The distance benchmark's scenes, defined once for the benchmarks and the tests (STYLE
/// habit 11): the paper's scenes (sec. 7) on real models from the mesh cache, plus bunny pairs.
///
/// | name              | meshes                                   | queries                         |
/// |-------------------|------------------------------------------|---------------------------------|
/// | cows              | CGAL cow.off × 2 (5 804 each)            | rigid close poses               |
/// | stick_dragon      | our capsule (1 024) × npm dragon res4 (10 600: 11 102 less 502 repeats) | rigid close poses |
/// | teddies_deforming | CGAL bear.off × 2 (27 648 each)          | consecutive frames of a smooth  |
/// |                   |                                          | deformation, B swaying close    |
/// | camels            | CGAL camel.off × 2 (19 536 each)         | rigid close poses               |
/// | bunnies           | npm bunny × 2 (3 674 each)               | rigid close poses               |
/// | problem_NAME      | robot × environment of a shipped planning problem (problems/scenes;  |
/// |                   | cow_doorway's robot is the cached cow)   | robot states near obstacles     |
///
/// Close poses: gaps log-uniform in [0.1 %, 5 %] of the larger bounding-box diagonal, convex hulls
/// overlapping (bench/scenes/close_poses.h). Placing them needs a distance and a hull test; the
/// caller supplies both (the benchmarks use FCL, a test may use the oracle), so the scenes depend
/// on no method under test. Planning problems: the robot (mesh A) slides from a random free state
/// until its clearance is 0.1 %–5 % of its own bounding-box diagonal (near_obstacle_poses.h); the
/// environment (mesh B) stays at the identity.

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "adsd/mesh.h"
#include "close_poses.h"
#include "near_obstacle_poses.h"
#include "smooth_deformation.h"

namespace adsd::bench {

/// \brief One scene: two meshes at rest and the placements of its queries.
struct DistanceScene {
  DistanceScene(std::string sceneName, std::string sceneDescription, Mesh meshA, Mesh meshB)
      : name(std::move(sceneName)), description(std::move(sceneDescription)), a(std::move(meshA)), b(std::move(meshB)) {}

  std::string name;
  std::string description;
  Mesh a;  ///< rest shape, mesh frame
  Mesh b;
  /// One per query. For a deforming scene, one per frame (in frame order).
  std::vector<PosePair> poses;
  bool deforming = false;
  /// A planning problem's robot against its environment: rigid, models built once by any method
  /// (FCL's per-query rebuild is no fair comparison there and is not run).
  bool planning = false;
  /// Deforming scenes: frame i shows mesh A displaced by deformA at t = i (and B by deformB).
  SmoothDeformation deformA;
  SmoothDeformation deformB;
  /// The scale of every tolerance and gap: the larger of the two rest bounding-box diagonals
  /// (planning problems: the robot's, since clearances are robot-sized).
  double referenceLength = 0.0;

  std::size_t queryCount() const { return poses.size(); }
  std::size_t triangleCount() const { return a.triangleCount() + b.triangleCount(); }

  /// \brief The vertices of both meshes at query \p i (deformed for a deforming scene, the rest
  /// vertices otherwise), written into \p verticesA and \p verticesB.
  void verticesAt(std::size_t i, std::vector<Vec3>& verticesA, std::vector<Vec3>& verticesB) const;
};

/// \brief How many queries to make.
struct SceneSize {
  std::size_t rigidPoses = 60;  ///< per rigid scene
  std::size_t frames = 1000;    ///< for the deforming scene (the paper's 1 000 frames)
};

/// \brief What placing close poses needs, for one mesh pair (at rest).
struct Placement {
  GapFunction gap;
  HullOverlapFunction hullsOverlap;
};
/// \brief Makes the Placement for meshes a and b (called once per scene, with the scene's meshes).
using PlacementFactory = std::function<Placement(const Mesh& a, const Mesh& b)>;

/// \brief The scene names, in the benchmark's order: the paper's scenes and bunnies, then the
/// planning problems (problem_NAME for each of adsd::shapes::allProblemScenes()).
const std::vector<std::string>& distanceSceneNames();

/// \brief Builds scene \p name: loads its meshes from the mesh cache (meshCacheDir()), generates
/// ours, places the queries with \p placement. Throws adsd::InputError for an unknown name or a
/// mesh missing from the cache (the message says how to fetch it).
DistanceScene makeDistanceScene(const std::string& name, const SceneSize& size, const PlacementFactory& placement);

}  // namespace adsd::bench
