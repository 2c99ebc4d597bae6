#pragma once
/// \file
/// \brief The part every rigid-body checker shares (ours and FCL's): the OMPL interface, the
/// bounds check, the broad phase over robot × environment mesh pairs, and the counters.

#include <array>
#include <cstddef>
#include <memory>
#include <vector>

#include <Eigen/Geometry>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/StateValidityChecker.h>

#include "adsd/planner/query_counters.h"
#include "adsd/planner/rigid_body_scene.h"

namespace adsd::planner {

/// \brief A state validity checker for a rigid robot among fixed obstacles.
///
/// A state is valid when it lies within the space's bounds and the distance between the robot's
/// meshes and the environment's meshes is above the safety margin (default 0: touching is a
/// collision). All const methods are thread-safe and take no lock: subclasses keep their per-query
/// memory per thread and the counters are atomic.
///
/// Broad phase: each robot mesh is enclosed in a body-frame ball and a body-frame box, each
/// environment mesh in a world-frame box. The larger of the ball–box distance and the distance
/// between the environment box and the world box around the posed robot box is a lower bound on
/// the pair's distance (the box suits long thin robots, the ball turned ones). A mesh pair whose
/// bound exceeds the current bound (the safety margin for validity, the best distance so far for
/// clearance) by more than roundoff cannot change the answer and is skipped; the pairs left are
/// visited nearest first so that a collision is found, or the clearance bound tightens, early.
class RigidBodyValidityChecker : public ompl::base::StateValidityChecker {
 public:
  RigidBodyValidityChecker(const ompl::base::SpaceInformationPtr& si, std::shared_ptr<const RigidBodyScene> scene,
                           double safetyMargin);

  /// \brief Bounds check, then the threshold query: is the distance above the safety margin.
  bool isValid(const ompl::base::State* state) const final;
  /// \brief \p dist is clearance(state), and the state is valid when it is within bounds and dist >
  /// safetyMargin(); when the clearance is a lower bound (not EXACT) at or below the margin, the
  /// threshold query decides, so the answer is always isValid(state)'s.
  bool isValid(const ompl::base::State* state, double& dist) const final;
  /// \brief The distance between robot and environment (exact, or a lower bound when the
  /// subclass says so in specs_.clearanceComputationType). A state whose pose the distance query
  /// cannot take (a NaN coordinate, a zero quaternion, a translation beyond
  /// tolerance::kMaxCoordinate) is invalid, at clearance 0.
  double clearance(const ompl::base::State* state) const final;

  /// \brief A lower bound on the distance at \p state that equals clearance(state) when that is
  /// below \p cap and is at least min(clearance, cap) otherwise (up to the checker's own
  /// tolerance). The certified motion validator asks only for as much as it needs. Counted as a
  /// clearance query. Throws adsd::InputError for a cap that is negative or NaN.
  double clearanceUpTo(const ompl::base::State* state, double cap) const;

  double safetyMargin() const { return safetyMargin_; }
  double robotRadius() const { return robotRadius_; }
  /// \brief The scene's length scale (see sceneScale()).
  double scale() const { return scale_; }
  const RigidBodyScene& scene() const { return *scene_; }
  RigidBodySpace space() const { return scene_->space; }

  QueryCounts counts() const { return counters_.snapshot(); }
  void resetCounts() { counters_.reset(); }

 protected:
  /// \brief What one mesh pair's distance query established.
  struct PairDistance {
    double lower = 0.0;        ///< a lower bound on the pair's distance (exact when exact)
    bool reachedCap = false;   ///< the pair's distance is proven >= the cap it was given
  };

  /// \brief Is robot mesh \p r (placed by \p robotPose) farther than \p margin from environment
  /// mesh \p e? Called only for pairs the broad phase could not decide.
  virtual bool pairSeparatedAbove(std::size_t r, std::size_t e, const Pose& robotPose, double margin) const = 0;
  /// \brief Distance of one pair, as precise as the checker's clearance setting, needed only
  /// below \p cap (infinite cap: always needed).
  virtual PairDistance pairDistance(std::size_t r, std::size_t e, const Pose& robotPose, double cap) const = 0;

  std::shared_ptr<const RigidBodyScene> scene_;

 private:
  /// \brief A mesh pair the broad phase could not skip, with its lower bound.
  struct PairBound {
    double lower;
    std::size_t robot;
    std::size_t environment;
  };
  /// \brief Fills \p pairs with the mesh pairs whose lower bound is at most \p limit plus the
  /// roundoff allowance (in no particular order), and returns that allowance. Environment boxes
  /// are kept coordinate by coordinate: the loop over them runs on every check.
  double broadPhase(const Pose& robotPose, double limit, std::vector<PairBound>& pairs) const;
  bool separatedAbove(const Pose& robotPose, double margin) const;
  double distanceUpTo(const Pose& robotPose, double cap) const;
  /// distanceUpTo at the state's pose, 0 for a pose that is not finite.
  double clearanceOf(const ompl::base::State* state, double cap) const;

  double safetyMargin_;
  double robotRadius_;
  double scale_;
  std::vector<Vec3> robotBallCentres_;  ///< body frame
  std::vector<double> robotBallRadii_;
  std::vector<Eigen::AlignedBox3d> robotBoxes_;  ///< body frame
  /// Environment boxes, world frame: centres and half extents, one array per coordinate.
  std::array<std::vector<double>, 3> environmentCentres_, environmentHalves_;
  mutable QueryCounters counters_;
};

}  // namespace adsd::planner
