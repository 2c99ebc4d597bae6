// `adsd benchmark [PROBLEM.cfg | ARM.cfg | DIR] [--planner NAME[,NAME]] [--checker adsd|fcl|both]
//                 [--motion discrete|certified|both] [--runs N | --run-range A:B] [--seed S]
//                 [--time SECONDS] [--out DIR] [--no-plots | --log-only]`
//
// Runs OMPL's benchmark (ompl::tools::Benchmark) on a problem file's [benchmark] and [planner]
// sections for every checker × motion-validator combination asked for, and writes
//   DIR/STEM.log        the OMPL benchmark log: one experiment, each planner once per combination,
//                       named "LABEL [CHECKER, MOTION]" (so Planner Arena shows them side by side);
//   DIR/STEM.db         the SQLite database `ompl_benchmark_statistics STEM.log -d STEM.db` writes;
//   DIR/STEM.*.png      plots drawn from that database (bench/planning/plot_benchmark.py), which
//                       also prints a summary table (not with --no-plots: the table only);
// where STEM is the problem's name, plus ".runs-A-B" for a run range and ".seed-S" for a seed, so
// that every shard writes its own files (`ompl_benchmark_statistics` merges many logs into one
// database). --log-only writes the log and stops (shards on machines without Python).
//
// Memory does not grow with the run count: each run's record goes to a spool file beside the log
// as soon as the run is done (SpooledBenchmarkLog), and the log is assembled from the spools at
// the end (through a temporary name; the spools are removed, also on error).
//
// Each run records, beside OMPL's own properties: the checker and the motion validator, the run's
// index, the planner's own solve time ("planner time": OMPL's "time" without its termination
// thread's start and join), and the planner's own queries: validity checks and clearance queries
// with their time, motion checks. These are read when the planner's solve returns, before the
// benchmark's bookkeeping (solution checks, clearance, simplification) queries the checker again.
//
// Arm problems (arm_planning_problem.h; issue 17) take the same path: an arm `.cfg`, or a directory
// whose every `problem.cfg` below it is an arm problem (MotionBenchMaker-style folders), one log
// and database per problem. An arm problem has no [benchmark] or [planner] section: the planners
// come from --planner (default rrtconnect), the runs from --runs (default 10), the time from
// --time (default the request's allowed_planning_time, else 10 s). Both problem kinds are held
// behind BenchmarkedProblem, so everything after the set-up is shared.
//
// Exit status: 0 done; 1 a tool failed or no run was recorded; 2 bad input (one line naming the
// file, line and key, or the option).
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <ompl/base/Planner.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/tools/benchmark/Benchmark.h>
#include <ompl/util/Console.h>
#include <ompl/util/Exception.h>
#include <ompl/util/RandomNumbers.h>

#include "adsd/cli/command_line.h"
#include "adsd/error.h"
#include "adsd/planner/arm_planning_problem.h"
#include "adsd/planner/motion_plan_request_yaml.h"
#include "adsd/planner/path_report.h"
#include "adsd/planner/planner_registry.h"
#include "adsd/planner/planning_problem.h"
#include "adsd/planner/problem_file.h"
#include "adsd/planner/shipped_problems.h"
#include "commands.h"
#include "planner_watchdog.h"
#include "spooled_benchmark_log.h"

namespace adsd::app {

namespace {

using namespace adsd::planner;
namespace fs = std::filesystem;
namespace ob = ompl::base;
namespace ot = ompl::tools;

const char* const kSynopsis =
    "adsd benchmark [PROBLEM.cfg | ARM.cfg | DIR] [--planner NAME[,NAME]] [--checker adsd|fcl|both]\n"
    "                      [--motion discrete|certified|both] [--runs N | --run-range A:B] [--seed S]\n"
    "                      [--time SECONDS] [--out DIR] [--no-plots | --log-only]";

const char* const kDescription =
    "Runs OMPL's benchmark on the problem's [benchmark] and [planner] sections for each checker and\n"
    "motion validator (default: both of each), writes DIR/STEM.log, converts it with\n"
    "ompl_benchmark_statistics into DIR/STEM.db and plots it (bench/planning/plot_benchmark.py).";

const char* const kDetails =
    "An arm problem (ARM.cfg, or every problem.cfg under DIR) is benchmarked the same way, one log per\n"
    "problem: planners from --planner (default rrtconnect), --runs default 10, --time default the\n"
    "request's allowed_planning_time, else 10 s.\n"
    "STEM is the problem's name, plus .runs-A-B for a run range and .seed-S for a seed, so that every\n"
    "shard writes its own files. Exit status: 0 done; 1 a tool failed or no run was recorded; 2 bad\n"
    "input or usage (one line naming the file, line and key, or the option).\n";

/// An arm problem has no [benchmark] section: its run count unless --runs says otherwise.
constexpr unsigned kArmRunCount = 10;
/// ... and its time limit (seconds) when neither --time nor the request's allowed_planning_time says.
constexpr double kArmTimeLimit = 10.0;

/// OMPL's RNG takes no seed 0. A shard of runs [A, B) without --seed is seeded with
/// A + kShardSeedOffset: shards get different seeds, and a shard run again gets the same one.
constexpr std::uint64_t kShardSeedOffset = 1;

/// The interpreter for the plotting script: Debian's, which has matplotlib (the team's rule: not
/// whichever python3 comes first on PATH).
const char* const kPython = "/usr/bin/python3";

/// OMPL's program that turns benchmark logs into a SQLite database, by both names it is installed
/// under, the first found on PATH taken: Debian's package ompl-demos drops the script's extension,
/// OMPL's own install (scripts/CMakeLists.txt; what a source build of OMPL 2.0 gives) keeps it.
const char* const kStatisticsPrograms[] = {"ompl_benchmark_statistics", "ompl_benchmark_statistics.py"};

#ifndef ADSD_PLOT_BENCHMARK_SCRIPT
#define ADSD_PLOT_BENCHMARK_SCRIPT ""
#endif

// ---- arguments ---------------------------------------------------------------------------------

struct BenchmarkArguments {
  std::string problem;
  std::vector<std::string> planners;  ///< --planner, split at commas; empty: the file's (arm: rrtconnect)
  std::vector<CheckerKind> checkers{CheckerKind::adsd, CheckerKind::fcl};
  std::vector<MotionKind> motions{MotionKind::discrete, MotionKind::certified};
  std::optional<unsigned> runs;
  std::optional<std::pair<unsigned, unsigned>> runRange;  ///< [first, end)
  std::optional<std::uint64_t> seed;
  std::optional<double> seconds;
  std::optional<std::string> outDirectory;
  bool plots = true;
  bool logOnly = false;
};

/// Returns nullopt after printing the help.
std::optional<BenchmarkArguments> parseArguments(const std::vector<std::string>& args) {
  constexpr std::uint64_t kMaxRuns = std::numeric_limits<unsigned>::max();  // OMPL counts runs in unsigned int
  // OMPL's seed type, std::uint_fast32_t, is 64 bits on Linux, and its own seeds fill it.
  constexpr std::uint64_t kMaxSeed = std::numeric_limits<std::uint_fast32_t>::max();
  cli::CommandLine line("adsd benchmark", kSynopsis, kDescription, kDetails);
  line.options()
      ("planner", cli::value("NAME[,NAME]"),
       "planners to benchmark, instead of the file's [planner] entries (default for an arm problem: rrtconnect)")
      ("checker", cli::value("adsd|fcl|both"), "state validity checkers (default both)")
      ("motion", cli::value("discrete|certified|both"), "motion validators (default both)")
      ("runs", cli::value("N"), "runs per planner and combination (default: [benchmark] run_count; arm: 10)")
      ("run-range", cli::value("A:B"), "this shard's runs: indices A to B-1 (seed A+1 unless --seed)")
      ("seed", cli::value("S"), "OMPL's random seed (from 1; default: OMPL's own)")
      ("time", cli::value("SECONDS"),
       "time limit per run, > 0 (default: [benchmark] time_limit; arm: allowed_planning_time, else 10)")
      ("out", cli::value("DIR"), "output directory (default: [benchmark] output, else the current one)")
      ("no-plots", "database and summary table, no plots")
      ("log-only", "the log only (merge shards' logs later with ompl_benchmark_statistics)");
  line.positional("problem");
  const std::optional<cli::Arguments> given = line.parse(args);
  if (!given) return std::nullopt;

  BenchmarkArguments a;
  const std::vector<std::string> problems = given->texts("problem");
  if (problems.size() > 1) {
    throw cli::UsageError("more than one problem file ('" + problems[0] + "', '" + problems[1] + "')");
  }
  if (const auto planners = given->text("planner")) {
    std::istringstream names(*planners);
    std::string n;
    while (std::getline(names, n, ',')) {
      const auto& known = knownPlannerNames();
      if (std::find(known.begin(), known.end(), n) == known.end()) {
        std::string list;
        for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
        throw cli::UsageError("--planner: no planner named '" + n + "' (known: " + list + ")");
      }
      a.planners.push_back(n);
    }
    if (a.planners.empty()) throw cli::UsageError("--planner: expected NAME[,NAME], got ''");
  }
  if (const auto checker = given->choice("checker", {"adsd", "fcl", "both"})) {
    if (*checker == "adsd") a.checkers = {CheckerKind::adsd};
    if (*checker == "fcl") a.checkers = {CheckerKind::fcl};
  }
  if (const auto motion = given->choice("motion", {"discrete", "certified", "both"})) {
    if (*motion == "discrete") a.motions = {MotionKind::discrete};
    if (*motion == "certified") a.motions = {MotionKind::certified};
  }
  if (const auto runs = given->whole("runs", 1, kMaxRuns)) a.runs = static_cast<unsigned>(*runs);
  if (const auto range = given->text("run-range")) {
    const auto colon = range->find(':');
    if (colon == std::string::npos) {
      throw cli::UsageError("--run-range: expected A:B (runs A to B-1), got '" + *range + "'");
    }
    const auto first = cli::parseWhole(range->substr(0, colon), "--run-range (A of A:B)", 0, kMaxRuns - 1);
    const auto end = cli::parseWhole(range->substr(colon + 1), "--run-range (B of A:B)", 1, kMaxRuns);
    if (end <= first) throw cli::UsageError("--run-range: expected A < B (runs A to B-1), got '" + *range + "'");
    a.runRange = std::make_pair(static_cast<unsigned>(first), static_cast<unsigned>(end));
  }
  a.seed = given->whole("seed", 1, kMaxSeed);
  a.seconds = given->real("time", cli::RealInterval::above(0.0).atMost(kMaxTimeLimitSeconds));
  a.outDirectory = given->text("out");
  if (a.outDirectory && a.outDirectory->empty()) throw cli::UsageError("--out: expected a directory, got ''");
  a.plots = !given->has("no-plots");
  a.logOnly = given->has("log-only");
  if (a.runs && a.runRange) throw cli::UsageError("--runs and --run-range: give one (a range's size is its run count)");
  if (a.logOnly && !a.plots) throw cli::UsageError("--log-only and --no-plots: give one (--log-only draws nothing)");
  // Last: finding the shipped problems may fail, and the options' errors come first.
  a.problem = problems.empty() ? defaultProblemFile() : problems.front();
  return a;
}

const char* name(CheckerKind k) { return k == CheckerKind::adsd ? "adsd" : "fcl"; }
const char* name(MotionKind k) { return k == MotionKind::discrete ? "discrete" : "certified"; }

// ---- measuring the planner's own queries ---------------------------------------------------------

/// \brief Runs another planner unchanged and calls \p atSolveEnd the moment its solve returns,
/// with the seconds that solve took.
///
/// Why: ompl::tools::Benchmark calls the post-run event only after its bookkeeping on the solution
/// (it checks the path twice, the second time at four times the resolution, measures its
/// clearance, simplifies it and measures again), and all of that queries the same checker. Counters
/// read at the end of solve are the planner's own queries; read in the post-run event they would
/// include the bookkeeping. Everything else is forwarded: the planner plans exactly as itself, its
/// parameters are the wrapped planner's (so the log's settings are its settings), and so are its
/// progress properties.
class MeasuredPlanner final : public ob::Planner {
 public:
  MeasuredPlanner(ob::PlannerPtr planner, const std::string& label, double timeLimit,
                  std::function<void(double)> atSolveEnd)
      : ob::Planner(planner->getSpaceInformation(), label),
        planner_(std::move(planner)),
        timeLimit_(timeLimit),
        atSolveEnd_(std::move(atSolveEnd)) {
    specs_ = planner_->getSpecs();
    params_.include(planner_->params());
    for (const auto& property : planner_->getPlannerProgressProperties()) {
      addPlannerProgressProperty(property.first, property.second);
    }
  }

  ob::PlannerStatus solve(const ob::PlannerTerminationCondition& ptc) override {
    // Also when the planner throws: Benchmark catches and records the run, and the counts then are
    // what the planner spent before it failed.
    struct AtExit {
      std::function<void(double)>& call;
      std::chrono::steady_clock::time_point started;
      ~AtExit() { call(std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count()); }
    } atExit{atSolveEnd_, std::chrono::steady_clock::now()};
    // Around the planner's solve alone: OMPL's Benchmark waits for ever on a planner that never
    // tests its time limit, and what it does after solve (checking and simplifying the path, with
    // no limit) is not the planner's. The line starts afresh after the progress bar's.
    const PlannerWatchdog watchdog("adsd benchmark", getName(), timeLimit_, "this problem's log is not written",
                                   true);
    return planner_->solve(ptc);
  }
  void setProblemDefinition(const ob::ProblemDefinitionPtr& pdef) override {
    ob::Planner::setProblemDefinition(pdef);
    planner_->setProblemDefinition(pdef);
  }
  void clear() override {
    ob::Planner::clear();
    planner_->clear();
  }
  void clearQuery() override {
    ob::Planner::clearQuery();
    planner_->clearQuery();
  }
  void setup() override {
    ob::Planner::setup();
    try {
      if (!planner_->isSetup()) planner_->setup();
    } catch (const ompl::Exception& e) {  // as adsd plan: the file's planner parameters
      throw InputError("planner " + getName() + " could not be set up with its parameters: " + e.what());
    }
  }
  void checkValidity() override { planner_->checkValidity(); }
  void getPlannerData(ob::PlannerData& data) const override { planner_->getPlannerData(data); }
  void printProperties(std::ostream& out) const override {
    out << "Benchmarked as " << getName() << '\n';
    planner_->printProperties(out);
  }
  void printSettings(std::ostream& out) const override { planner_->printSettings(out); }

 private:
  ob::PlannerPtr planner_;
  double timeLimit_;
  std::function<void(double)> atSolveEnd_;
};

/// The planner's own queries in one run: the counters when its solve returned.
struct RunQueries {
  bool captured = false;
  /// The wrapped planner's solve alone, from its call to its return (seconds). OMPL's "time" also
  /// holds the termination condition's thread, which Planner::solve(fn, period) starts first and
  /// joins last; that thread sleeps in steps of 1 ms, so the join waits up to 1 ms whatever was
  /// planned, a large share of a short solve.
  double plannerSeconds = 0.0;
  QueryCounts queries;
  std::uint64_t motionChecks = 0;
  std::uint64_t motionsRejected = 0;
  std::optional<std::uint64_t> certifiedSteps;  ///< certified validator only
};

/// What a certified motion validator has done (rigid: CertifiedMotionValidator's MotionCounts; arm:
/// ArmMotionValidator's ArmMotionCounts).
struct CertifiedCounts {
  std::uint64_t motions = 0;
  std::uint64_t rejected = 0;
  std::uint64_t clearanceSteps = 0;  ///< clearance queries spent certifying motions
};
CertifiedCounts certifiedCounts(const MotionCounts& m) { return {m.motions, m.rejected, m.clearanceSteps}; }
CertifiedCounts certifiedCounts(const ArmMotionCounts& m) { return {m.motions, m.rejected, m.clearanceQueries}; }

/// \brief What the benchmark needs of a problem, rigid body (PlanningProblem) or arm
/// (ArmPlanningProblem): its SimpleSetup and its counters.
class BenchmarkedProblem {
 public:
  virtual ~BenchmarkedProblem() = default;
  virtual ompl::geometric::SimpleSetup& setup() = 0;
  virtual const ob::SpaceInformationPtr& spaceInformation() const = 0;
  virtual QueryCounts counts() const = 0;
  /// \brief The checker's counters, and the certified validator's when there is one.
  virtual void resetCounts() = 0;
  /// \brief The certified validator's counts, or nullopt when OMPL's discrete validator is in use.
  virtual std::optional<CertifiedCounts> certified() const = 0;
  virtual const std::vector<std::string>& warnings() const = 0;
  /// \brief The least clearance of \p path as `adsd plan` measures it (a rigid body's between its
  /// states too, leastClearanceAlong; an arm's at its measured states), and the checker's margin.
  virtual std::pair<double, double> leastClearanceOf(const ompl::geometric::PathGeometric& path) const = 0;
};

/// What `adsd plan` measures of a path, by problem type.
double leastClearanceOf(const PlanningProblem& problem, const ompl::geometric::PathGeometric& path) {
  return leastClearanceAlong(path, *problem.checker()).least;
}
double leastClearanceOf(const ArmPlanningProblem& problem, const ompl::geometric::PathGeometric& path) {
  return measurePath(path, *problem.checker()).minClearance;
}

/// BenchmarkedProblem over either problem type (both have the same members; only their motion
/// counts' types differ, which certifiedCounts() reconciles).
template <class Problem>
class BenchmarkedProblemOf final : public BenchmarkedProblem {
 public:
  template <class File>
  BenchmarkedProblemOf(const File& file, const CheckingOptions& options) : problem_(file, options) {}
  ompl::geometric::SimpleSetup& setup() override { return problem_.setup(); }
  const ob::SpaceInformationPtr& spaceInformation() const override { return problem_.spaceInformation(); }
  QueryCounts counts() const override { return problem_.checker()->counts(); }
  void resetCounts() override {
    problem_.checker()->resetCounts();
    if (const auto& certified = problem_.certifiedValidator()) certified->resetCounts();
  }
  std::optional<CertifiedCounts> certified() const override {
    if (const auto& certified = problem_.certifiedValidator()) return certifiedCounts(certified->counts());
    return std::nullopt;
  }
  const std::vector<std::string>& warnings() const override { return problem_.warnings(); }
  std::pair<double, double> leastClearanceOf(const ompl::geometric::PathGeometric& path) const override {
    return {app::leastClearanceOf(problem_, path), problem_.checker()->safetyMargin()};
  }

 private:
  Problem problem_;
};

/// One checker × motion validator: its own problem (checker, validator, SimpleSetup) and benchmark.
struct Combination {
  CheckerKind checker = CheckerKind::adsd;
  MotionKind motion = MotionKind::discrete;
  std::unique_ptr<BenchmarkedProblem> problem;
  std::unique_ptr<ot::Benchmark> benchmark;
  /// Written by the planning thread when solve returns; read in the post-run event, which runs
  /// after Benchmark has joined that thread.
  RunQueries atSolveEnd;
  /// OMPL's description of the set-up (space, validity checker, planners), from its first run.
  std::string setupInfo;

  std::string label() const { return std::string(name(checker)) + ", " + name(motion); }
};

void captureQueries(Combination& c, double plannerSeconds) {
  RunQueries& r = c.atSolveEnd;
  r.plannerSeconds = plannerSeconds;
  r.queries = c.problem->counts();
  if (const auto certified = c.problem->certified()) {
    const CertifiedCounts& m = *certified;
    r.motionChecks = m.motions;
    r.motionsRejected = m.rejected;
    r.certifiedSteps = m.clearanceSteps;
  } else {
    // OMPL's DiscreteMotionValidator counts in plain (non-atomic) integers: exact for one planning
    // thread, approximate for planners that check motions from several (PRM).
    const ob::MotionValidatorPtr& validator = c.problem->spaceInformation()->getMotionValidator();
    r.motionChecks = validator->getCheckedMotionCount();
    r.motionsRejected = validator->getInvalidMotionCount();
    r.certifiedSteps.reset();
  }
  r.captured = true;
}

/// A REAL property's text, with every digit of the double (ompl::toString keeps six).
std::string real(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

/// Our run properties, named by OMPL's convention ("name TYPE"; ompl_benchmark_statistics makes
/// "name" a column of the runs table with that SQL type). Times are seconds, as OMPL's.
void addRunProperties(const Combination& c, unsigned runIndex, ot::Benchmark::RunProperties& run) {
  run["checker STRING"] = name(c.checker);
  run["motion validator STRING"] = name(c.motion);
  run["run index INTEGER"] = std::to_string(runIndex);
  if (const auto certified = c.problem->certified()) {
    // OMPL's "valid segment fraction" reads the base class's counters, which the certified
    // validator does not write (they are not atomic); give the same fraction from its own counts,
    // over the same span as OMPL's (every motion check since the run began, bookkeeping included).
    const CertifiedCounts& m = *certified;
    run["valid segment fraction REAL"] =
        real(m.motions == 0 ? 0.0 : static_cast<double>(m.motions - m.rejected) / static_cast<double>(m.motions));
  }
  const RunQueries& r = c.atSolveEnd;
  if (!r.captured) return;  // solve never ran; Benchmark has said why
  const QueryCounts& q = r.queries;
  run["planner time REAL"] = real(r.plannerSeconds);
  run["validity checks INTEGER"] = std::to_string(q.validityChecks);
  run["clearance queries INTEGER"] = std::to_string(q.clearanceQueries);
  run["validity check time REAL"] = real(q.validitySeconds);
  run["clearance query time REAL"] = real(q.clearanceSeconds);
  // A mean over no queries is left out (NULL in the database), never written as 0.
  if (q.validityChecks > 0) run["mean validity check time REAL"] = real(q.meanValiditySeconds());
  if (q.clearanceQueries > 0) run["mean clearance query time REAL"] = real(q.meanClearanceSeconds());
  run["motion checks INTEGER"] = std::to_string(r.motionChecks);
  run["motions rejected INTEGER"] = std::to_string(r.motionsRejected);
  if (r.certifiedSteps) run["certified clearance steps INTEGER"] = std::to_string(*r.certifiedSteps);
  // The share of the planning time spent in our queries. Query times are summed over threads, so
  // a planner that plans on several threads can exceed 1.
  const auto time = run.find("time REAL");
  if (time != run.end()) {
    const double planningSeconds = cli::toReal(time->second).value_or(0.0);
    if (planningSeconds > 0.0 && std::isfinite(planningSeconds)) {
      run["query time fraction REAL"] = real((q.validitySeconds + q.clearanceSeconds) / planningSeconds);
    }
  }
}

/// Whether the run's path comes within the checker's safety margin, as `adsd plan` measures it: OMPL
/// counts a discrete validator's path that steps over a thin obstacle as solved (`solved`,
/// `correct_solution`), and an outside review found 5 of 8 such paths colliding on one problem
/// with nothing in the log to tell. "path least clearance" is measured after the run, outside
/// its times and query counts (captured when solve returned); "path in contact" is 1 when it is
/// at or below the margin. Runs without a path have neither.
void addPathContact(const Combination& c, const ob::Planner& planner, ot::Benchmark::RunProperties& run) {
  const ob::ProblemDefinitionPtr& definition = planner.getProblemDefinition();
  if (!definition || !definition->hasSolution()) return;
  const auto path = std::dynamic_pointer_cast<ompl::geometric::PathGeometric>(definition->getSolutionPath());
  if (!path || path->getStateCount() == 0) return;
  const auto [least, margin] = c.problem->leastClearanceOf(*path);
  run["path least clearance REAL"] = real(least);
  run["path in contact BOOLEAN"] = least <= margin ? "1" : "0";
}

// ---- progress ----------------------------------------------------------------------------------

/// \brief A progress bar on stderr: redrawn in place on a terminal; otherwise a line per tenth of
/// the runs, and at least one a minute (a long benchmark's log shows how far it got).
///
/// OMPL's own bar (Request::displayProgress) starts over at every call of Benchmark::benchmark;
/// the runs here are one call each (interleaved across combinations), so the bar is ours.
class ProgressBar {
 public:
  explicit ProgressBar(std::size_t total) : total_(total), terminal_(isatty(STDERR_FILENO) != 0) {}

  void starting(const std::string& what) {
    current_ = what;
    if (terminal_) draw();
  }
  void finished() {
    ++done_;
    if (terminal_) {
      draw();
    } else if (done_ * 10 / total_ != (done_ - 1) * 10 / total_ || done_ == total_ ||
               std::chrono::steady_clock::now() - lastLine_ >= kLineEvery) {
      lastLine_ = std::chrono::steady_clock::now();
      std::cerr << "adsd benchmark: " << done_ << "/" << total_ << " runs done\n";
    }
  }
  void close() {
    if (terminal_) std::cerr << '\n';
  }

 private:
  void draw() {
    constexpr std::size_t kWidth = 30;
    const std::size_t filled = done_ * kWidth / total_;
    std::string line = "\r[" + std::string(filled, '#') + std::string(kWidth - filled, '.') + "] " +
                       std::to_string(done_) + "/" + std::to_string(total_) + "  " + current_;
    constexpr std::size_t kLine = 110;  // keep it on one line of a usual terminal
    if (line.size() > kLine) line.resize(kLine);
    line.resize(kLine, ' ');
    std::cerr << line << std::flush;
  }

  static constexpr std::chrono::seconds kLineEvery{60};

  std::size_t total_;
  std::size_t done_ = 0;
  bool terminal_;
  std::string current_;
  std::chrono::steady_clock::time_point lastLine_ = std::chrono::steady_clock::now();
};

// ---- other programs ----------------------------------------------------------------------------

/// The program's path when it is an executable file in a directory of PATH.
std::optional<std::string> findOnPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::istringstream directories(path != nullptr ? path : "");
  std::string directory;
  while (std::getline(directories, directory, ':')) {
    const std::string candidate = (directory.empty() ? std::string(".") : directory) + "/" + program;
    if (::access(candidate.c_str(), X_OK) == 0 && fs::is_regular_file(candidate)) return candidate;
  }
  return std::nullopt;
}

/// Runs \p argv (argv[0] a path) and returns its exit status, -1 when it could not run or was
/// killed. With \p stdoutToStderr its standard output goes to our standard error (its progress
/// chatter, while our standard output keeps the results).
int runProgram(const std::vector<std::string>& argv, bool stdoutToStderr) {
  std::vector<char*> pointers;
  for (const std::string& s : argv) pointers.push_back(const_cast<char*>(s.c_str()));
  pointers.push_back(nullptr);
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  const pid_t child = ::fork();
  if (child < 0) return -1;
  if (child == 0) {
    if (stdoutToStderr) ::dup2(STDERR_FILENO, STDOUT_FILENO);
    ::execv(pointers[0], pointers.data());
    std::fprintf(stderr, "adsd benchmark: cannot run %s: %s\n", pointers[0], std::strerror(errno));
    ::_exit(127);
  }
  int status = 0;
  while (::waitpid(child, &status, 0) < 0) {
    if (errno != EINTR) return -1;
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// The command as one line, for messages.
std::string commandLine(const std::vector<std::string>& argv) {
  std::string s;
  for (const std::string& a : argv) s += (s.empty() ? "" : " ") + a;
  return s;
}

/// A tool we need is missing or failed: exit status 1, not 2 (the input was fine).
struct ToolFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// ---- the command -------------------------------------------------------------------------------

/// Letters, digits, '.', '-' and '_' of \p name; anything else becomes '_' (file names).
std::string fileStem(const std::string& name) {
  std::string s = name.empty() ? std::string("benchmark") : name;
  for (char& ch : s) {
    const bool keep = (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') || ch == '.' ||
                      ch == '-' || ch == '_';
    if (!keep) ch = '_';
  }
  return s;
}

/// The file's planner entries; a file without any benchmarks RRTConnect, as `adsd plan` plans with it.
std::vector<PlannerEntry> plannersOf(const ProblemFile& file) {
  if (!file.planners.empty()) return file.planners;
  std::cerr << "adsd benchmark: note: " << file.path << " has no [planner] entry; benchmarking rrtconnect\n";
  PlannerEntry rrtconnect;
  rrtconnect.name = "rrtconnect";
  rrtconnect.label = "rrtconnect";
  return {rrtconnect};
}

/// A planner of \p entry on \p si with the entry's parameters; warnings only when \p warn (they are
/// the same for every combination).
ob::PlannerPtr makeConfiguredPlanner(const PlannerEntry& entry, ompl::geometric::SimpleSetup& ss, bool warn) {
  // Where the name came from: the problem file's [planner] line, or --planner.
  const std::string source = entry.location.file.empty() ? "--planner" : entry.location.describe();
  if (const auto conflict = plannerConflict(entry.name, ss.getOptimizationObjective().get(), *ss.getStateSpace())) {
    throw InputError(source + ": " + *conflict);
  }
  const ob::SpaceInformationPtr& si = ss.getSpaceInformation();
  ob::PlannerPtr planner = makePlanner(entry.name, si);
  if (!planner) throw InputError(source + ": no planner named '" + entry.name + "'");
  const std::vector<std::string> warnings = configurePlanner(*planner, entry.name, entry.parameters);
  for (const std::string& w : warnings) {
    if (warn) std::cerr << "adsd benchmark: warning: " << w << '\n';
  }
  return planner;
}

/// \brief One problem to benchmark, of either kind: what the shared machinery needs of it.
struct BenchmarkInput {
  std::string path;  ///< the .cfg as given
  std::string name;
  std::string kind;  ///< "SE(2)", "SE(3)" or "arm ROBOT-FILE-STEM"
  std::vector<PlannerEntry> planners;
  unsigned runCount = kArmRunCount;  ///< without --runs or --run-range
  ot::Benchmark::Request request;    ///< maxTime, maxMem and simplify set; the rest benchmarkOne's
  std::optional<std::string> output;  ///< the file's output directory
  std::optional<SourceLocation> outputLocation;  ///< the problem file's `output` line, if it named it
  /// A problem for one checker × motion validator.
  std::function<std::unique_ptr<BenchmarkedProblem>(const CheckingOptions&)> make;
};

/// PlannerEntry for a --planner name.
std::vector<PlannerEntry> plannersNamed(const std::vector<std::string>& names) {
  std::vector<PlannerEntry> entries;
  for (const std::string& n : names) {
    PlannerEntry entry;
    entry.name = n;
    entry.label = n;
    entries.push_back(entry);
  }
  return entries;
}

/// An OMPL.app problem file (problem_file.h).
BenchmarkInput rigidInput(const BenchmarkArguments& a, const std::string& path) {
  auto file = std::make_shared<const ProblemFile>(readProblemFile(path));
  for (const std::string& w : file->warnings) std::cerr << "adsd benchmark: warning: " << w << '\n';
  if (file->benchmark.savePaths && *file->benchmark.savePaths != "none") {
    std::cerr << "adsd benchmark: warning: " << file->benchmark.savePathsLocation.describe()
              << ": saving paths is not supported, ignored\n";
  }
  const ot::Benchmark::Request defaults;
  BenchmarkInput in;
  in.path = path;
  in.name = file->name;
  in.kind = file->space == RigidBodySpace::se2 ? "SE(2)" : "SE(3)";
  in.planners = a.planners.empty() ? plannersOf(*file) : plannersNamed(a.planners);
  in.runCount = static_cast<unsigned>(file->benchmark.runCount.value_or(static_cast<int>(defaults.runCount)));
  in.request.maxTime = a.seconds.value_or(file->benchmark.timeLimit.value_or(defaults.maxTime));
  in.request.maxMem = file->benchmark.memoryLimit.value_or(defaults.maxMem);
  // A path planned for clearance is measured as planned, as adsd plan keeps it, unless the file
  // asks for simplification: OMPL's simplifier shortens it back towards the obstacles, and the run
  // recorded the shortcut's clearance (the maze: 5 of 8 RRT* paths "in contact" where the planner's
  // least clearance was 0.128; an outside review).
  const bool forClearance = file->objective == ObjectiveKind::maxMinClearance;
  in.request.simplify = file->benchmark.simplify.value_or(forClearance ? false : defaults.simplify);
  in.output = file->benchmark.output;
  if (in.output) in.outputLocation = file->benchmark.outputLocation;
  in.make = [file](const CheckingOptions& options) {
    return std::make_unique<BenchmarkedProblemOf<PlanningProblem>>(*file, options);
  };
  return in;
}

/// An arm problem `.cfg` (arm_planning_problem.h).
BenchmarkInput armInput(const BenchmarkArguments& a, const std::string& path) {
  auto file = std::make_shared<const MotionBenchMakerProblem>(readMotionBenchMakerProblem(path));
  for (const std::string& w : file->warnings) std::cerr << "adsd benchmark: warning: " << w << '\n';
  const ot::Benchmark::Request defaults;
  BenchmarkInput in;
  in.path = path;
  in.name = file->name;
  in.kind = "arm " + fs::path(file->robotPath).stem().string();
  in.planners = plannersNamed(a.planners.empty() ? std::vector<std::string>{"rrtconnect"} : a.planners);
  in.runCount = kArmRunCount;
  // The request's allowed_planning_time; a request that cannot be read is reported by the problem,
  // which is built before any run (naming the cfg's line for a missing file).
  std::optional<double> allowed;
  std::error_code ec;
  if (!a.seconds && fs::is_regular_file(file->requestPath, ec)) {
    allowed = readMotionPlanRequestYaml(file->requestPath).allowedPlanningTime;
  }
  in.request.maxTime = a.seconds.value_or(allowed.value_or(kArmTimeLimit));
  in.request.maxMem = defaults.maxMem;
  in.request.simplify = defaults.simplify;
  in.make = [file](const CheckingOptions& options) {
    return std::make_unique<BenchmarkedProblemOf<ArmPlanningProblem>>(*file, options);
  };
  return in;
}

/// Adds every `problem.cfg` under \p directory to \p found. Linked folders are followed (a
/// problem set assembled from links to a dataset's folders), each real folder once, the first
/// met in name order: a link back up (a loop) or a second link to one folder is not entered again.
void collectProblemFiles(const fs::path& directory, std::set<fs::path>& entered, std::vector<std::string>& found) {
  std::error_code ec;
  std::vector<fs::directory_entry> entries;
  for (fs::directory_iterator it(directory, ec), end; !ec && it != end; it.increment(ec)) entries.push_back(*it);
  if (ec) throw InputError(directory.string() + ": cannot list the directory: " + ec.message());
  std::sort(entries.begin(), entries.end(),
            [](const fs::directory_entry& x, const fs::directory_entry& y) { return x.path() < y.path(); });
  for (const fs::directory_entry& e : entries) {
    std::error_code entry;
    if (e.is_directory(entry)) {
      const fs::path real = fs::canonical(e.path(), entry);
      if (!entry && entered.insert(real).second) collectProblemFiles(e.path(), entered, found);
    } else if (e.path().filename() == "problem.cfg" && e.is_regular_file(entry)) {
      found.push_back(e.path().string());
    }
  }
}

/// The problems \p a names: a problem file (either kind), or every `problem.cfg` under a
/// directory, in path order (each an arm problem).
std::vector<BenchmarkInput> inputsOf(const BenchmarkArguments& a) {
  std::error_code ec;
  if (!fs::is_directory(a.problem, ec)) {
    return {isArmProblemFile(a.problem) ? armInput(a, a.problem) : rigidInput(a, a.problem)};
  }
  std::vector<std::string> found;
  std::set<fs::path> entered{fs::canonical(a.problem, ec)};
  if (ec) throw InputError(a.problem + ": cannot list the directory: " + ec.message());
  collectProblemFiles(a.problem, entered, found);
  std::sort(found.begin(), found.end());
  if (found.empty()) throw InputError(a.problem + ": no problem.cfg under this directory");
  std::vector<BenchmarkInput> inputs;
  for (const std::string& path : found) {
    if (!isArmProblemFile(path)) {
      throw InputError(path + ": not an arm problem (no 'request' key in [problem]); a directory holds arm problems");
    }
    inputs.push_back(armInput(a, path));
  }
  return inputs;
}

/// The external tools the database and plots need (empty with --log-only).
struct Tools {
  std::string statistics;
  std::string plotter;
};

/// The problem and planners of every combination of checker and motion validator that \p a asks
/// for, for \p input: building them reads every file and checks every planner, so that what is
/// wrong with the input stops the command before a run. Prints the problem's warnings.
std::vector<std::unique_ptr<Combination>> buildCombinations(const BenchmarkArguments& a, const BenchmarkInput& input) {
  std::vector<std::unique_ptr<Combination>> combinations;
  for (const CheckerKind checker : a.checkers) {
    for (const MotionKind motion : a.motions) {
      auto c = std::make_unique<Combination>();
      c->checker = checker;
      c->motion = motion;
      CheckingOptions options;
      options.checker = checker;
      options.motion = motion;
      c->problem = input.make(options);
      const bool first = combinations.empty();
      if (first) {
        for (const std::string& w : c->problem->warnings()) std::cerr << "adsd benchmark: warning: " << w << '\n';
      }
      c->benchmark = std::make_unique<ot::Benchmark>(c->problem->setup(), input.name);
      Combination* self = c.get();
      // Instances under one name (the format repeats a planner's line for each, with other
      // parameters) are told apart by a number: under one name, the summary and the plots merged
      // their runs into one row (an outside review).
      std::map<std::string, int> instances;
      for (const PlannerEntry& entry : input.planners) {
        ob::PlannerPtr planner = makeConfiguredPlanner(entry, c->problem->setup(), first);
        std::string name = entry.label != entry.name ? entry.label : planner->getName();
        if (const int k = ++instances[name]; k > 1) {
          const std::string numbered = name + " #" + std::to_string(k);
          if (first) {
            const std::string where = entry.location.file.empty() ? "--planner" : entry.location.describe();
            std::cerr << "adsd benchmark: warning: " << where
                      << ": another instance named '" << name << "': its results are named '" << numbered
                      << "' (`" << entry.name << ".name = ...` names it)\n";
          }
          name = numbered;
        }
        const std::string label = name + " [" + c->label() + "]";
        c->benchmark->addPlanner(
            std::make_shared<MeasuredPlanner>(planner, label, input.request.maxTime,
                                              [self](double seconds) { captureQueries(*self, seconds); }));
      }
      combinations.push_back(std::move(c));
    }
  }
  return combinations;
}

/// The directory and file stem of \p input's log, database and plots.
std::pair<fs::path, std::string> outputNames(const BenchmarkArguments& a, const BenchmarkInput& input) {
  const fs::path directory = a.outDirectory ? fs::path(*a.outDirectory)
                                            : (input.output ? fs::path(*input.output) : fs::path("."));
  std::string stem = fileStem(input.name);
  if (a.runRange) stem += ".runs-" + std::to_string(a.runRange->first) + "-" + std::to_string(a.runRange->second);
  if (a.seed) stem += ".seed-" + std::to_string(*a.seed);
  return {directory, stem};
}

/// Benchmarks one problem, its \p combinations built by buildCombinations: runs, log, database and
/// plots.
void benchmarkOne(const BenchmarkArguments& a, const BenchmarkInput& input,
                  std::vector<std::unique_ptr<Combination>> combinations, const Tools& tools,
                  const std::optional<std::uint64_t>& seed) {
  // Which runs.
  const unsigned firstRun = a.runRange ? a.runRange->first : 0;
  const unsigned runCount = a.runRange ? a.runRange->second - a.runRange->first : a.runs.value_or(input.runCount);

  ot::Benchmark::Request request = input.request;
  request.runCount = 1;  // one run per call: the combinations take turns run by run
  request.displayProgress = false;
  request.saveConsoleOutput = false;  // OMPL would write ompl_HOST_DATE.console into the current directory

  const std::vector<PlannerEntry>& entries = input.planners;
  unsigned currentRun = 0;
  std::unique_ptr<ProgressBar> progress;
  for (const std::unique_ptr<Combination>& c : combinations) {
    Combination* self = c.get();
    c->benchmark->setPreRunEvent([self, &currentRun, &progress, runCount](const ob::PlannerPtr& planner) {
      // Benchmark has just reset the discrete validator's counters; ours are reset here.
      self->problem->resetCounts();
      self->atSolveEnd = RunQueries{};
      progress->starting("run " + std::to_string(currentRun + 1) + "/" + std::to_string(runCount) + "  " +
                         planner->getName());
    });
    c->benchmark->setPostRunEvent([self, &currentRun, &progress, firstRun](const ob::PlannerPtr& planner,
                                                                          ot::Benchmark::RunProperties& run) {
      addRunProperties(*self, firstRun + currentRun, run);
      addPathContact(*self, *planner, run);
      progress->finished();
    });
  }

  const auto [directory, stem] = outputNames(a, input);
  // The longest name written is a spool's, STEM.log.PID-K.progress (about 30 bytes more than the
  // stem): a name that only fits without them failed after every run was done (an adversarial
  // review), so it is refused before the first.
  constexpr std::size_t kLongestSuffix = 40, kNameMax = 255;
  if (stem.size() + kLongestSuffix > kNameMax) {
    throw InputError(input.path + ": the problem's name makes output files named '" + stem.substr(0, 20) + "...' of " +
                     std::to_string(stem.size()) + " bytes and more; the benchmark's files add up to " +
                     std::to_string(kLongestSuffix) + " bytes to it, and a name may have " + std::to_string(kNameMax) +
                     ": shorten the name (at most " + std::to_string(kNameMax - kLongestSuffix) + " bytes)");
  }
  // Named where it came from: --out, or the problem file's `output` line.
  const std::string source = a.outDirectory || !input.outputLocation ? "--out" : input.outputLocation->describe();
  std::error_code error;
  // The directory itself is made, as mkdir makes it, but not a missing parent: a mistyped name
  // (--out /nonexistent/dir) made a tree at the root and filled it.
  fs::path whole = fs::absolute(directory, error).lexically_normal();
  if (!whole.has_filename()) whole = whole.parent_path();  // "results/"
  const fs::path parent = whole.parent_path();
  if (!error && !fs::exists(directory, error) && !fs::is_directory(parent, error)) {
    throw InputError(source + ": cannot make directory '" + directory.string() + "': directory '" + parent.string() +
                     "' does not exist");
  }
  error.clear();
  if (fs::exists(directory, error) && !fs::is_directory(directory, error)) {
    throw InputError(source + ": '" + directory.string() + "' is a file, not a directory to write the results in");
  }
  error.clear();
  if (cli::inSystemTree((directory / (stem + ".log")).string())) {
    throw InputError(source + ": '" + directory.string() + "' is in /dev, /proc or /sys, not a directory to write the results in");
  }
  const bool made = fs::create_directory(directory, error);
  if (error || !fs::is_directory(directory) || ::access(directory.c_str(), W_OK) != 0) {
    throw InputError(source + ": cannot write in directory '" + directory.string() + "'" +
                     (error ? ": " + error.message() : std::string(" (not a writable directory)")));
  }
  PlannerWatchdog::outputDirectoryMade(made ? directory : fs::path());  // not an earlier problem's
  const fs::path logPath = directory / (stem + ".log");
  const fs::path databasePath = directory / (stem + ".db");
  // Every file this writes is renamed over its name at the end: a directory there would fail it
  // after the runs (the plots' names are the plotting script's, stem.*.png).
  for (const fs::path& output : {logPath, databasePath, directory / (stem + ".summary.md")}) {
    if (fs::is_directory(output, error)) {
      throw InputError("--out: '" + output.string() + "' is a directory, where the benchmark writes a file");
    }
  }

  const std::size_t plannerCount = entries.size();
  std::printf("benchmark   %s (%s, %s): %zu planner(s) x %zu combination(s) x %u run(s)%s, %g s and %g MB per run\n",
              input.name.c_str(), input.kind.c_str(), input.path.c_str(), plannerCount, combinations.size(), runCount,
              a.runRange ? (" (runs " + std::to_string(firstRun) + " to " + std::to_string(firstRun + runCount - 1) + ")").c_str()
                         : "",
              request.maxTime, request.maxMem);
  std::printf("seed        %llu%s\n", static_cast<unsigned long long>(ompl::RNG::getSeed()),
              seed ? (a.seed ? " (--seed)" : " (first run + 1)") : " (OMPL's choice)");
  std::fflush(stdout);
  // The runs. Combinations take turns run by run, starting one further along each time, so that a
  // machine that slows down or speeds up (other jobs on shared cores) affects all of them alike.
  // The log lists combination k's planners at k * plannerCount onwards: every combination's
  // planners side by side in one experiment.
  SpooledBenchmarkLog log(logPath);
  std::optional<ot::Benchmark::CompleteExperiment> experiment;  // the first run's, without planners
  progress = std::make_unique<ProgressBar>(static_cast<std::size_t>(runCount) * combinations.size() * plannerCount);
  const auto started = std::chrono::steady_clock::now();
  for (currentRun = 0; currentRun < runCount; ++currentRun) {
    for (std::size_t k = 0; k < combinations.size(); ++k) {
      const std::size_t index = (currentRun + k) % combinations.size();
      Combination& c = *combinations[index];
      c.benchmark->benchmark(request);
      const ot::Benchmark::CompleteExperiment& call = c.benchmark->getRecordedExperimentData();
      if (currentRun == 0) {
        c.setupInfo = call.setupInfo;
        if (index == 0) {
          experiment = call;
          experiment->planners.clear();
        }
      }
      log.append(index * plannerCount, call);
    }
  }
  progress->close();
  const double totalSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

  experiment->name = input.name;
  experiment->runCount = runCount;
  experiment->totalDuration = totalSeconds;
  experiment->seed = ompl::RNG::getSeed();
  experiment->setupInfo.clear();
  for (const auto& c : combinations) {
    experiment->setupInfo += "==== adsd benchmark: checker " + std::string(name(c->checker)) + ", motion validator " +
                             name(c->motion) + "\n" + c->setupInfo;
  }
  const std::size_t recorded = log.runCount();
  const std::size_t expected = static_cast<std::size_t>(runCount) * combinations.size() * plannerCount;
  if (recorded != expected) {
    std::cerr << "adsd benchmark: warning: " << expected - recorded << " of " << expected
              << " runs were not recorded (OMPL reported an error for them)\n";
  }
  if (recorded == 0) throw ToolFailure("no run was recorded");

  log.write(*experiment);
  std::printf("log         %s (%zu runs in %.1f s)\n", logPath.c_str(), recorded, totalSeconds);
  if (a.logOnly) return;

  // The database, through a temporary name: ompl_benchmark_statistics writes it in place.
  const std::string temporaryDatabase = databasePath.string() + ".tmp";
  fs::remove(temporaryDatabase, error);
  const std::vector<std::string> convert = {tools.statistics, logPath.string(), "-d", temporaryDatabase};
  if (runProgram(convert, true) != 0 || !fs::is_regular_file(temporaryDatabase)) {
    fs::remove(temporaryDatabase, error);
    throw ToolFailure("'" + commandLine(convert) + "' failed");
  }
  fs::rename(temporaryDatabase, databasePath, error);
  if (error) {
    std::error_code ignored;
    fs::remove(temporaryDatabase, ignored);
    throw ToolFailure("cannot write '" + databasePath.string() + "': " + error.message());
  }
  std::printf("database    %s\n", databasePath.c_str());
  std::fflush(stdout);

  std::vector<std::string> draw = {kPython, tools.plotter, databasePath.string(), "--out", directory.string(), "--prefix", stem};
  if (!a.plots) draw.push_back("--no-plots");
  if (runProgram(draw, false) != 0) throw ToolFailure("'" + commandLine(draw) + "' failed");
}

int benchmark(const std::vector<std::string>& args) {
  const std::optional<BenchmarkArguments> parsed = parseArguments(args);
  if (!parsed) return 0;  // the help
  const BenchmarkArguments& a = *parsed;
  // Every problem's files read before any run (each problem's checkers are built before its runs).
  const std::vector<BenchmarkInput> inputs = inputsOf(a);

  // The tools first: a missing one must stop us before the runs, not after them.
  Tools tools;
  tools.plotter = ADSD_PLOT_BENCHMARK_SCRIPT;
  if (!a.logOnly) {
    std::optional<std::string> found;
    for (const char* name : kStatisticsPrograms) {
      if (!found) found = findOnPath(name);
    }
    if (!found) {
      throw ToolFailure(std::string(kStatisticsPrograms[0]) + " (or " + kStatisticsPrograms[1] +
                        ", as OMPL's own install names it) is not on PATH (Debian package ompl-demos); --log-only "
                        "writes the log without it");
    }
    tools.statistics = *found;
    if (::access(kPython, X_OK) != 0) throw ToolFailure(std::string(kPython) + " is missing (Debian package python3)");
    if (tools.plotter.empty() || !fs::is_regular_file(tools.plotter)) {
      throw ToolFailure("the plotting script, which writes the summary too, is missing" +
                        (tools.plotter.empty()
                             ? std::string(" (no share/adsd/plot_benchmark.py in the prefix this program runs from)")
                             : " ('" + tools.plotter + "')") +
                        "; --log-only writes the log without it");
    }
  }

  // The seed: set before anything draws a random number (OMPL seeds every new generator from one
  // seeded generator).
  std::optional<std::uint64_t> seed = a.seed;
  if (!seed && a.runRange) seed = a.runRange->first + kShardSeedOffset;
  if (seed) ompl::RNG::setSeed(static_cast<std::uint_fast32_t>(*seed));
  // Several problems (a directory): each one's outputs must have a name of their own.
  if (inputs.size() > 1) {
    std::map<fs::path, const BenchmarkInput*> byOutput;
    for (const BenchmarkInput& input : inputs) {
      const auto [directory, stem] = outputNames(a, input);
      const auto [it, added] = byOutput.emplace(fs::absolute(directory / stem).lexically_normal(), &input);
      if (!added) {
        throw InputError(input.path + ": its results would overwrite those of " + it->second->path + " (named '" +
                         input.name + "' and '" + it->second->name + "', both written as '" + stem +
                         "': give each problem its own `name =` in [problem])");
      }
    }
  }
  // Every problem is built, with its planners, before any run and before any file is written:
  // what is wrong with any of them (a bad file, a planner the space cannot take) stops the command
  // first.
  std::vector<std::vector<std::unique_ptr<Combination>>> built;
  for (const BenchmarkInput& input : inputs) built.push_back(buildCombinations(a, input));
  for (std::size_t i = 0; i < inputs.size(); ++i) benchmarkOne(a, inputs[i], std::move(built[i]), tools, seed);
  return 0;
}

}  // namespace

/// \brief Entry point of `adsd benchmark`; \p args are the arguments after "benchmark".
int benchmarkCommand(const std::vector<std::string>& args) {
  ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
  return reportingErrors("adsd benchmark", [&] {
    // A tool the benchmark runs failed (ompl_benchmark_statistics, the plotter): an error of the
    // run, not of its input, so exit status 1.
    try {
      return benchmark(args);
    } catch (const ToolFailure& e) {
      std::cerr << "adsd benchmark: error: " << e.what() << '\n';
      return 1;
    }
  });
}

}  // namespace adsd::app
