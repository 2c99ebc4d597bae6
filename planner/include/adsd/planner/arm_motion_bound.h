#pragma once
/// \file
/// \brief How far any point of each link of an arm can move for a step of the joint vector: the
/// bound the certified joint-space motion check stands on (issue 17).

#include <cstddef>
#include <vector>

#include "adsd/planner/arm_model.h"

namespace adsd::planner {

/// \brief Per link L and joint-vector coordinate i, a speed bound K(L, i) >= 0 (metres per radian
/// for a turning joint, 1 for a prismatic one) valid in every configuration, so that along the
/// straight joint-space motion q(t) = q0 + t dq, t in [0, 1], every point of link L travels a path
/// no longer than
///   B_L(dq) = sum_i K(L, i) |dq_i|.
///
/// Proof sketch. A point p of L moves with velocity sum_i J_i(q) dq_i, where J_i is the velocity
/// that joint i alone gives p: zero unless L lies beyond joint i; the joint's unit axis for a
/// prismatic joint (|J_i| = 1); for a revolute or continuous joint, axis x (p - o), with o on the
/// axis, so |J_i| <= distance of p from the axis <= |p - o|. Take o = the joint's origin, which is
/// the origin of its child link C's frame. Between C and L the chain passes links M, each framed
/// at most |t_M| (its joint's origin offset) from its parent's frame, plus the stroke
/// max(|lower|, |upper|) when M's joint is prismatic; and every point of L is within
/// r_L = max |vertex| of L's frame origin. So |p - o| <= sum_M (|t_M| + stroke_M) + r_L, for every
/// configuration of the joints in between: that is K(L, i). For L = C itself the exact distance
/// from the axis is used (max over C's vertices of |p - (p.a)a|, a fixed set as C turns about a).
/// Integrating the speed over t bounds the path, hence the displacement, by B_L(dq) (Schwarzer,
/// Saha and Latombe 2002, sec. 3, the bound for a chain of links).
///
/// Two links: their distance is unchanged by a rigid motion of both, so in the frame of their
/// deepest common ancestor the joints above it do nothing, and the distance changes by at most
///   B_{L1,L2}(dq) = sum over joints i beyond exactly one of the two links' common chain of
///                   (K(L1, i) + K(L2, i)) |dq_i|
/// (pairDisplacement): a wrist pair near contact then costs only the wrist joints' motion.
///
/// A mimic joint (ArmJoint::mimicCoordinate) moves |multiplier| times as far as the coordinate it
/// follows, so it adds its own term, K(L, j) |multiplier| |dq_i|, to coordinate i's: for B_L
/// summed into K(L, i), and for two links counted where exactly one of them lies beyond it (a
/// gripper's two fingers, driven by one coordinate, move relative to each other by both joints).
/// A prismatic mimic joint's stroke is its leader's range scaled and offset.
class ArmMotionBound {
 public:
  explicit ArmMotionBound(const ArmModel& model);

  /// \brief K(L, i): speed bound of link \p link per unit change of coordinate \p i (the mimic
  /// joints that follow it included).
  double coefficient(std::size_t link, std::size_t i) const { return coefficients_[link * dof_ + i]; }
  /// \brief B_L(dq) for every link into \p out (model.links.size() values; 0 for links without
  /// geometry and for links no moved joint carries).
  void linkDisplacements(const double* dq, double* out) const;
  /// \brief B_{L1,L2}(dq): the most the distance between links \p a and \p b can change.
  double pairDisplacement(std::size_t a, std::size_t b, const double* dq) const;

 private:
  /// A joint that moves: one of the joint vector (rate 1), or a mimic joint (rate |multiplier|).
  struct Mover {
    std::size_t joint;       ///< index into ArmModel::joints
    std::size_t coordinate;  ///< the joint-vector coordinate that drives it
    double rate;             ///< its position's change per unit change of that coordinate
  };
  std::size_t links_, dof_;
  std::vector<Mover> movers_;
  std::vector<double> k_;  ///< links_ x movers_, row-major: K(L, joint) times the mover's rate
  std::vector<char> beyond_;  ///< links_ x movers_: link lies beyond the mover's joint
  std::vector<double> coefficients_;  ///< links_ x dof_: K(L, i), every mover of coordinate i summed
};

}  // namespace adsd::planner
