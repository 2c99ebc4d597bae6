// `adsd view [PROBLEM.cfg | ARM.cfg] [--path FILE] --html OUT.html`
//
// Writes the browser viewer (viewer_html.h) for a problem: its start and goal, or a path read from
// a file as `adsd plan --path` writes it (one state a line: SE(2) x y yaw; SE(3) x y z qx qy qz qw),
// which is also what OMPL's PathGeometric::printAsMatrix prints. An arm problem's page
// (arm_viewer_html.h) takes an arm's path file: a "# joints: ..." header and one line of joint
// values per state. Exit status: 0 written, 2 bad input.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <ompl/base/ScopedState.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/base/spaces/SE3StateSpace.h>
#include <ompl/util/Console.h>

#include "adsd/cli/command_line.h"
#include "adsd/cli/numbers.h"
#include "adsd/error.h"
#include "adsd/planner/arm_planning_problem.h"
#include "adsd/planner/arm_state_space.h"
#include "adsd/planner/path_report.h"
#include "adsd/planner/planning_problem.h"
#include "adsd/planner/problem_file.h"
#include "adsd/planner/shipped_problems.h"
#include "adsd/planner/state_pose.h"
#include "arm_viewer_html.h"
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

constexpr const char* kSynopsis = "adsd view [PROBLEM.cfg | ARM.cfg] [--path FILE] --html OUT.html";
constexpr const char* kDescription =
    "Writes one self-contained HTML page (it opens offline) showing the problem's meshes, start and\n"
    "goal, and with --path the robot moving along the path: the closest points to the environment\n"
    "at each state and the clearance along the path, its minimum marked. An arm problem (ARM.cfg,\n"
    "docs/problem-files.md) shows its links posed at each state, and the closest points of link and\n"
    "obstacle or of two links. Without a problem file, the default problem of `adsd plan`.";
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
      ("path", cli::value("FILE"),
       "a path: one state a line, as `adsd plan --path` writes it (for an arm, its joint values)")
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
  const std::optional<std::string> html = given->outputFile("html");
  if (!html) throw cli::UsageError("--html OUT.html is required");
  a.html = *html;
  // Last: finding the shipped problems may fail, and the options' errors come first.
  a.problem = problems.empty() ? defaultProblemFile() : problems.front();
  std::vector<std::pair<std::string, std::string>> inputs = {{"the problem file", a.problem}};
  if (a.pathFile) inputs.emplace_back("the --path file", *a.pathFile);
  cli::requireDistinctFile("--html", a.html, inputs);
  return a;
}

/// The longest line of a path file read: an arm's joint values and a comment fit many times over.
/// A line of millions of numbers was kept whole before its count was checked (a 200 MB line took
/// 2.3 GB).
constexpr std::size_t kMaxPathLineBytes = std::size_t{1} << 20;
/// The most states a path file may hold: each is a clearance query and about 240 bytes of the
/// page, and 300 000 took 42 s and a 73 MB page (an adversarial review); a planned path, even
/// interpolated at the validity-checking resolution, has far fewer.
constexpr std::size_t kMaxPathStates = 100000;

/// Calls \p onComment for each comment line of a path file (its text after '#') and \p onState
/// for each state line (its numbers), each with "FILE:LINE: " to put before an error; blank lines
/// are skipped. Throws when the file cannot be read, a word is not a finite number, or there is no
/// state line.
void readPathLines(const std::string& file,
                   const std::function<void(const std::string& comment, const std::string& where)>& onComment,
                   const std::function<void(const std::vector<double>& values, const std::string& where)>& onState) {
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) throw InputError(file + ": no such path file");
  if (!std::filesystem::is_regular_file(file, ec)) throw InputError(file + ": is a directory or a device, not a path file");
  std::ifstream in(file);
  if (!in) throw InputError(file + ": cannot be opened for reading");
  std::size_t states = 0;
  const auto readLine = [&](std::string_view text, std::size_t number) {
    const std::string where = file + ":" + std::to_string(number) + ": ";
    if (text.size() > kMaxPathLineBytes) {
      throw InputError(where + "line longer than " + std::to_string(kMaxPathLineBytes) + " bytes (not a path file?)");
    }
    std::string line(text);
    // A UTF-8 byte-order mark, which Windows editors write, is no part of the first line: left in,
    // it was quoted invisibly as part of a number ("'-6' is not a finite number").
    if (number == 1 && line.compare(0, 3, "\xEF\xBB\xBF") == 0) line.erase(0, 3);
    const std::size_t first = line.find_first_not_of(" \t");
    if (first == std::string::npos) return;
    if (line[first] == '#') {
      onComment(line.substr(first + 1), where);
      return;
    }
    // A comment may follow a state's numbers on its line.
    std::istringstream words(line.substr(0, line.find('#')));
    std::vector<double> values;
    std::string word;
    while (words >> word) {
      // The same reading in every locale (cli/numbers.h): a path file's numbers are C-locale text.
      const std::optional<double> v = cli::toReal(word);
      if (!v) throw InputError(where + "'" + word + "' is not a finite number");
      values.push_back(*v);
    }
    if (states == kMaxPathStates) {
      throw InputError(where + "more than " + std::to_string(kMaxPathStates) +
                       " states (each is a clearance query and a frame of the page)");
    }
    onState(values, where);
    ++states;
  };
  // Lines end in '\n', "\r\n" or a lone '\r' (classic Mac OS text, which getline returns whole).
  std::string raw;
  for (std::size_t number = 0; std::getline(in, raw);) {
    std::string_view rest(raw);
    if (!rest.empty() && rest.back() == '\r') rest.remove_suffix(1);
    for (std::size_t cr = rest.find('\r');; cr = rest.find('\r')) {
      readLine(rest.substr(0, cr), ++number);
      if (cr == std::string_view::npos) break;
      rest.remove_prefix(cr + 1);
    }
  }
  if (states == 0) throw InputError(file + ": no states (only comments or blank lines)");
}

/// How far beyond a bound, relative to the bounds' extent or magnitude, a path file's position may
/// lie and be taken (clamped): OMPL's printAsMatrix rounds to six significant digits.
constexpr double kPathBoundsSlack = 1e-5;

/// The position bounds of \p si's rigid-body space, as "x in [a, b], y in [c, d]...".
std::string boundsText(const ob::SpaceInformation& si, RigidBodySpace space) {
  const ob::RealVectorBounds& bounds = positionBounds(si, space);
  std::ostringstream text;
  for (std::size_t i = 0; i < bounds.low.size(); ++i) {
    text << (i ? ", " : "") << "xyz"[i] << " in [" << bounds.low[i] << ", " << bounds.high[i] << "]";
  }
  return text.str();
}

/// Reads a rigid body's path file into states of \p si's space; errors name the file and line.
ompl::geometric::PathGeometric readPathFile(const std::string& file, const ob::SpaceInformationPtr& si,
                                            RigidBodySpace space) {
  const std::size_t expected = space == RigidBodySpace::se2 ? 3 : 7;
  const char* layout = space == RigidBodySpace::se2 ? "x y yaw" : "x y z qx qy qz qw";
  ompl::geometric::PathGeometric path(si);
  ob::ScopedState<> state(si->getStateSpace());
  const auto onState = [&](const std::vector<double>& values, const std::string& where) {
    if (values.size() != expected) {
      throw InputError(where + "expected " + std::to_string(expected) + " numbers (" + layout + ") for this " +
                       (space == RigidBodySpace::se2 ? "SE(2)" : "SE(3)") + " problem, got " +
                       std::to_string(values.size()));
    }
    if (space == RigidBodySpace::se2) {
      auto* s = state->as<ob::SE2StateSpace::StateType>();
      s->setXY(values[0], values[1]);
      // Other tools write yaw in [0, 2 pi) or unwrapped; OMPL's SE(2) takes it in [-pi, pi] only.
      s->setYaw(std::remainder(values[2], 2.0 * M_PI));
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
    // A state outside the problem's bounds is not one of its states (and one far outside would
    // fail later, in a distance query that cannot name this line). OMPL's printAsMatrix writes
    // six digits, which may round a state on a bound outward: within kPathBoundsSlack it is taken,
    // clamped.
    const ob::RealVectorBounds& bounds = positionBounds(*si, space);
    for (std::size_t i = 0; i < bounds.low.size(); ++i) {
      const double slack = kPathBoundsSlack * std::max({bounds.high[i] - bounds.low[i], std::abs(bounds.low[i]),
                                                        std::abs(bounds.high[i])});
      if (!(values[i] >= bounds.low[i] - slack && values[i] <= bounds.high[i] + slack)) {
        throw InputError(where + "the state lies outside the problem's bounds (" + boundsText(*si, space) + ")");
      }
    }
    si->enforceBounds(state.get());
    path.append(state.get());
  };
  readPathLines(file, [](const std::string&, const std::string&) {}, onState);
  return path;
}

/// Reads an arm's path file, as `adsd plan ARM.cfg --path` writes it (path_report.h): an optional
/// "# joints: NAME ..." line, which must name the model's movable joints in its order, and one
/// line of joint values per state, each within its joint's limits (a continuous joint's value
/// may be any angle). Errors name the file and line.
ompl::geometric::PathGeometric readArmPathFile(const std::string& file, const ArmPlanningProblem& problem) {
  const ArmModel& model = problem.model();
  const ob::SpaceInformationPtr& si = problem.spaceInformation();
  const auto& space = static_cast<const ArmStateSpace&>(*si->getStateSpace());
  std::string names;
  for (const std::size_t j : model.activeJoints) names += (names.empty() ? "" : " ") + model.joints[j].name;
  const auto onComment = [&](const std::string& comment, const std::string& where) {
    // "# joints:" as `adsd plan` writes it, and as hands write it ("#joints:", "# Joints :"): a
    // header taken for a comment gave the values in the robot's order whatever it named.
    const std::size_t start = comment.find_first_not_of(" \t");
    const std::size_t colon = comment.find(':');
    if (start == std::string::npos || colon == std::string::npos || colon < start) return;
    std::string key = comment.substr(start, colon - start);
    key.erase(key.find_last_not_of(" \t") + 1);
    std::transform(key.begin(), key.end(), key.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (key != "joints") return;
    std::istringstream words(comment.substr(colon + 1));
    std::string given, word;
    while (words >> word) given += (given.empty() ? "" : " ") + word;
    if (given != names) {
      throw InputError(where + "the path's joints (" + given + ") are not those of robot '" + model.name + "' (" +
                       names + ")");
    }
  };
  ompl::geometric::PathGeometric path(si);
  ob::ScopedState<> state(si->getStateSpace());
  const auto onState = [&](const std::vector<double>& q, const std::string& where) {
    if (q.size() != model.dof()) {
      throw InputError(where + "expected " + std::to_string(model.dof()) + " joint values (" + names +
                       ") for robot '" + model.name + "', got " + std::to_string(q.size()));
    }
    for (std::size_t i = 0; i < q.size(); ++i) {
      const ArmJoint& joint = model.joints[model.activeJoints[i]];
      if (joint.type != ArmJointType::continuous && (q[i] < joint.lower || q[i] > joint.upper)) {
        // Shortest texts: at 6 digits a value one ulp outside read as its limit.
        std::ostringstream why;
        why << where << "joint " << joint.name << " = " << cli::shortestText(q[i]) << " is outside its limits ["
            << cli::shortestText(joint.lower) << ", " << cli::shortestText(joint.upper) << "]";
        throw InputError(why.str());
      }
    }
    space.fromJoints(q.data(), state.get());
    path.append(state.get());
  };
  readPathLines(file, onComment, onState);
  return path;
}

/// A start or goal in collision is shown, with a warning, rather than refused as `adsd plan`
/// refuses it: seeing where it touches is why one looks.
CheckingOptions showingOptions() {
  CheckingOptions options;
  options.keepEndpointsInCollision = true;
  return options;
}

/// `adsd view ARM.cfg`: the arm viewer (arm_viewer_html.h).
int viewArm(const ViewArguments& a) {
  const MotionBenchMakerProblem file = readMotionBenchMakerProblem(a.problem);
  // The files the cfg names, once it is read (the cfg itself was checked with the arguments).
  std::vector<std::pair<std::string, std::string>> inputs = {
      {"the URDF file", file.robotPath}, {"the scene file", file.scenePath}, {"the request file", file.requestPath}};
  if (file.srdfPath) inputs.emplace_back("the SRDF file", *file.srdfPath);
  cli::requireDistinctFile("--html", a.html, inputs);
  ArmPlanningProblem problem(file, showingOptions());
  for (const std::string& w : problem.warnings()) std::cerr << "adsd view: warning: " << w << '\n';
  requireArmViewable(problem, a.problem);
  // As `adsd plan` does before solving: the space's validity-checking resolution.
  problem.setup().setup();
  std::optional<ompl::geometric::PathGeometric> path;
  if (a.pathFile) path = readArmPathFile(*a.pathFile, problem);
  const ViewerSummary s = writeArmViewerHtml(a.html, problem, path ? &*path : nullptr,
                                             a.pathFile ? "path " + *a.pathFile : std::string("start and goal, no path"));
  std::printf("problem     %s (arm %s, %zu joints, %s)\n", problem.name().c_str(), problem.model().name.c_str(),
              problem.model().dof(), a.problem.c_str());
  if (std::isfinite(s.minClearance)) {
    std::printf("clearance   min %.6g m (exact, over %zu states%s)\n", s.minClearance, s.states,
                path ? ": the path interpolated as `adsd plan` measures it" : ": the start and the goal");
  } else {
    std::printf("clearance   none measured: nothing for the links to collide with\n");
  }
  std::printf("viewer      %s (%.0f kB)\n", a.html.c_str(), static_cast<double>(s.bytes) / 1000.0);
  return 0;
}

int view(const std::vector<std::string>& args) {
  const std::optional<ViewArguments> a = parseArguments(args);
  if (!a) return 0;
  if (isArmProblemFile(a->problem)) return viewArm(*a);
  const ProblemFile file = readProblemFile(a->problem);
  cli::requireDistinctFile("--html", a->html, {{"the robot mesh", file.robotPath}, {"the world mesh", file.worldPath}});
  for (const std::string& w : file.warnings) std::cerr << "adsd view: warning: " << w << '\n';
  PlanningProblem problem(file, showingOptions());
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
  const std::string over = !path ? ": the start and the goal"
                            : s.coarserThanResolution
                                ? ": the motions cut coarser than the validity-checking resolution, to about " +
                                      std::to_string(kMaxMeasuredStates) + " states or the path's own"
                                : std::string(" at the validity-checking resolution");
  std::printf("clearance   min %.6g (over %zu states%s)\n", s.minClearance, s.states, over.c_str());
  std::optional<PathLeastClearance> along;
  if (path) along = leastClearanceAlong(*path, *problem.checker());  // as `adsd plan` measures it
  if (along) {
    std::printf("along       min %.6g between the states too (no state of the motions nearer than %.6g; %zu "
                "clearance queries)\n",
                along->least, along->lowerBound, along->queries);
    // The verdict `adsd plan` gives its own path, said (the exit status stays 0: the page shows
    // the path, whatever it touches): the page's clearances are those of the states, and a path
    // past a thin wall showed 0.01 there with nothing said of the wall it steps through (an
    // adversarial review).
    const double margin = problem.checker()->safetyMargin();
    if (along->least <= margin) {
      std::printf("contact     the path comes within the safety margin (%g) along its motions (the page shows "
                  "the clearance at its states)\n",
                  margin);
    } else if (along->lowerBound <= margin) {
      std::printf("unproven    no state found within the safety margin (%g), but %zu clearance queries did not "
                  "prove every state between the measured ones beyond it\n",
                  margin, along->queries);
    }
  }
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
