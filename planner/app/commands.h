#pragma once
/// \file
/// \brief The subcommands of the `adsd` program, one file each (<name>_command.cpp).
///
/// Each takes the arguments after its name, prints its own errors (one line on stderr) and returns
/// the exit status: 0 done, 2 bad input or usage; other values as the command documents.

#include <exception>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include "adsd/cli/command_line.h"
#include "adsd/error.h"

namespace adsd::app {

/// \brief Runs a command's body and turns what it throws into the program's one-line errors and
/// exit statuses, alike for every command: a bad command line as cli::reportUsageError (2), bad
/// input (adsd::InputError, which names the file, line and field) as "PROGRAM: error: ..." (2),
/// anything else as "PROGRAM: internal error: ..." (1).
inline int reportingErrors(const char* program, const std::function<int()>& body) {
  try {
    return body();
  } catch (const cli::UsageError& e) {
    return cli::reportUsageError(program, e);
  } catch (const InputError& e) {
    std::cerr << program << ": error: " << e.what() << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << program << ": internal error: " << e.what() << '\n';
    return 1;
  }
}

/// \brief `adsd distance MESH_A MESH_B [--poses FILE|-] [--csv] [query mode]` (distance_command.cpp).
int distanceCommand(const std::vector<std::string>& args);

/// \brief `adsd plan [PROBLEM.cfg] [options]` (plan_command.cpp, the planner's).
int planCommand(const std::vector<std::string>& args);

/// \brief `adsd benchmark [PROBLEM.cfg] [options]` (benchmark_command.cpp): OMPL's benchmark for each
/// checker and motion validator, its log, SQLite database and plots.
int benchmarkCommand(const std::vector<std::string>& args);

/// \brief `adsd srdf ROBOT.urdf --out ROBOT.srdf [options]` (srdf_command.cpp): the self-collision pairs
/// to leave unchecked, found as MoveIt's setup assistant finds them, written as an SRDF.
int srdfCommand(const std::vector<std::string>& args);

/// \brief `adsd view [PROBLEM.cfg | ARM.cfg] [--path FILE] --html OUT.html` (view_command.cpp): the browser viewer.
int viewCommand(const std::vector<std::string>& args);

}  // namespace adsd::app
