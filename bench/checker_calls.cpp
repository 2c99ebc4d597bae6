// bench_checker_calls: what a planner pays per validity check or clearance query, ours against
// FCL's, without the planner. For each problem file, both checkers are set up as `adsd plan` sets them up (the
// environment split into parts, the shared broad phase, our sub-mesh trees or FCL's OBBRSS
// models), the same states are drawn, and StateValidityChecker::isValid (or, with --clearance,
// clearance) is timed on them in blocks, the two checkers interleaved block by block in
// alternating order. It isolates the checker's term of the planning rows (issue 6), whose solve
// times also hold the planner's own work and, for PRM, its threads' timing.
//
//   bench_checker_calls [--states N] [--seed S] [--from uniform|rrtconnect|prm|rrtstar...] [--clearance]
//                       PROBLEM.cfg...
//
// --clearance: the exact clearance query instead of the validity check, on the same states for
// both checkers (clearance_query_ratios.py times it in planning runs, whose states differ between
// the checkers once their answers do). With --from PLANNER the planner runs with the clearance
// objective (MaximizeMinClearanceObjective) for up to 2 s per solve, as in those runs, and the
// states it asks clearance for are kept. The two answers must agree to 1e-9 of the scene's size
// (FCL's distance is exact up to roundoff too): states where they do not are counted.
//
// The states: seeded uniform states of the problem's space (--from uniform, the default), or the
// states a planner checks, in the order it checks them: the planner solves the problem again and
// again with FCL's checker, stopping at its first solution as in the planning rows, and every
// state it hands the checker (motion checks included) is kept until there are N. Uniform states
// are mostly far from every obstacle; a planner's cluster along its motions, many of them near or
// in contact, which cost both checkers more and in other proportions.
//
// Prints per problem: median microseconds per check over the blocks for each checker, ours ÷ FCL,
// the share of states each found valid (with --clearance: in contact, distance 0) and the number
// of states on which they disagree (expected 0: a state touches an obstacle exactly with
// probability 0). Exit status 0; 2 on bad usage or a problem that cannot be set up; 3 when the
// checkers disagree on some state.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include <ompl/base/StateValidityChecker.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include "adsd/cli/command_line.h"
#include "adsd/planner/planner_registry.h"
#include "adsd/planner/planning_problem.h"
#include "timing.h"

namespace {

using adsd::bench::median;
using adsd::bench::microsecondsOf;
using adsd::planner::CheckerKind;
using adsd::planner::CheckingOptions;
using adsd::planner::PlanningProblem;

/// States per timed block: long enough that the clock's own cost (tens of ns) is noise, short
/// enough for many blocks, whose median resists the machine's other load.
constexpr std::size_t kBlockStates = 1000;

/// Time limit of one solve while states are recorded (seconds): a solve that reaches it still
/// gave its states.
constexpr double kRecordingSolveSeconds = 10.0;

/// Solves after which recording stops even with fewer states than asked for (a planner that
/// checks almost nothing per solve would otherwise loop for long).
constexpr int kMaxRecordingSolves = 10000;

/// Time limit of one clearance-objective solve while its states are recorded (seconds): the
/// planning runs' (bench/planning/clearance_query_ratios.py --time 2); RRT* refines its tree for
/// all of it.
constexpr double kClearanceSolveSeconds = 2.0;

/// Two clearances agree when they differ by at most this fraction of the scene's size.
constexpr double kClearanceAgreement = 1e-9;

struct Options {
  std::size_t states = 100000;
  unsigned long seed = 1;
  std::string from = "uniform";  // or a planner's name
  bool clearance = false;        // time clearance() instead of isValid()
  std::vector<std::string> problems;
};

/// \brief Passes every check to another checker and keeps a copy of each state checked (or each
/// state asked for clearance), up to a limit. Planners may check from several threads (PRM),
/// hence the lock; its cost is the planner's, and only the replay is timed.
class RecordingChecker final : public ompl::base::StateValidityChecker {
 public:
  RecordingChecker(const ompl::base::SpaceInformationPtr& si, std::shared_ptr<ompl::base::StateValidityChecker> inner,
                   std::size_t limit, bool clearanceStates)
      : ompl::base::StateValidityChecker(si), inner_(std::move(inner)), limit_(limit),
        clearanceStates_(clearanceStates) {
    specs_ = inner_->getSpecs();
  }
  ~RecordingChecker() override {
    for (ompl::base::State* s : states_) si_->freeState(s);
  }

  bool isValid(const ompl::base::State* state) const override {
    if (!clearanceStates_) record(state);
    return inner_->isValid(state);
  }
  bool isValid(const ompl::base::State* state, double& dist) const override {
    if (clearanceStates_) record(state);
    return inner_->isValid(state, dist);
  }
  double clearance(const ompl::base::State* state) const override {
    if (clearanceStates_) record(state);
    return inner_->clearance(state);
  }
  std::size_t recorded() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return states_.size();
  }
  /// Hands the recorded states over (the caller frees them).
  std::vector<ompl::base::State*> take() {
    std::lock_guard<std::mutex> lock(mutex_);
    return std::move(states_);
  }

 private:
  void record(const ompl::base::State* state) const {
    std::lock_guard<std::mutex> lock(mutex_);
    if (states_.size() < limit_) states_.push_back(si_->cloneState(state));
  }

  std::shared_ptr<ompl::base::StateValidityChecker> inner_;
  std::size_t limit_;
  bool clearanceStates_;
  mutable std::mutex mutex_;
  mutable std::vector<ompl::base::State*> states_;
};

/// The first \p count states \p plannerName checks on \p problem (set up with FCL's checker),
/// over as many solves as that takes; each solve stops at its first solution. With
/// \p clearanceStates, the states it asks clearance for instead, each solve optimizing the
/// problem's objective (the clearance objective) for kClearanceSolveSeconds.
std::vector<ompl::base::State*> plannerStates(adsd::planner::PlanningProblem& problem, const std::string& plannerName,
                                              std::size_t count, bool clearanceStates) {
  ompl::geometric::SimpleSetup& setup = problem.setup();
  const auto& si = problem.spaceInformation();
  auto recorder = std::make_shared<RecordingChecker>(si, problem.checker(), count, clearanceStates);
  setup.setStateValidityChecker(recorder);
  ompl::base::PlannerPtr planner = adsd::planner::makePlanner(plannerName, si);
  if (!planner) throw std::runtime_error("no planner named '" + plannerName + "'");
  setup.setPlanner(planner);
  // Any path meets the length objective, so that optimizing roadmaps (PRM) stop at their first
  // solution, as in the planning rows (bench/planning/solve_time_ratios.py). The clearance
  // objective keeps its threshold, which no path meets: RRT* refines for the whole limit.
  if (!clearanceStates) {
    setup.getProblemDefinition()->getOptimizationObjective()->setCostThreshold(
        ompl::base::Cost(std::numeric_limits<double>::infinity()));
  }
  for (int solve = 0; solve < kMaxRecordingSolves && recorder->recorded() < count; ++solve) {
    setup.clear();
    setup.solve(clearanceStates ? kClearanceSolveSeconds : kRecordingSolveSeconds);
  }
  setup.setStateValidityChecker(problem.checker());
  return recorder->take();
}

adsd::cli::CommandLine commandLine() {
  adsd::cli::CommandLine line(
      "bench_checker_calls",
      "bench_checker_calls [--states N] [--seed S] [--from uniform|rrtconnect|prm|...] [--clearance] PROBLEM.cfg...",
      "Times StateValidityChecker::isValid (or clearance), ours against FCL's checker, on the same states of each "
      "problem.",
      "Exit status 0; 2 on bad usage or a problem that cannot be set up; 3 when the checkers disagree on some state.");
  line.options()
      ("states", adsd::cli::value("N"), "states per problem, at least 1000 (default 100000)")
      ("seed", adsd::cli::value("S"), "OMPL's random seed, 1 to 4294967295 (default 1)")
      ("from", adsd::cli::value("uniform|PLANNER"),
       "uniform states (default), or the states a planner (rrtconnect, prm, ...) checks, in its order")
      ("clearance", "time the exact clearance query instead of the validity check (with --from PLANNER: the "
                    "states the planner asks clearance for, optimizing clearance)");
  line.positional("problem");
  return line;
}

Options parse(const adsd::cli::Arguments& given) {
  Options o;
  o.states = given.whole("states", kBlockStates, std::numeric_limits<std::size_t>::max()).value_or(o.states);
  o.seed = given.whole("seed", 1, std::numeric_limits<std::uint32_t>::max()).value_or(o.seed);
  o.from = given.text("from").value_or(o.from);
  const auto& planners = adsd::planner::knownPlannerNames();
  if (o.from != "uniform" && std::find(planners.begin(), planners.end(), o.from) == planners.end()) {
    throw adsd::cli::UsageError("--from: expected uniform or a planner's name (rrtconnect, prm, ...), got '" + o.from +
                                "'");
  }
  o.clearance = given.has("clearance");
  o.problems = given.texts("problem");
  if (o.problems.empty()) throw adsd::cli::UsageError("no problem file given");
  return o;
}

int run(const Options& options) {
  ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
  // Once, before OMPL makes any generator: every sampler's seed then follows from it, so a command
  // (its problems in its order) always draws the same states.
  ompl::RNG::setSeed(options.seed);
  const bool uniform = options.from == "uniform";
  const char* const call = options.clearance ? "exact clearance" : "isValid";
  const std::string source =
      uniform ? "uniform states"
              : options.clearance ? "the states " + options.from +
                                        " asks clearance for, optimizing clearance, in its order, solve after solve"
                                  : "the states " + options.from + " checks, in its order, solve after solve";
  std::printf("Median microseconds per %s call over blocks of %zu states (%zu states, seed %lu): %s;\n"
              "the two checkers interleaved block by block; both share the broad phase over environment parts.\n",
              call, kBlockStates, options.states, options.seed, source.c_str());
  std::printf("%-18s %12s %12s %10s %12s %12s\n", "problem", "ours us", "fcl us", "ratio",
              options.clearance ? "free share" : "valid share", "disagree");
  bool disagreement = false;
  for (const std::string& path : options.problems) {
    try {
      const adsd::planner::ProblemFile file = adsd::planner::readProblemFile(path);
      CheckingOptions ours, fcl;
      ours.checker = CheckerKind::adsd;
      fcl.checker = CheckerKind::fcl;
      if (options.clearance) ours.objective = fcl.objective = adsd::planner::ObjectiveKind::maxMinClearance;
      PlanningProblem withOurs(file, ours), withFcl(file, fcl);
      const auto& si = withOurs.spaceInformation();

      std::vector<ompl::base::State*> states;
      // Recorded states come from FCL's problem (both problems have the same space, so its states
      // serve both); each state is freed by the space that allocated it.
      const ompl::base::SpaceInformationPtr& owner = uniform ? si : withFcl.spaceInformation();
      if (uniform) {
        auto sampler = si->allocStateSampler();
        states.resize(options.states);
        for (ompl::base::State*& s : states) {
          s = si->allocState();
          sampler->sampleUniform(s);
        }
      } else {
        states = plannerStates(withFcl, options.from, options.states, options.clearance);
      }
      const std::size_t blocks = states.size() / kBlockStates;
      for (std::size_t i = blocks * kBlockStates; i < states.size(); ++i) owner->freeState(states[i]);
      states.resize(blocks * kBlockStates);
      if (blocks == 0) throw std::runtime_error(file.name + ": fewer than " + std::to_string(kBlockStates) + " states");
      std::vector<char> validOurs(states.size()), validFcl(states.size());
      std::vector<double> clearanceOurs(options.clearance ? states.size() : 0),
          clearanceFcl(options.clearance ? states.size() : 0);
      std::vector<double> microsOurs, microsFcl;
      auto runBlock = [&](const PlanningProblem& problem, std::size_t b, std::vector<char>& valid,
                          std::vector<double>& clearance) {
        const auto& checker = *problem.checker();
        const std::size_t first = b * kBlockStates, last = (b + 1) * kBlockStates;
        if (options.clearance) {
          const double micros =
              microsecondsOf([&] { for (std::size_t i = first; i < last; ++i) clearance[i] = checker.clearance(states[i]); });
          for (std::size_t i = first; i < last; ++i) valid[i] = clearance[i] > 0.0;
          return micros;
        }
        return microsecondsOf([&] { for (std::size_t i = first; i < last; ++i) valid[i] = checker.isValid(states[i]); });
      };
      for (std::size_t b = 0; b < blocks; ++b) {
        if (b % 2 == 0) {
          microsOurs.push_back(runBlock(withOurs, b, validOurs, clearanceOurs));
          microsFcl.push_back(runBlock(withFcl, b, validFcl, clearanceFcl));
        } else {
          microsFcl.push_back(runBlock(withFcl, b, validFcl, clearanceFcl));
          microsOurs.push_back(runBlock(withOurs, b, validOurs, clearanceOurs));
        }
      }
      std::size_t valid = 0, differ = 0;
      const double agreement = kClearanceAgreement * withOurs.spaceInformation()->getMaximumExtent();
      for (std::size_t i = 0; i < states.size(); ++i) {
        valid += validOurs[i] != 0;
        differ += validOurs[i] != validFcl[i] ||
                  (options.clearance && !(std::abs(clearanceOurs[i] - clearanceFcl[i]) <= agreement));
      }
      for (ompl::base::State* s : states) owner->freeState(s);
      const double usOurs = median(microsOurs) / kBlockStates, usFcl = median(microsFcl) / kBlockStates;
      std::printf("%-18s %12.3f %12.3f %10.3f %12.3f %12zu\n", file.name.c_str(), usOurs, usFcl, usOurs / usFcl,
                  static_cast<double>(valid) / static_cast<double>(states.size()), differ);
      disagreement = disagreement || differ > 0;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "bench_checker_calls: %s\n", e.what());  // InputError names the file
      return 2;
    }
  }
  return disagreement ? 3 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  return adsd::cli::runProgram(commandLine(), argc, argv,
                               [](const adsd::cli::Arguments& given) { return run(parse(given)); });
}
