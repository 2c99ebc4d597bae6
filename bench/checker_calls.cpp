// bench_checker_calls: what a planner pays per validity check, ours against FCL's, without the
// planner. For each problem file, both checkers are set up as `adsd plan` sets them up (the
// environment split into parts, the shared broad phase, our sub-mesh trees or FCL's OBBRSS
// models), the same seeded uniform states of the problem's space are drawn, and
// StateValidityChecker::isValid is timed on them in blocks, the two checkers interleaved block by
// block in alternating order. It isolates the checker's term of the planning rows (issue 6), whose
// solve times also hold the planner's own work and, for PRM, its threads' timing.
//
//   bench_checker_calls [--states N] [--seed S] PROBLEM.cfg...
//
// Prints per problem: median microseconds per check over the blocks for each checker, ours ÷ FCL,
// the share of states each found valid and the number of states on which they disagree (expected
// 0: uniform states touch an obstacle exactly with probability 0). Exit status 0; 2 on bad usage
// or a problem that cannot be set up; 3 when the checkers disagree on some state.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

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

struct Options {
  std::size_t states = 100000;
  unsigned long seed = 1;
  std::vector<std::string> problems;
};

[[noreturn]] void usage(const std::string& why) {
  std::fprintf(stderr, "bench_checker_calls: %s\nusage: bench_checker_calls [--states N] [--seed S] PROBLEM.cfg...\n",
               why.c_str());
  std::exit(2);
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--states" || arg == "--seed") {
      if (i + 1 >= argc) usage(arg + " needs a value");
      char* end = nullptr;
      const unsigned long value = std::strtoul(argv[++i], &end, 10);
      if (end == argv[i] || *end != '\0' || value == 0) usage(arg + " needs a positive integer, got '" + argv[i] + "'");
      (arg == "--states" ? o.states : o.seed) = value;
    } else if (!arg.empty() && arg[0] == '-') {
      usage("unknown option " + arg);
    } else {
      o.problems.push_back(arg);
    }
  }
  if (o.problems.empty()) usage("no problem file given");
  if (o.states < kBlockStates) usage("--states must be at least " + std::to_string(kBlockStates));
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  const Options options = parse(argc, argv);
  ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
  // Once, before OMPL makes any generator: every sampler's seed then follows from it, so a command
  // (its problems in its order) always draws the same states.
  ompl::RNG::setSeed(options.seed);
  std::printf("Median microseconds per isValid call over blocks of %zu uniform states (%zu states, seed %lu),\n"
              "the two checkers interleaved block by block; both share the broad phase over environment parts.\n",
              kBlockStates, options.states, options.seed);
  std::printf("%-18s %12s %12s %10s %12s %12s\n", "problem", "ours us", "fcl us", "ratio", "valid share", "disagree");
  bool disagreement = false;
  for (const std::string& path : options.problems) {
    try {
      const adsd::planner::ProblemFile file = adsd::planner::readProblemFile(path);
      CheckingOptions ours, fcl;
      ours.checker = CheckerKind::adsd;
      fcl.checker = CheckerKind::fcl;
      PlanningProblem withOurs(file, ours), withFcl(file, fcl);
      const auto& si = withOurs.spaceInformation();

      auto sampler = si->allocStateSampler();
      const std::size_t blocks = options.states / kBlockStates;
      std::vector<ompl::base::State*> states(blocks * kBlockStates);
      for (ompl::base::State*& s : states) {
        s = si->allocState();
        sampler->sampleUniform(s);
      }
      std::vector<char> validOurs(states.size()), validFcl(states.size());
      std::vector<double> microsOurs, microsFcl;
      auto runBlock = [&](const PlanningProblem& problem, std::size_t b, std::vector<char>& valid) {
        const auto& checker = *problem.checker();
        return microsecondsOf([&] {
          for (std::size_t i = b * kBlockStates; i < (b + 1) * kBlockStates; ++i) valid[i] = checker.isValid(states[i]);
        });
      };
      for (std::size_t b = 0; b < blocks; ++b) {
        if (b % 2 == 0) {
          microsOurs.push_back(runBlock(withOurs, b, validOurs));
          microsFcl.push_back(runBlock(withFcl, b, validFcl));
        } else {
          microsFcl.push_back(runBlock(withFcl, b, validFcl));
          microsOurs.push_back(runBlock(withOurs, b, validOurs));
        }
      }
      std::size_t valid = 0, differ = 0;
      for (std::size_t i = 0; i < states.size(); ++i) {
        valid += validOurs[i] != 0;
        differ += validOurs[i] != validFcl[i];
      }
      for (ompl::base::State* s : states) si->freeState(s);
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
