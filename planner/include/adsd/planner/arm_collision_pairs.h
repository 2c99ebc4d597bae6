#pragma once
/// \file
/// \brief Which pairs of an arm's links are checked against each other (self-collision), and the
/// SRDF `<disable_collisions>` entries that switch pairs off.

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "adsd/planner/arm_model.h"

namespace adsd::planner {

/// \brief A symmetric matrix over an arm's links: which link pairs a checker tests against each
/// other. Only links with collision geometry can be in an enabled pair.
class ArmCollisionPairs {
 public:
  /// \brief Every pair of distinct links that both have collision geometry, except the pairs
  /// disabledByAdjacency() finds: links that touch by design at a joint, or cannot move relative
  /// to each other.
  explicit ArmCollisionPairs(const ArmModel& model);

  bool enabled(std::size_t a, std::size_t b) const { return enabled_[a * links_ + b]; }
  /// \brief Switches the pair off (both orders); \p reason is kept for writeSrdf().
  void disable(std::size_t a, std::size_t b, const std::string& reason);
  /// \brief The enabled pairs, a < b, in increasing order.
  std::vector<std::pair<std::size_t, std::size_t>> enabledPairs() const;
  /// \brief The disabled pairs between links with geometry, a < b, with their reasons.
  struct Disabled {
    std::size_t a, b;
    std::string reason;
  };
  const std::vector<Disabled>& disabled() const { return disabled_; }

 private:
  std::size_t links_;
  std::vector<bool> enabled_;
  std::vector<Disabled> disabled_;
};

/// \brief Pairs of links with collision geometry never checked because the kinematic tree joins
/// them (reason "Adjacent"):
///  - a parent link and its child link, through any joint, and, as MoveIt's setup assistant has
///    it, links whose only link between them has no collision geometry (repeatedly: a chain of
///    such links counts as one);
///  - links joined only through fixed joints (a rigid group: their distance never changes).
/// A link fixed to another is not adjacent to that one's parent: a gripper fixed to a wrist can
/// fold into the forearm the wrist turns on, and that pair stays checked.
std::vector<std::pair<std::size_t, std::size_t>> adjacentLinkPairs(const ArmModel& model);

/// \brief Disables the pairs an SRDF file leaves unchecked, as MoveIt's allowed collision matrix
/// does: every `<disable_collisions link1="" link2="" reason=""/>` pair, and every pair of a
/// `<disable_default_collisions link=""/>` link but those `<enable_collisions link1="" link2=""/>`
/// names (other elements are ignored). Throws adsd::InputError naming the file
/// and line when it is not XML, has no `<robot>` element, is a URDF (its `<robot>` has `<link>`
/// elements), or names a link the model lacks. Returns its warnings, one line each: a `<robot
/// name="">` other than the model's (MoveIt logs that as an error and reads on).
std::vector<std::string> disablePairsFromSrdf(const ArmModel& model, const std::string& srdfPath,
                                              ArmCollisionPairs& pairs);

/// \brief Writes the disabled pairs as an SRDF file (a `<robot name="">` with one
/// `<disable_collisions>` per pair), which disablePairsFromSrdf() and MoveIt read, through a
/// temporary name renamed into place, so that a failure leaves no half-written file. Throws
/// adsd::InputError when the file cannot be written.
void writeSrdf(const ArmModel& model, const ArmCollisionPairs& pairs, const std::string& srdfPath);

}  // namespace adsd::planner
