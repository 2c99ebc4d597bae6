#pragma once
/// \file
/// \brief What every viewer page is made of, a rigid robot's (viewer_html.h) or an arm's
/// (arm_viewer_html.h): the robot as rigid bodies, each body's pose at each state, the clearance
/// and the closest points there, filled into the page template viewer/viewer.html.

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "adsd/distance.h"
#include "adsd/mesh.h"

namespace adsd::app {

/// \brief One rigid part of the robot as drawn: meshes in the body's own frame. A rigid robot is
/// one body; an arm has one per link with collision geometry.
struct ViewerBody {
  std::string name;
  std::vector<const Mesh*> parts;
};

/// \brief The closest pair of points at one state, world frame: \p onA on body \p bodyA, \p onB on
/// body \p bodyB, or on the environment when bodyB is kEnvironment.
struct ClosestPoints {
  static constexpr int kEnvironment = -1;
  int bodyA = 0;
  int bodyB = kEnvironment;
  Vec3 onA = Vec3::Zero();
  Vec3 onB = Vec3::Zero();
  /// When bodyB is kEnvironment: the object it is part of (an arm scene's collision object id), so
  /// that the page names it rather than saying "obstacle".
  std::string obstacle;
};

/// \brief One state shown.
struct ViewerState {
  std::vector<Pose> bodyPoses;  ///< world pose of each body, in ViewerPage::bodies' order
  double clearance = 0.0;       ///< the checker's clearance (metres, or the problem's length unit)
  ClosestPoints closest;
  std::vector<double> joints;   ///< an arm's joint vector (ViewerPage::jointNames' order); else empty
  /// A body point inside a solid obstacle, where no surfaces meet (an arm's link wholly inside a
  /// primitive: clearance 0): shown when no mesh pair realizes the clearance. Set by describe.
  std::optional<ClosestPoints> inside;
};

/// \brief Everything a page shows.
struct ViewerPage {
  std::string name;    ///< the problem's name: the page's title
  std::string space;   ///< the state space, as the page names it: "SE(2)", "SE(3)", "joints"
  std::string source;  ///< where the states came from (a path file, `adsd plan`, start and goal)
  Vec3 up = Vec3::UnitZ();  ///< world direction drawn upwards (unit)
  const std::vector<Mesh>* environment = nullptr;  ///< the obstacles, world frame
  std::vector<ViewerBody> bodies;
  std::vector<Pose> start, goal;  ///< each body's pose at the problem's start and goal
  std::vector<std::string> jointNames;  ///< an arm's joints; empty for a rigid robot
  std::vector<ViewerState> states;
};

/// \brief What a page writer wrote (writeViewerHtml, writeArmViewerHtml).
struct ViewerSummary {
  std::size_t states = 0;     ///< states shown (the path at the resolution `adsd plan` measures it)
  double minClearance = 0.0;  ///< least of the checker's clearance over those states
  std::size_t bytes = 0;      ///< size of the page
  bool coarserThanResolution = false;  ///< the path's states capped (planner::kMaxMeasuredStates)
};

/// \brief A pair of meshes that may realize a state's clearance, posed in the world frame; the
/// body indices are what ClosestPoints reports for it.
struct CandidatePair {
  const Mesh* a;
  Pose poseA;
  const Mesh* b;
  Pose poseB;
  int bodyA;
  int bodyB;
};

/// \brief Witness search slack, relative to the scene's length scale (dimensionless): a mesh pair
/// whose distance is within this of the checker's clearance realizes it. Ten times the core's
/// promised accuracy (1e-10 of the scene's diagonal, adsd/distance.h), so rounding cannot hide
/// the pair.
constexpr double kWitnessSlackPerScale = 1e-9;

/// \brief Describes state \p i of a page: sets \p state's body poses, clearance (and an arm's
/// joints), and puts into \p pairs (given empty) the mesh pairs that may realize the clearance.
using DescribeState = std::function<void(std::size_t i, ViewerState& state, std::vector<CandidatePair>& pairs)>;

/// \brief Adds \p count states to \p page, each from \p describe with its closest points: those of
/// the pair whose distance is the state's clearance (to within \p slack), found by queries capped
/// just above it, which stop at the hull bounds for the far pairs; should the clearance be another
/// engine's (FCL's) and no pair come within the cap, of the exact minimum over all pairs. Then
/// fills the page template with \p page and three.js and writes it to \p file through a temporary
/// file renamed on success, so a failure leaves nothing half-written. Throws adsd::InputError
/// naming \p file when it cannot be written.
ViewerSummary writeViewerPage(const std::string& file, ViewerPage& page, std::size_t count,
                              const DescribeState& describe, double slack);

}  // namespace adsd::app
