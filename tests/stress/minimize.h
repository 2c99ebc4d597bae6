#pragma once
/// \file
/// \brief Shrinking a failing case to the few triangles that still fail, so that it can be pinned
/// as a regression with exact numbers that fit on a screen.

#include <string>

#include "adsd/distance.h"
#include "stress_case.h"

namespace adsd::stress {

/// \brief Removes triangles of A and B (halves, then quarters, ... then single triangles; unused
/// vertices dropped) as long as checkCase() still reports a failure labelled \p check. Poses are
/// kept. Returns the smallest such case found within \p maxChecks calls of checkCase().
StressCase minimizeFailure(const StressCase& failing, const std::string& check, DistanceScratch& scratch,
                           int maxChecks = 3000);

}  // namespace adsd::stress
