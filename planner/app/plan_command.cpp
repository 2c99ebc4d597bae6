// `adsd plan [PROBLEM.cfg] [--planner NAME] [--time SECONDS] [--objective length|clearance]
//            [--checker adsd|fcl] [--motion discrete|certified] [--seed S] [--no-simplify]
//            [--path OUT.path] [--html OUT.html]`
//
// Solves a problem file (the default problem without one), simplifies the path, prints a summary
// and writes the path in OMPL.app's .path format. Exit status: 0 solved, 1 not solved within the
// time, 2 bad input (one line naming the file, line and key).
//
// An arm problem (arm_planning_problem.h: a .cfg whose [problem] has a `request` key) is planned in
// joint space with the same options: the planner defaults to rrtconnect, the time to the request's
// allowed_planning_time, the path file has a "# joints: ..." header and one line of joint values
// per state, and --html writes the arm's viewer page (arm_viewer_html.h).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <functional>
#include <iostream>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <ompl/util/Console.h>
#include <ompl/util/Exception.h>
#include <ompl/util/RandomNumbers.h>
#include <ompl/util/Time.h>

#include "adsd/cli/command_line.h"
#include "adsd/error.h"
#include "adsd/planner/arm_planning_problem.h"
#include "adsd/planner/arm_state_space.h"
#include "adsd/planner/path_report.h"
#include "adsd/planner/planner_registry.h"
#include "adsd/planner/planning_problem.h"
#include "adsd/planner/problem_file.h"
#include "adsd/planner/shipped_problems.h"
#include "arm_path_samples.h"
#include "arm_viewer_html.h"
#include "commands.h"
#include "planner_watchdog.h"
#include "viewer_html.h"

namespace adsd::app {

namespace {

using namespace adsd::planner;

struct PlanArguments {
  std::string problem;
  std::optional<std::string> planner;
  std::optional<double> seconds;
  std::optional<ObjectiveKind> objective;
  CheckerKind checker = CheckerKind::adsd;
  MotionKind motion = MotionKind::discrete;
  std::optional<std::string> pathFile;
  std::optional<std::string> htmlFile;  // the browser viewer (viewer_html.h)
  std::optional<std::uint64_t> seed;
  bool simplify = true;
};

const char* const kSynopsis =
    "adsd plan [PROBLEM.cfg] [--planner NAME] [--time SECONDS] [--objective length|clearance]\n"
    "                 [--checker adsd|fcl] [--motion discrete|certified] [--seed S] [--no-simplify]\n"
    "                 [--path OUT.path] [--html OUT.html]";

const char* const kDescription =
    "Solves a problem file (OMPL.app's .cfg; the default problem without one) with the adsd validity\n"
    "checker, simplifies the path, prints a summary and writes the path in OMPL.app's .path format.\n"
    "An arm problem (a .cfg whose [problem] has a request key, docs/problem-files.md) is planned in\n"
    "joint space; its path file has one line of joint values per state.";

const char* const kDetails =
    "Exit status: 0 solved, 1 not solved within the time, 2 bad input or usage (one line naming the\n"
    "file, line and key, or the option).\n";

/// Returns nullopt after printing the help.
std::optional<PlanArguments> parseArguments(const std::vector<std::string>& args) {
  cli::CommandLine line("adsd plan", kSynopsis, kDescription, kDetails);
  line.options()
      ("planner", cli::value("NAME"), "the planner (default: the file's first [planner], else rrtconnect)")
      ("time", cli::value("SECONDS"),
       "time limit, > 0 (default: [benchmark] time_limit, for an arm the request's allowed_planning_time, else 10)")
      ("objective", cli::value("length|clearance"), "optimization objective (default: the file's)")
      ("checker", cli::value("adsd|fcl"), "state validity checker (default adsd)")
      ("motion", cli::value("discrete|certified"), "motion validator (default discrete)")
      ("seed", cli::value("S"),
       "OMPL's random seed (from 1; default: OMPL's own, printed so that it can be given back), so that runs "
       "with either checker can be repeated and compared on the same random draws")
      ("no-simplify",
       "report and write the planner's path as found (comparisons of planning time need not wait for the "
       "simplifier, which is given the time limit again and may run past it to finish the step under way; a path "
       "planned for clearance is never simplified)")
      ("path", cli::value("OUT.path"), "write the path to OUT.path")
      ("html", cli::value("OUT.html"), "write the browser viewer of the problem and its path (one page, opens offline)");
  line.positional("problem");
  const std::optional<cli::Arguments> given = line.parse(args);
  if (!given) return std::nullopt;

  PlanArguments a;
  const std::vector<std::string> problems = given->texts("problem");
  if (problems.size() > 1) {
    throw cli::UsageError("more than one problem file ('" + problems[0] + "', '" + problems[1] + "')");
  }
  a.planner = given->text("planner");
  a.seconds = given->real("time", cli::RealInterval::above(0.0).atMost(kMaxTimeLimitSeconds));
  if (const auto objective = given->choice("objective", {"length", "clearance"})) {
    a.objective = *objective == "length" ? ObjectiveKind::length : ObjectiveKind::maxMinClearance;
  }
  if (const auto checker = given->choice("checker", {"adsd", "fcl"})) {
    a.checker = *checker == "adsd" ? CheckerKind::adsd : CheckerKind::fcl;
  }
  if (const auto motion = given->choice("motion", {"discrete", "certified"})) {
    a.motion = *motion == "discrete" ? MotionKind::discrete : MotionKind::certified;
  }
  // OMPL's generator takes no seed 0, and its own seeds (microseconds of the clock) fill its seed
  // type, std::uint_fast32_t (64 bits on Linux): any seed it prints is taken back.
  a.seed = given->whole("seed", 1, std::numeric_limits<std::uint_fast32_t>::max());
  a.simplify = !given->has("no-simplify");
  a.pathFile = given->outputFile("path");
  a.htmlFile = given->outputFile("html");
  // Last: finding the shipped problems may fail, and the options' errors come first.
  a.problem = problems.empty() ? defaultProblemFile() : problems.front();
  if (a.pathFile) cli::requireDistinctFile("--path", *a.pathFile, {{"the problem file", a.problem}});
  if (a.htmlFile) {
    std::vector<std::pair<std::string, std::string>> others = {{"the problem file", a.problem}};
    if (a.pathFile) others.emplace_back("the --path file", *a.pathFile);
    cli::requireDistinctFile("--html", *a.htmlFile, others);
  }
  return a;
}

const char* name(CheckerKind k) { return k == CheckerKind::adsd ? "adsd" : "fcl"; }
const char* name(MotionKind k) { return k == MotionKind::discrete ? "discrete" : "certified"; }
const char* name(ObjectiveKind k) { return k == ObjectiveKind::length ? "length" : "max_min_clearance"; }

/// The planner named \p chosen for \p ss's objective, or an InputError listing the known names
/// (or saying why this planner cannot take that objective), which begins with \p source: where
/// the name came from ("--planner", or the problem file's line).
ompl::base::PlannerPtr makeNamedPlanner(const std::string& chosen, ompl::geometric::SimpleSetup& ss,
                                        const std::string& source = "--planner") {
  if (const auto conflict = plannerConflict(chosen, ss.getOptimizationObjective().get(), *ss.getStateSpace())) {
    throw InputError(source + ": " + *conflict);
  }
  ompl::base::PlannerPtr planner = makePlanner(chosen, ss.getSpaceInformation());
  if (!planner) {
    std::string known;
    for (const std::string& n : knownPlannerNames()) known += (known.empty() ? "" : ", ") + n;
    throw InputError(source + ": no planner named '" + chosen + "' (known: " + known + ")");
  }
  return planner;
}

/// The planner: --planner, else the file's first [planner] entry, else RRTConnect. The file's
/// parameters for that planner apply either way.
ompl::base::PlannerPtr choosePlanner(const PlanArguments& a, const ProblemFile& file, PlanningProblem& problem,
                                     std::string& chosen) {
  const PlannerEntry* entry = nullptr;
  if (a.planner) {
    chosen = *a.planner;
    for (const PlannerEntry& p : file.planners) {
      if (p.name == chosen) {
        entry = &p;
        break;
      }
    }
  } else if (!file.planners.empty()) {
    entry = &file.planners.front();
    chosen = entry->name;
  } else {
    chosen = "rrtconnect";
  }
  const std::string source = a.planner || entry == nullptr ? "--planner" : entry->location.describe();
  ompl::base::PlannerPtr planner = makeNamedPlanner(chosen, problem.setup(), source);
  if (entry != nullptr) {
    for (const std::string& w : configurePlanner(*planner, chosen, entry->parameters)) {
      std::cerr << "adsd plan: warning: " << w << '\n';
    }
  }
  return planner;
}

/// The checker, motion validator and objective the options ask for.
CheckingOptions checkingOptions(const PlanArguments& a) {
  CheckingOptions options;
  options.checker = a.checker;
  options.motion = a.motion;
  options.objective = a.objective;
  return options;
}

/// What one solve did: status, times and the planner's own queries (before the simplifier's).
struct SolveReport {
  ompl::base::PlannerStatus status;
  bool solved = false;
  double planningSeconds = 0.0;
  double simplifySeconds = 0.0;
  QueryCounts counts;
};

/// Solves \p ss within \p seconds, reads \p checker's counts when the planner returns (the
/// planner's own queries), then simplifies a solution unless told not to. A planner that runs far
/// past the limit ends the program (PlannerWatchdog), naming \p planner; the simplifier may finish
/// the step under way past it (the help says so), and is left to.
template <class Checker>
SolveReport solveAndSimplify(ompl::geometric::SimpleSetup& ss, const Checker& checker, const std::string& planner,
                             double seconds, bool simplify, const std::function<void()>& atSolveEnd) {
  SolveReport r;
  try {
    ss.setup();
  } catch (const ompl::Exception& e) {
    // A planner's set-up refuses what its setters took (KPIECE a fraction below machine epsilon,
    // STRIDE degrees that disagree): the problem file's planner parameters, not an internal error.
    throw InputError("planner " + planner + " could not be set up with its parameters: " + e.what());
  }
  const ompl::time::point started = ompl::time::now();
  {
    const PlannerWatchdog watchdog("adsd plan", planner, seconds, "no path written");
    r.status = ss.solve(seconds);
  }
  r.planningSeconds = ompl::time::seconds(ompl::time::now() - started);
  r.solved = r.status == ompl::base::PlannerStatus::EXACT_SOLUTION;
  r.counts = checker.counts();
  atSolveEnd();
  if (r.solved && simplify) {
    const ompl::time::point s = ompl::time::now();
    ss.simplifySolution(seconds);
    r.simplifySeconds = ompl::time::seconds(ompl::time::now() - s);
  }
  return r;
}

/// Whether the path is simplified: when asked (not --no-simplify) and the objective is length.
/// OMPL's simplifier shortens a path (it first tries the straight motion from start to goal), which
/// undoes what the clearance objective found (the shipped maze by RRT*, 10 s, seed 1, before this
/// rule: minimum clearance 0.0033 simplified, 0.218 as planned), so such a path is kept as planned.
bool simplifies(const PlanArguments& a, ObjectiveKind objective) {
  return a.simplify && objective == ObjectiveKind::length;
}

/// The exit status of a solved problem: 0, or 1 when the path's measured clearance is within the
/// safety margin somewhere. The discrete motion validator checks states a resolution apart, and a
/// motion past a thin obstacle, or a link that moves many times its coordinate's step (a mimic
/// finger), can step over it: OMPL then reports a solution that the summary's finer measure finds
/// in contact. Said, instead of exit status 0 under "solved yes" (the path and page are written, to
/// look at it).
int reportContact(double leastClearance, double safetyMargin, const ompl::base::SpaceInformation& si,
                  const char* where) {
  if (!(leastClearance <= safetyMargin)) return 0;
  std::printf("contact     the path comes within the safety margin (%g) %s: the discrete motion validator checks "
              "states %g apart and stepped over it; --motion certified proves every motion\n",
              safetyMargin, where, si.getStateValidityCheckingResolution() * si.getMaximumExtent());
  return 1;
}

/// A rigid body's verdict from leastClearanceAlong: a state within the margin found (contact), or
/// none found and none proven impossible within its queries. Exit status 1 for the second too
/// unless every motion was certified: a discretely checked path is then neither proven nor refuted.
int reportAlong(const PathLeastClearance& along, double safetyMargin, const ompl::base::SpaceInformation& si,
                bool certified) {
  if (reportContact(along.least, safetyMargin, si, "along its motions") != 0) return 1;
  if (along.lowerBound > safetyMargin) return 0;
  std::printf("unproven    no state found within the safety margin (%g), but %zu clearance queries did not prove "
              "every state between the measured ones beyond it%s\n",
              safetyMargin, along.queries,
              certified ? " (the certified motion validator proved each motion)"
                        : "; --motion certified proves every motion");
  return certified ? 0 : 1;
}

/// The summary lines every problem kind prints after its "problem" and "setup" lines.
void printSolveReport(const PlanArguments& a, const SolveReport& r) {
  std::printf("seed        %lu%s\n", static_cast<unsigned long>(ompl::RNG::getSeed()), a.seed ? " (--seed)" : "");
  std::printf("solved      %s (%s)\n", r.solved ? "yes" : "no", r.status.asString().c_str());
  std::printf("time        %.3f s planning, %.3f s simplifying\n", r.planningSeconds, r.simplifySeconds);
  std::printf("queries     planning: %llu validity checks (mean %.2f us), %llu clearance queries (mean %.2f us)\n",
              static_cast<unsigned long long>(r.counts.validityChecks), 1e6 * r.counts.meanValiditySeconds(),
              static_cast<unsigned long long>(r.counts.clearanceQueries), 1e6 * r.counts.meanClearanceSeconds());
}

/// `adsd plan ARM.cfg`: an arm problem (arm_planning_problem.h).
/// The outputs must not be files the problem reads: the cfg is checked with the arguments, the
/// files it names only once it is read (`--path robot.obj` wrote the path over the robot's mesh).
void requireOutputsApart(const PlanArguments& a, const std::vector<std::pair<std::string, std::string>>& inputs) {
  if (a.pathFile) cli::requireDistinctFile("--path", *a.pathFile, inputs);
  if (a.htmlFile) cli::requireDistinctFile("--html", *a.htmlFile, inputs);
}

int planArm(const PlanArguments& a) {
  const MotionBenchMakerProblem file = readMotionBenchMakerProblem(a.problem);
  std::vector<std::pair<std::string, std::string>> inputs = {
      {"the URDF file", file.robotPath}, {"the scene file", file.scenePath}, {"the request file", file.requestPath}};
  if (file.srdfPath) inputs.emplace_back("the SRDF file", *file.srdfPath);
  requireOutputsApart(a, inputs);
  ArmPlanningProblem problem(file, checkingOptions(a));
  for (const std::string& w : problem.warnings()) std::cerr << "adsd plan: warning: " << w << '\n';
  if (a.htmlFile) requireArmViewable(problem, a.problem);  // before planning: a refused page leaves nothing written

  const std::string plannerName = a.planner.value_or("rrtconnect");
  ompl::geometric::SimpleSetup& ss = problem.setup();
  ss.setPlanner(makeNamedPlanner(plannerName, ss));
  const double seconds = a.seconds.value_or(problem.allowedPlanningTime().value_or(10.0));

  ArmMotionCounts certified;
  std::uint64_t discreteMotions = 0, costedMotions = 0, costStates = 0;
  const bool simplify = simplifies(a, problem.objective());
  const SolveReport r = solveAndSimplify(ss, *problem.checker(), plannerName, seconds, simplify, [&] {
    if (const auto& objective = problem.objectiveClearance()) {
      costedMotions = objective->motions();
      costStates = objective->statesQueried();
    }
    if (problem.certifiedValidator()) {
      certified = problem.certifiedValidator()->counts();
    } else {
      discreteMotions = problem.spaceInformation()->getMotionValidator()->getCheckedMotionCount();
    }
  });

  std::printf("problem     %s (arm %s, %zu joints, %s)\n", problem.name().c_str(), problem.model().name.c_str(),
              problem.model().dof(), a.problem.c_str());
  std::printf("setup       planner %s, checker %s, motion %s, objective %s, time limit %g s\n", plannerName.c_str(),
              name(a.checker), name(a.motion), name(problem.objective()), seconds);
  printSolveReport(a, r);
  if (problem.certifiedValidator()) {
    std::printf("motions     planning: %llu certified checks, %llu rejected, %llu clearance queries\n",
                static_cast<unsigned long long>(certified.motions), static_cast<unsigned long long>(certified.rejected),
                static_cast<unsigned long long>(certified.clearanceQueries));
  } else {
    std::printf("motions     planning: %llu discrete checks\n", static_cast<unsigned long long>(discreteMotions));
  }
  if (problem.objectiveClearance()) {
    std::printf("costs       planning: %llu motions costed by their certified clearance, %.1f states queried each "
                "(the path is not simplified: the simplifier shortens, lowering the clearance)\n",
                static_cast<unsigned long long>(costedMotions),
                costedMotions ? static_cast<double>(costStates) / static_cast<double>(costedMotions) : 0.0);
  }
  if (!r.solved) return 1;

  const ompl::geometric::PathGeometric& path = ss.getSolutionPath();
  // The clearance at states armClearanceStep() apart along the path, or closer (a copy).
  const ompl::geometric::PathGeometric samples = armClearanceSamples(path);
  const PathMeasures measures = measurePath(samples, *problem.checker());
  const auto& space = problem.spaceInformation()->getStateSpace();
  std::printf("path        %zu states, length %.6g (joint space: the sum of the joints' absolute changes)\n",
              path.getStateCount(), measures.length);
  // With no obstacle and no link pair to check, no distance is measured: said, not printed as inf.
  if (std::isfinite(measures.minClearance)) {
    std::printf("clearance   min %.6g m, mean %.6g m (%s, at %zu states of the path, at most %.3g apart in joint space)\n",
                measures.minClearance, measures.meanClearance, a.checker == CheckerKind::adsd ? "exact" : "FCL's distance",
                measures.statesSampled, largestStep(samples));
  } else {
    std::printf("clearance   none measured: nothing for the links to collide with\n");
  }
  // What the clearance objective maximizes, the clearance to the obstacles, measured with either
  // objective so that runs with both compare.
  std::shared_ptr<const ArmMotionClearance> objective = problem.objectiveClearance();
  if (!objective) objective = std::make_shared<const ArmMotionClearance>(problem.checker());
  const ArmPathClearance obstacles = measureArmPathClearance(path, samples, *objective);
  if (std::isfinite(obstacles.min)) {
    std::printf("obstacles   clearance min %.6g m, mean %.6g m (exact, the same states; the links against the obstacles, "
                "what --objective clearance maximizes), certified >= %.6g m along the path\n",
                obstacles.min, obstacles.mean, obstacles.certifiedMin);
  } else {
    std::printf("obstacles   none measured: %s\n",
                problem.scene().environment.empty() ? "none in the scene" : "no link has collision geometry");
  }
  if (a.pathFile) {
    std::vector<std::string> joints;
    for (const std::size_t j : problem.model().activeJoints) joints.push_back(problem.model().joints[j].name);
    writeArmPathFile(*a.pathFile, path, static_cast<const ArmStateSpace&>(*space), joints);
    std::printf("path file   %s\n", a.pathFile->c_str());
  }
  if (a.htmlFile) {
    writeArmViewerHtml(*a.htmlFile, problem, &path, "adsd plan, planner " + plannerName);
    std::printf("viewer      %s\n", a.htmlFile->c_str());
  }
  return reportContact(measures.minClearance, problem.checker()->safetyMargin(), *problem.spaceInformation(),
                       "at a measured state");
}

int plan(const std::vector<std::string>& args) {
  const std::optional<PlanArguments> parsed = parseArguments(args);
  if (!parsed) return 0;  // the help
  const PlanArguments& a = *parsed;
  // Before anything draws a random number: OMPL seeds every new generator from one seeded one.
  if (a.seed) ompl::RNG::setSeed(static_cast<std::uint_fast32_t>(*a.seed));
  if (isArmProblemFile(a.problem)) return planArm(a);
  const ProblemFile file = readProblemFile(a.problem);
  for (const std::string& w : file.warnings) std::cerr << "adsd plan: warning: " << w << '\n';
  requireOutputsApart(a, {{"the robot mesh", file.robotPath}, {"the world mesh", file.worldPath}});

  PlanningProblem problem(file, checkingOptions(a));
  for (const std::string& w : problem.warnings()) std::cerr << "adsd plan: warning: " << w << '\n';

  std::string plannerName;
  ompl::geometric::SimpleSetup& ss = problem.setup();
  ss.setPlanner(choosePlanner(a, file, problem, plannerName));
  const double seconds = a.seconds.value_or(file.benchmark.timeLimit.value_or(10.0));

  MotionCounts motionCounts;
  const bool simplify = simplifies(a, problem.objective());
  const SolveReport r = solveAndSimplify(ss, *problem.checker(), plannerName, seconds, simplify, [&] {
    if (problem.certifiedValidator()) motionCounts = problem.certifiedValidator()->counts();
  });

  std::printf("problem     %s (%s, %s)\n", file.name.c_str(), file.space == RigidBodySpace::se2 ? "SE(2)" : "SE(3)",
              a.problem.c_str());
  std::printf("setup       planner %s, checker %s, motion %s, objective %s, time limit %g s\n", plannerName.c_str(),
              name(a.checker), name(a.motion), name(problem.objective()), seconds);
  printSolveReport(a, r);
  if (problem.certifiedValidator()) {
    const MotionCounts& m = motionCounts;
    std::printf("motions     planning: %llu certified checks, %llu rejected, %llu clearance steps\n",
                static_cast<unsigned long long>(m.motions), static_cast<unsigned long long>(m.rejected),
                static_cast<unsigned long long>(m.clearanceSteps));
  }
  if (a.simplify && !simplify) {
    std::printf("simplify    not done: the objective is clearance, and the simplifier shortens the path, lowering "
                "it\n");
  }
  if (!r.solved) return 1;

  const ompl::geometric::PathGeometric& path = ss.getSolutionPath();
  const PathMeasures measures = measurePath(path, *problem.checker());
  std::printf("path        %zu states, length %.6g\n", path.getStateCount(), measures.length);
  const std::string over = measures.coarserThanResolution
                               ? "cut coarser than the validity-checking resolution, to about " +
                                     std::to_string(kMaxMeasuredStates) + " or the path's own"
                               : std::string("at the validity-checking resolution");
  std::printf("clearance   min %.6g, mean %.6g (over %zu states %s)\n", measures.minClearance,
              measures.meanClearance, measures.statesSampled, over.c_str());
  // Between those states too: a motion can pass nearer an edge than either end of its step, or,
  // checked discretely, step over a thin obstacle.
  const PathLeastClearance along = leastClearanceAlong(path, *problem.checker());
  std::printf("along       min %.6g between the states too (no state of the motions nearer than %.6g; %zu "
              "clearance queries)\n",
              along.least, along.lowerBound, along.queries);
  if (a.pathFile) {
    writePathFile(*a.pathFile, path, file.space);
    std::printf("path file   %s\n", a.pathFile->c_str());
  }
  if (a.htmlFile) {
    writeViewerHtml(*a.htmlFile, file, problem, &path, "adsd plan, planner " + plannerName);
    std::printf("viewer      %s\n", a.htmlFile->c_str());
  }
  return reportAlong(along, problem.checker()->safetyMargin(), *problem.spaceInformation(),
                     problem.certifiedValidator() != nullptr);
}

}  // namespace

/// \brief Entry point of `adsd plan`; \p args are the arguments after "plan".
int planCommand(const std::vector<std::string>& args) {
  ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
  return reportingErrors("adsd plan", [&] { return plan(args); });
}

}  // namespace adsd::app
