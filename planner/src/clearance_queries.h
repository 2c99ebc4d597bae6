#pragma once
// What the checkers built on adsd::distance share (MeshValidityChecker for rigid bodies,
// ArmValidityChecker for arms): the calling thread's scratch, and the rule for clearance options.

#include <cmath>

#include "adsd/distance.h"
#include "adsd/error.h"

namespace adsd::planner::detail {

/// The scratch of the calling thread: a thread runs one query at a time and a scratch is only
/// working memory (distance.h), so one per thread serves every checker, rigid or arm.
inline DistanceScratch& threadScratch() {
  thread_local DistanceScratch scratch;
  return scratch;
}

/// Clearance is exact, within a tolerance, or capped; the threshold mode answers validity only.
/// Throws adsd::InputError for the threshold mode or for values out of range.
inline void requireClearanceOptions(const DistanceOptions& o) {
  switch (o.mode) {
    case QueryMode::exact:
      return;
    case QueryMode::tolerance:
      if (!(o.absTolerance >= 0.0) || !(o.relTolerance >= 0.0) || !std::isfinite(o.absTolerance) ||
          !std::isfinite(o.relTolerance)) {
        throw InputError("clearance options: tolerances must be finite and >= 0");
      }
      return;
    case QueryMode::cap:
      if (!(o.cap > 0.0)) throw InputError("clearance options: the cap must be > 0");
      return;
    case QueryMode::threshold:
      break;
  }
  throw InputError("clearance options: the threshold mode answers validity, not clearance; use exact, tolerance or cap");
}

}  // namespace adsd::planner::detail
