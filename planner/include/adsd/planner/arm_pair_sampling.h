#pragma once
/// \file
/// \brief The sampling pass of MoveIt's setup assistant: link pairs found in contact in every
/// random state, or in none, are disabled (and may be written to an SRDF with writeSrdf()).

#include <cstddef>
#include <cstdint>
#include <vector>

#include "adsd/planner/arm_collision_pairs.h"

namespace adsd::planner {

/// \brief What a sampling pass does with the pairs it never saw in contact: MoveIt's setup
/// assistant disables them ("Never"), which is a guess (see disablePairsBySampling); `keep` counts
/// them and leaves them checked.
enum class NeverInContact { disable, keep };

/// \brief What a sampling pass found.
struct PairSamplingResult {
  std::size_t states = 0;          ///< random joint vectors drawn (uniform within the limits)
  std::size_t pairsTested = 0;     ///< enabled pairs before the pass
  std::size_t alwaysInContact = 0; ///< disabled with reason "Always"
  std::size_t neverInContact = 0;  ///< not in contact in any state: disabled with reason "Never", or kept
};

/// \brief Draws \p states joint vectors uniformly within the limits (continuous joints in
/// [-pi, pi]) from \p seed, tests every enabled pair of \p pairs for contact (our threshold query
/// at distance 0), and disables the pairs in contact in every state ("Always": they touch by
/// design) and, unless \p never is NeverInContact::keep, those in none ("Never").
///
/// "Never" is a heuristic, as in MoveIt: a pair not seen in contact in the sample may still touch
/// in some state, which the checker then misses. Use enough states (MoveIt's default is 10 000),
/// and do not use it where self-contact must be proven absent. Throws adsd::InputError when
/// \p states is 0.
PairSamplingResult disablePairsBySampling(const ArmModel& model, ArmCollisionPairs& pairs, std::size_t states,
                                          std::uint64_t seed = 1, NeverInContact never = NeverInContact::disable);

/// \brief The default joint vector, as MoveIt's setup assistant takes it (the robot's default
/// state): every joint at 0, or at the midpoint of its limits when 0 lies outside them
/// (defaultPosition).
std::vector<double> defaultJointVector(const ArmModel& model);

/// \brief Disables the enabled pairs of \p pairs in contact at joint vector \p q (our threshold
/// query at distance 0), with reason "Default" as MoveIt's setup assistant does for the default
/// pose: links that overlap where the robot is drawn. Returns how many. A guess of the same kind
/// as "Never": such a pair may still collide elsewhere, so it is applied only when asked for.
std::size_t disablePairsInContactAt(const ArmModel& model, ArmCollisionPairs& pairs, const std::vector<double>& q);

}  // namespace adsd::planner
