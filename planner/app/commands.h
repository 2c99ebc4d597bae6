#pragma once
/// \file
/// \brief The subcommands of the `adsd` program, one file each (<name>_command.cpp).
///
/// Each takes the arguments after its name, prints its own errors (one line on stderr) and returns
/// the exit status: 0 done, 2 bad input or usage; other values as the command documents.

#include <string>
#include <vector>

namespace adsd::app {

/// \brief `adsd distance MESH_A MESH_B [--poses FILE|-] [--csv] [query mode]` (distance_command.cpp).
int distanceCommand(const std::vector<std::string>& args);

/// \brief `adsd plan [PROBLEM.cfg] [options]` (plan_command.cpp, the planner's).
int planCommand(const std::vector<std::string>& args);

/// \brief `adsd benchmark [PROBLEM.cfg] [options]` (benchmark_command.cpp): OMPL's benchmark for each
/// checker and motion validator, its log, SQLite database and plots.
int benchmarkCommand(const std::vector<std::string>& args);

/// \brief `adsd view [PROBLEM.cfg] [--path FILE] --html OUT.html` (view_command.cpp): the browser viewer.
int viewCommand(const std::vector<std::string>& args);

}  // namespace adsd::app
