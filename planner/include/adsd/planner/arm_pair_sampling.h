#pragma once
/// \file
/// \brief The sampling pass of MoveIt's setup assistant: link pairs found in contact in every
/// random state, or in none, are disabled (and may be written to an SRDF with writeSrdf()).

#include <cstddef>
#include <cstdint>

#include "adsd/planner/arm_collision_pairs.h"

namespace adsd::planner {

/// \brief What a sampling pass found.
struct PairSamplingResult {
  std::size_t states = 0;          ///< random joint vectors drawn (uniform within the limits)
  std::size_t pairsTested = 0;     ///< enabled pairs before the pass
  std::size_t alwaysInContact = 0; ///< disabled with reason "Always"
  std::size_t neverInContact = 0;  ///< disabled with reason "Never"
};

/// \brief Draws \p states joint vectors uniformly within the limits (continuous joints in
/// [-pi, pi]) from \p seed, tests every enabled pair of \p pairs for contact (our threshold query
/// at distance 0), and disables the pairs in contact in every state ("Always": they touch by
/// design) and in none ("Never").
///
/// "Never" is a heuristic, as in MoveIt: a pair not seen in contact in the sample may still touch
/// in some state, which the checker then misses. Use enough states (MoveIt's default is 10 000),
/// and do not use it where self-contact must be proven absent. Throws adsd::InputError when
/// \p states is 0.
PairSamplingResult disablePairsBySampling(const ArmModel& model, ArmCollisionPairs& pairs, std::size_t states,
                                          std::uint64_t seed = 1);

}  // namespace adsd::planner
