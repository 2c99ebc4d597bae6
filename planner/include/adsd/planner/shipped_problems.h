#pragma once
/// \file
/// \brief Where the shipped problems are: the build writes them (problems/README.md).

#include <string>

namespace adsd::planner {

/// \brief The directory holding the shipped .cfg files and their generated meshes: the
/// environment variable ADSD_PROBLEMS_DIR when set, otherwise the build tree's problem_files/.
std::string shippedProblemsDirectory();

/// \brief The default problem of `adsd plan` (office.cfg in shippedProblemsDirectory()).
std::string defaultProblemFile();

}  // namespace adsd::planner
