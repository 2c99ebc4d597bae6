#pragma once
/// \file
/// \brief Where the shipped data are: the problem files (problems/README.md) and the benchmark
/// plotting script, in an install or in a build tree.
///
/// The data directory is `share/adsd` under the prefix the running program is installed in
/// (`PREFIX/bin/adsd` reads `PREFIX/share/adsd`); a build tree has the same layout
/// (`BUILD/share/adsd`, beside `BUILD/problem_files`). It is found from the program's own location,
/// so neither holds a path of the machine that built it. A program elsewhere (one that links the
/// installed adsd::planner) names the directory itself: the package config's `adsd_PROBLEMS_DIR`,
/// or the environment variable ADSD_PROBLEMS_DIR.

#include <string>

namespace adsd::planner {

/// \brief The directory holding the shipped .cfg files and their generated meshes: the
/// environment variable ADSD_PROBLEMS_DIR when set, otherwise `share/adsd/problems` found from the
/// running program (see the file's note). Throws adsd::InputError saying how to name it when
/// neither exists.
std::string shippedProblemsDirectory();

/// \brief The default problem of `adsd plan` (office.cfg in shippedProblemsDirectory()).
std::string defaultProblemFile();

/// \brief bench/planning/plot_benchmark.py as shipped in the data directory, or an empty string
/// when the running program has no data directory.
std::string benchmarkPlotScript();

}  // namespace adsd::planner
