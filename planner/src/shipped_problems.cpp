#include "adsd/planner/shipped_problems.h"

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <system_error>

#include "adsd/error.h"

#ifndef ADSD_INSTALLED_DATA_DIR
#error "ADSD_INSTALLED_DATA_DIR must name the data directory relative to the prefix (planner/CMakeLists.txt)"
#endif

namespace adsd::planner {

namespace fs = std::filesystem;

namespace {

/// How many directories above the program's own to look for the data directory: an installed
/// program sits in PREFIX/bin (one up), the build tree's programs in BUILD/planner/app and
/// BUILD/tests/AREA (two up). A bounded walk never wanders into an unrelated tree.
constexpr int kLevelsAboveProgram = 3;

/// The data directory found from the running program, if any (see shipped_problems.h).
std::optional<fs::path> dataDirectory() {
  std::error_code ec;
  const fs::path program = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return std::nullopt;
  fs::path dir = program.parent_path();
  for (int level = 0; level < kLevelsAboveProgram && !dir.empty(); ++level, dir = dir.parent_path()) {
    const fs::path candidate = dir / ADSD_INSTALLED_DATA_DIR;
    if (fs::is_regular_file(candidate / "problems" / "office.cfg", ec)) return candidate;
    if (dir == dir.root_path()) break;
  }
  return std::nullopt;
}

}  // namespace

std::string shippedProblemsDirectory() {
  if (const char* dir = std::getenv("ADSD_PROBLEMS_DIR"); dir != nullptr && *dir != '\0') return dir;
  if (const auto data = dataDirectory()) return (*data / "problems").string();
  throw InputError(std::string("the shipped problems were not found: no ") + ADSD_INSTALLED_DATA_DIR +
                   "/problems beside this program's prefix; set ADSD_PROBLEMS_DIR to their directory");
}

std::string defaultProblemFile() { return shippedProblemsDirectory() + "/office.cfg"; }

std::string benchmarkPlotScript() {
  if (const auto data = dataDirectory()) return (*data / "plot_benchmark.py").string();
  return "";
}

}  // namespace adsd::planner
