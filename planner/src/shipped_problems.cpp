#include "adsd/planner/shipped_problems.h"

#include <cstdlib>

#ifndef ADSD_PROBLEMS_BUILD_DIR
#error "ADSD_PROBLEMS_BUILD_DIR must name the build tree's problem directory (planner/CMakeLists.txt)"
#endif

namespace adsd::planner {

std::string shippedProblemsDirectory() {
  if (const char* dir = std::getenv("ADSD_PROBLEMS_DIR"); dir != nullptr && *dir != '\0') return dir;
  return ADSD_PROBLEMS_BUILD_DIR;
}

std::string defaultProblemFile() { return shippedProblemsDirectory() + "/office.cfg"; }

}  // namespace adsd::planner
