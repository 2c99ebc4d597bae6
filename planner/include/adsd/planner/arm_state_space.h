#pragma once
/// \file
/// \brief The OMPL state space of an arm's joint vector.

#include <memory>

#include <ompl/base/spaces/SO2StateSpace.h>
#include <ompl/base/StateSpace.h>

#include "adsd/planner/arm_model.h"

namespace adsd::planner {

/// \brief One subspace per joint-vector coordinate, in the model's joint order: an SO2StateSpace
/// for a continuous joint (it wraps at +-pi, and OMPL interpolates it along the shorter arc) and a
/// one-dimensional RealVectorStateSpace bounded by the limits for a revolute or prismatic joint.
/// Subspaces are named after their joints, each with weight 1, so distance() is the sum of the
/// joints' absolute changes (radians and metres added as they are). Uses only API present in both
/// OMPL 1.5 and OMPL 2.0.
///
/// Interpolation is linear in every coordinate (for a continuous joint, in the wrapped difference),
/// which is what ArmMotionBound assumes.
class ArmStateSpace : public ompl::base::CompoundStateSpace {
 public:
  /// \brief Throws adsd::InputError when the model has no movable joint.
  explicit ArmStateSpace(const ArmModel& model);

  /// \brief Coordinate \p i of the state's joint vector.
  double coordinate(const ompl::base::State* state, std::size_t i) const;
  /// \brief Writes the state's joint vector into \p q (dof() values).
  void toJoints(const ompl::base::State* state, double* q) const;
  /// \brief Sets the state from the joint vector \p q (a continuous joint's angle is wrapped
  /// into [-pi, pi)).
  void fromJoints(const double* q, ompl::base::State* state) const;
  /// \brief The change of every coordinate from \p from to \p to that interpolation follows: the
  /// difference, for a continuous joint the shorter way round (in [-pi, pi]).
  void jointSteps(const ompl::base::State* from, const ompl::base::State* to, double* dq) const;

  std::size_t dof() const { return continuous_.size(); }

  /// \brief Registers the default projection that OMPL's grid-based planners (KPIECE, BKPIECE,
  /// LBKPIECE, SBL, STRIDE, PDST) need: the first kProjectedJoints coordinates, the joints nearest
  /// the base, which move the most of the arm (MoveIt's default for an arm group too), each in
  /// cells of 1/20 of its range.
  void registerProjections() override;
  static constexpr std::size_t kProjectedJoints = 2;

 private:
  std::vector<bool> continuous_;
};

}  // namespace adsd::planner
