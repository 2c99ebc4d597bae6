// `adsd view [PROBLEM.cfg] [--path FILE] --html OUT.html`
//
// Writes the browser viewer (viewer_html.h) for a problem: its start and goal, or a path read from
// a file as `adsd plan --path` writes it (one state a line: SE(2) x y yaw; SE(3) x y z qx qy qz qw),
// which is also what OMPL's PathGeometric::printAsMatrix prints. Exit status: 0 written, 2 bad input.
#include <cmath>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <ompl/base/ScopedState.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/base/spaces/SE3StateSpace.h>
#include <ompl/util/Console.h>

#include "adsd/cli/command_line.h"
#include "adsd/error.h"
#include "adsd/planner/planning_problem.h"
#include "adsd/planner/problem_file.h"
#include "adsd/planner/shipped_problems.h"
#include "commands.h"
#include "viewer_html.h"

namespace adsd::app {

namespace {

namespace ob = ompl::base;
using namespace adsd::planner;

/// A path file's quaternion may be off unit length by this much (dimensionless) and is then
/// normalized: printAsMatrix prints six significant digits, which leaves the norm off by up to
/// about 1e-6; anything farther is not a rotation.
constexpr double kQuaternionNormSlack = 1e-4;

constexpr const char* kSynopsis = "adsd view [PROBLEM.cfg] [--path FILE] --html OUT.html";
constexpr const char* kDescription =
    "Writes one self-contained HTML page (it opens offline) showing the problem's meshes, start and\n"
    "goal, and with --path the robot moving along the path: the closest points to the environment\n"
    "at each state and the clearance along the path, its minimum marked. Without PROBLEM.cfg, the\n"
    "default problem of `adsd plan`.";
constexpr const char* kDetails =
    "Exit status: 0 written, 2 bad input or usage (one line naming the file and line, or the option).\n";

struct ViewArguments {
  std::string problem;
  std::optional<std::string> pathFile;
  std::string html;
};

/// Returns nullopt after printing the help.
std::optional<ViewArguments> parseArguments(const std::vector<std::string>& args) {
  cli::CommandLine line("adsd view", kSynopsis, kDescription, kDetails);
  line.options()
      ("path", cli::value("FILE"), "a path: one state a line, as `adsd plan --path` writes it")
      ("html", cli::value("OUT.html"), "the page to write (required)");
  line.positional("problem");
  const std::optional<cli::Arguments> given = line.parse(args);
  if (!given) return std::nullopt;
  ViewArguments a;
  const std::vector<std::string> problems = given->texts("problem");
  if (problems.size() > 1) {
    throw cli::UsageError("more than one problem file ('" + problems[0] + "', '" + problems[1] + "')");
  }
  a.pathFile = given->text("path");
  const std::optional<std::string> html = given->text("html");
  if (!html) throw cli::UsageError("--html OUT.html is required");
  a.html = *html;
  // Last: finding the shipped problems may fail, and the options' errors come first.
  a.problem = problems.empty() ? defaultProblemFile() : problems.front();
  return a;
}

/// Reads a path file into states of \p si's space; errors name the file and line.
ompl::geometric::PathGeometric readPathFile(const std::string& file, const ob::SpaceInformationPtr& si,
                                            RigidBodySpace space) {
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) throw InputError(file + ": no such path file");
  if (!std::filesystem::is_regular_file(file, ec)) throw InputError(file + ": is a directory or a device, not a path file");
  std::ifstream in(file);
  if (!in) throw InputError(file + ": cannot be opened for reading");
  const std::size_t expected = space == RigidBodySpace::se2 ? 3 : 7;
  const char* layout = space == RigidBodySpace::se2 ? "x y yaw" : "x y z qx qy qz qw";
  ompl::geometric::PathGeometric path(si);
  ob::ScopedState<> state(si->getStateSpace());
  std::string line;
  for (std::size_t number = 1; std::getline(in, line); ++number) {
    const std::string where = file + ":" + std::to_string(number) + ": ";
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    std::istringstream words(line);
    std::vector<double> values;
    std::string word;
    while (words >> word) {
      // The same reading in every locale (cli/numbers.h): a path file's numbers are C-locale text.
      const std::optional<double> v = cli::toReal(word);
      if (!v) throw InputError(where + "'" + word + "' is not a finite number");
      values.push_back(*v);
    }
    if (values.size() != expected) {
      throw InputError(where + "expected " + std::to_string(expected) + " numbers (" + layout + ") for this " +
                       (space == RigidBodySpace::se2 ? "SE(2)" : "SE(3)") + " problem, got " +
                       std::to_string(values.size()));
    }
    if (space == RigidBodySpace::se2) {
      auto* s = state->as<ob::SE2StateSpace::StateType>();
      s->setXY(values[0], values[1]);
      s->setYaw(values[2]);
    } else {
      const double norm = std::sqrt(values[3] * values[3] + values[4] * values[4] + values[5] * values[5] +
                                    values[6] * values[6]);
      if (!(std::abs(norm - 1.0) <= kQuaternionNormSlack)) {
        throw InputError(where + "the quaternion (qx qy qz qw) has norm " + std::to_string(norm) + ", not 1");
      }
      auto* s = state->as<ob::SE3StateSpace::StateType>();
      s->setXYZ(values[0], values[1], values[2]);
      s->rotation().x = values[3] / norm;
      s->rotation().y = values[4] / norm;
      s->rotation().z = values[5] / norm;
      s->rotation().w = values[6] / norm;
    }
    path.append(state.get());
  }
  if (path.getStateCount() == 0) throw InputError(file + ": no states (only comments or blank lines)");
  return path;
}

int view(const std::vector<std::string>& args) {
  const std::optional<ViewArguments> a = parseArguments(args);
  if (!a) return 0;
  const ProblemFile file = readProblemFile(a->problem);
  for (const std::string& w : file.warnings) std::cerr << "adsd view: warning: " << w << '\n';
  PlanningProblem problem(file, CheckingOptions{});
  for (const std::string& w : problem.warnings()) std::cerr << "adsd view: warning: " << w << '\n';

  // As `adsd plan` does before solving: the space's validity-checking resolution, which the
  // page's states are interpolated to, is set up here.
  problem.setup().setup();
  std::optional<ompl::geometric::PathGeometric> path;
  if (a->pathFile) path = readPathFile(*a->pathFile, problem.spaceInformation(), file.space);
  const ViewerSummary s = writeViewerHtml(a->html, file, problem, path ? &*path : nullptr,
                                          a->pathFile ? "path " + *a->pathFile : std::string("start and goal, no path"));
  std::printf("problem     %s (%s, %s)\n", file.name.c_str(), file.space == RigidBodySpace::se2 ? "SE(2)" : "SE(3)",
              a->problem.c_str());
  std::printf("clearance   min %.6g (over %zu states%s)\n", s.minClearance, s.states,
              path ? " at the validity-checking resolution" : ": the start and the goal");
  std::printf("viewer      %s (%.0f kB)\n", a->html.c_str(), static_cast<double>(s.bytes) / 1000.0);
  return 0;
}

}  // namespace

/// \brief Entry point of `adsd view`; \p args are the arguments after "view".
int viewCommand(const std::vector<std::string>& args) {
  ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
  return reportingErrors("adsd view", [&] { return view(args); });
}

}  // namespace adsd::app
