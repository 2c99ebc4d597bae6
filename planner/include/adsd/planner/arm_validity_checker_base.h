#pragma once
/// \file
/// \brief The part every arm checker shares (ours and FCL's): the OMPL interface, forward
/// kinematics into per-thread scratch, the broad phase over link × obstacle and link × link pairs,
/// and the counters.

#include <array>
#include <cstdint>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/StateValidityChecker.h>

#include "adsd/tolerances.h"
#include "adsd/planner/arm_scene.h"
#include "adsd/planner/arm_state_space.h"
#include "adsd/planner/query_counters.h"

namespace adsd::planner {

/// \brief A state validity checker for an arm: every checked link against every obstacle, and the
/// enabled link pairs against each other.
///
/// A state is valid when it lies within the space's bounds, every such distance is above the
/// safety margin (default 0: touching is a collision), and no link lies inside one of the scene's
/// solids (ArmScene::solids: its primitives) and no obstacle or checked link lies inside one of a
/// link's own (ArmLink::solids: its primitive <collision> elements); inside, the distance and the
/// clearance are 0. The space must be an ArmStateSpace of the scene's model. All const methods
/// are thread-safe and take no lock: the joint vector, the link poses and the pair list live in
/// thread_local scratch, and the counters are atomic.
///
/// Broad phase (as RigidBodyValidityChecker's): each link's mesh has a ball and a box in its link
/// frame, each obstacle part a box in the world frame. A pair's lower bound is the larger of its
/// ball and box gaps (for link × link: ball–ball and box–box; the posed box is the world box
/// around the link box). Pairs whose bound exceeds the current bound (margin, or best distance so
/// far) by more than roundoff are skipped; the rest are visited nearest first. The obstacle parts'
/// boxes sit in a tree (median splits, a few parts per leaf), so a link meets only the parts its
/// box can reach: on a cage of 146 bars, testing every part took a third of a validity check.
///
/// Bodies: the narrow phase sees body indices, links with geometry first (body b < linkBodies(),
/// link linkOfBody(b)), then the obstacle parts.
class ArmValidityCheckerBase : public ompl::base::StateValidityChecker {
 public:
  /// \brief Throws adsd::InputError when the space is not an ArmStateSpace with the model's joint
  /// count, or the margin is negative or not finite.
  ArmValidityCheckerBase(const ompl::base::SpaceInformationPtr& si, std::shared_ptr<const ArmScene> scene,
                         double safetyMargin);

  /// \brief Bounds check, then threshold queries: is every checked distance above the margin.
  bool isValid(const ompl::base::State* state) const final;
  /// \brief \p dist is clearance(state); valid when within bounds and dist > safetyMargin().
  bool isValid(const ompl::base::State* state, double& dist) const final;
  /// \brief The smallest distance over the checked pairs (link–obstacle and enabled link–link).
  /// A state with a joint value that is not finite (NaN) is invalid, at clearance 0.
  double clearance(const ompl::base::State* state) const final;
  /// \brief A lower bound on clearance(state) that equals it when below \p cap and is at least
  /// min(clearance, cap) otherwise. Counted as a clearance query.
  double clearanceUpTo(const ompl::base::State* state, double cap) const;
  /// \brief clearanceUpTo() over the links against the obstacles only (the link pairs left out):
  /// what MoveIt calls the distance to collision. Infinity when there is no obstacle and \p cap is
  /// infinite. Counted as a clearance query.
  double obstacleClearanceUpTo(const ompl::base::State* state, double cap) const;

  /// \brief The weighted clearance the certified motion check needs (ArmMotionValidator):
  ///   min over checked pairs P with w_P > 0 of (distance_P - subtract) / w_P,
  /// where w_P = linkWeights[L] for link L against an obstacle (one weight per link) and
  /// selfPairWeights[k] for the k-th pair of scene().selfPairs.enabledPairs(); weights >= 0. A
  /// lower bound of it that equals it when below \p cap and is at least \p cap otherwise; pairs
  /// with w_P = 0 are left out (their distance cannot change). Counted as a clearance query.
  double weightedClearanceUpTo(const ompl::base::State* state, const double* linkWeights,
                               const double* selfPairWeights, double subtract, double cap) const;

  /// \brief For messages: the checked pairs not separated by more than the safety margin at
  /// \p state, in checking order, as "links 'A' and 'B'" or "link 'A' and obstacle 'NAME'"; at most
  /// \p count of them, then "and N more pairs" ("pair" for one). Empty when the state is free. Tests every pair
  /// (no broad phase): not for a planner's inner loop.
  std::vector<std::string> pairsInContact(const ompl::base::State* state, std::size_t count = 3) const;

  double safetyMargin() const { return safetyMargin_; }
  /// \brief The scene's length scale: the diagonal of the box around the obstacles and the arm's
  /// reach (the arm's links placed anywhere within reach of the root).
  double scale() const { return scale_; }
  const ArmScene& scene() const { return *scene_; }
  const ArmModel& model() const { return *scene_->model; }
  const ArmStateSpace& armSpace() const { return *space_; }

  QueryCounts counts() const { return counters_.snapshot(); }
  void resetCounts() { counters_.reset(); }

  std::size_t linkBodies() const { return linkOfBody_.size(); }
  std::size_t linkOfBody(std::size_t body) const { return linkOfBody_[body]; }
  /// \brief The mesh of body \p b (a link's collision mesh, or an obstacle part).
  const Mesh& bodyMesh(std::size_t b) const;

 protected:
  /// \brief What one pair's distance query established.
  struct PairDistance {
    double lower = 0.0;       ///< a lower bound on the pair's distance (exact when exact)
    bool reachedCap = false;  ///< the pair's distance is proven >= the cap it was given
  };
  /// \brief Are bodies \p a and \p b, at these world poses, farther apart than \p margin?
  virtual bool pairSeparatedAbove(std::size_t a, const Pose& poseA, std::size_t b, const Pose& poseB,
                                  double margin) const = 0;
  /// \brief The pair's distance, as precise as the checker's clearance setting, needed only below
  /// \p cap (infinite: always needed).
  virtual PairDistance pairDistance(std::size_t a, const Pose& poseA, std::size_t b, const Pose& poseB,
                                    double cap) const = 0;

  std::shared_ptr<const ArmScene> scene_;

 private:
  struct PairBound {
    double lower;
    std::size_t a, b;
  };
  /// Joint vector and link poses for the state, in the calling thread's scratch; null when a
  /// joint value is not finite. A NaN passes OMPL's bounds test for a revolute or prismatic joint
  /// (its comparisons are false), and the distance query refuses the poses it makes by throwing
  /// into the planner: such a state is invalid, at clearance 0 (a NaN continuous joint already
  /// failed SO(2)'s bounds test).
  const std::vector<Pose>* posesFor(const ompl::base::State* state) const;
  /// The scene's solid that holds link body \p body at \p pose (a vertex of each of its
  /// components strictly inside), or null: ArmScene::solids.
  const ConvexSolid* solidHolding(std::size_t body, const Pose& pose) const;
  /// How far inside a solid's faces a point must lie to count as inside (the roundoff allowance
  /// at the scene's scale): on a face, the distance queries find the contact.
  double insideSlack() const { return tolerance::kBoundSafetyUlps * tolerance::kEpsilon * scale_; }
  /// Whether some link lies inside a solid at these poses.
  bool anyLinkInsideSolid(const std::vector<Pose>& linkPoses) const;
  /// Whether a link's own solid (ArmLink::solids) wholly holds an obstacle part or the other link
  /// of an enabled pair at these poses (a vertex of each of its components strictly inside) for
  /// which \p counts(holder body, held body) returns true; bodies as in pairsInContact (obstacle
  /// part e is body linkOfBody_.size() + e). Defined in the .cpp, its one user.
  template <class Counts>
  bool heldByALinkSolid(const std::vector<Pose>& linkPoses, Counts counts) const;
  /// Down the obstacle parts' box tree: \p visit(e, squared box gap) for each obstacle part e whose
  /// world box lies within sqrt(\p reach2) of the world box (\p centre, \p half), until it returns
  /// true (then true). Defined in the .cpp.
  template <class Visit>
  bool forObstaclePartsNear(const Vec3& centre, const Vec3& half, double reach2, Visit visit) const;
  double broadPhase(const std::vector<Pose>& linkPoses, double limit, std::vector<PairBound>& pairs) const;
  /// Link body \p body's box at these poses, in the world frame (centre, half extents).
  void posedLinkBox(const std::vector<Pose>& linkPoses, std::size_t body, Vec3& centre, Vec3& half) const;
  /// The clearance queries' first pair, measured before their broad phase when the scene has many
  /// obstacle parts: a link body and the obstacle part its box is nearest, found by a descent of
  /// the parts' box tree. False without obstacle parts.
  bool firstPair(const std::vector<Pose>& linkPoses, std::size_t& body, std::size_t& part) const;
  bool separatedAbove(const std::vector<Pose>& linkPoses, double margin) const;
  /// isValid's answer for the links at \p linkPoses (a state within bounds).
  bool validAt(const std::vector<Pose>& linkPoses) const;
  /// The smallest distance over the checked pairs (the link pairs left out when \p obstaclesOnly).
  double distanceUpTo(const std::vector<Pose>& linkPoses, double cap, bool obstaclesOnly = false) const;

  const ArmStateSpace* space_;
  double safetyMargin_;
  double scale_;
  std::vector<std::size_t> linkOfBody_;
  std::vector<Vec3> ballCentres_;  ///< link frame, per link body
  std::vector<double> ballRadii_;
  std::vector<Eigen::AlignedBox3d> linkBoxes_;  ///< link frame, per link body
  std::vector<std::vector<Vec3>> linkComponentPoints_;  ///< link frame, per link body: vertexPerComponent
  std::vector<std::pair<std::size_t, std::size_t>> selfPairs_;  ///< link bodies, enabled pairs
  std::vector<std::size_t> selfPairIndex_;  ///< link bodies a x b -> index into selfPairs_
  std::vector<Vec3> obstacleCentres_, obstacleHalves_;  ///< world frame, per obstacle part
  std::vector<std::vector<Vec3>> obstacleComponentPoints_;  ///< world frame, per obstacle part: vertexPerComponent
  std::vector<std::size_t> solidBodies_;  ///< link bodies whose link has solids (ArmLink::solids)
  /// A node of the obstacle parts' box tree: its box (centre, half extents, world frame), and
  /// either two children or, for a leaf, parts obstacleOrder_[first, first + count).
  struct ObstacleNode {
    Vec3 centre, half;
    std::uint32_t first = 0, count = 0;
    std::int32_t left = -1, right = -1;
  };
  std::vector<ObstacleNode> obstacleTree_;  ///< root first; empty without obstacles
  std::vector<std::uint32_t> obstacleOrder_;  ///< obstacle part indices, leaf by leaf
  /// The same tree over the scene's solids' boxes (ArmScene::solids): a cage of 146 bars made
  /// every free state test each bar's box for each link.
  std::vector<ObstacleNode> solidTree_;
  std::vector<std::uint32_t> solidOrder_;
  /// Builds \p tree over boxes (\p centres, \p halves) order[first, first + count): median
  /// splits, a few boxes per leaf. Returns the node's index.
  static std::int32_t buildBoxTree(const std::vector<Vec3>& centres, const std::vector<Vec3>& halves,
                                   std::vector<std::uint32_t>& order, std::vector<ObstacleNode>& tree,
                                   std::uint32_t first, std::uint32_t count);
  mutable QueryCounters counters_;
};

}  // namespace adsd::planner
