/// \file
/// \brief Arm problems: our checker against FCL's per state, and certified against discrete motion
/// checking per motion (issue 17's benchmark rows).
///
///   bench_arms [--problems DIR] [--only a,b] [--states N] [--motions M] [--step RADIANS] [--rounds R]
///              [--seed S] [--summary-md FILE] [--validity-alone]
///
/// For every arm problem (DIR/NAME/problem.cfg, MotionBenchMaker format; default: the shipped
/// problems/arm), both checkers sit behind one broad phase and one list of disabled link pairs
/// (ArmValidityCheckerBase), so what differs is the narrow phase alone: our distance queries or
/// FCL 0.7's (OBBRSS hierarchies, built once). On N joint vectors drawn uniformly within the
/// limits (valid and invalid, as a planner's sampler draws them) it times, interleaved state by
/// state (timing.h), each checker's validity check and its clearance (exact distance over every
/// checked pair). Every validity answer must equal FCL's and every clearance of a valid state
/// must agree with FCL's within 1e-9 of the scene's scale; the program exits 3 otherwise.
///
/// Motions: M motions from valid states, each joint moved by up to --step radians (a planner's
/// range), checked by OMPL's DiscreteMotionValidator (states at the space's resolution) and by
/// the certified ArmMotionValidator, both on our checker. Per motion: states the discrete one
/// checks, clearance queries the certified one makes, and microseconds. A motion the certified
/// validator accepts must be accepted by the discrete one too (exit 3 otherwise: it found a
/// colliding state on a motion proven free).
///
/// Prints one row per problem and a Markdown table (--summary-md) with the medians. With
/// --validity-alone, the two validity checks are also timed by themselves (interleaved with each
/// other only) before the four queries are timed together: the caches then hold what validity
/// checks leave, not what the clearance queries do; the medians go on a line after the table.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <ompl/base/DiscreteMotionValidator.h>
#include <ompl/base/SpaceInformation.h>

#include "adsd/cli/command_line.h"
#include "adsd/error.h"
#include "adsd/planner/arm_motion_validator.h"
#include "adsd/planner/arm_planning_problem.h"
#include "adsd/planner/arm_state_space.h"
#include "adsd/planner/arm_validity_checker.h"
#include "adsd/planner/fcl_arm_validity_checker.h"
#include "adsd/planner/motion_bench_maker_problem.h"
#include "scenes/seeded_random.h"
#include "timing.h"

#ifndef ADSD_ARM_PROBLEMS_DIR
#define ADSD_ARM_PROBLEMS_DIR ""
#endif

namespace {

namespace ob = ompl::base;
namespace ap = adsd::planner;
namespace fs = std::filesystem;

struct Options {
  std::string problems = ADSD_ARM_PROBLEMS_DIR;
  std::vector<std::string> only;
  std::size_t states = 300;
  std::size_t motions = 100;
  double step = 0.3;
  int rounds = 3;
  std::uint64_t seed = 1717;
  std::string summaryMarkdown;
  bool validityAlone = false;
};

/// What one problem measured (medians in microseconds).
struct ProblemRow {
  std::string name;
  std::size_t dof = 0, links = 0, obstacles = 0, selfPairs = 0;
  double validShare = 0.0;
  double oursValid = 0, fclValid = 0, oursClear = 0, fclClear = 0;
  double oursValidAlone = 0, fclValidAlone = 0;  // --validity-alone
  double discreteChecks = 0, certifiedQueries = 0;  // per motion (means)
  double discreteMicros = 0, certifiedMicros = 0;   // per motion (medians)
  std::size_t motionsAccepted[2] = {0, 0};          // discrete, certified
};

adsd::cli::CommandLine commandLine() {
  adsd::cli::CommandLine line(
      "bench_arms",
      "bench_arms [--problems DIR] [--only a,b] [--states N] [--motions M] [--step RADIANS] [--rounds R] [--seed S]\n"
      "           [--summary-md FILE] [--validity-alone]",
      "Arm problems: our checker against FCL's per state (validity, clearance), certified against discrete motion "
      "checking per motion.",
      "Exit status: 0, 2 for a bad command line or a broken problem (the others are still measured), 3 when an answer disagrees with FCL's or a certified "
      "motion is found colliding.");
  line.options()("problems", adsd::cli::value("DIR"),
                 "directory of arm problems, DIR/NAME/problem.cfg (default: the shipped problems/arm)")(
      "only", adsd::cli::value("LIST"), "only these problems (names), comma-separated")(
      "states", adsd::cli::value("N"), "uniform joint vectors per problem (default 300)")(
      "motions", adsd::cli::value("M"), "motions per problem (default 100)")(
      "step", adsd::cli::value("RADIANS"), "largest change of a joint along a motion (default 0.3)")(
      "rounds", adsd::cli::value("R"), "timed rounds (default 3)")(
      "seed", adsd::cli::value("S"), "seed of the draws (default 1717)")(
      "summary-md", adsd::cli::value("FILE"), "also write the table as Markdown")(
      "validity-alone", "also time the validity checks by themselves, not interleaved with the clearance queries");
  return line;
}

Options optionsFrom(const adsd::cli::Arguments& given) {
  Options o;
  o.problems = given.text("problems").value_or(o.problems);
  if (o.problems.empty()) throw adsd::cli::UsageError("--problems: no default problem directory in this build; give one");
  if (const auto list = given.text("only")) {
    std::string item;
    for (char c : *list + ",") {
      if (c != ',') {
        item += c;
      } else if (!item.empty()) {
        o.only.push_back(item);
        item.clear();
      }
    }
  }
  o.states = given.whole("states", 1, 1000000).value_or(o.states);
  o.motions = given.whole("motions", 0, 1000000).value_or(o.motions);
  o.step = given.real("step", adsd::cli::RealInterval::above(0.0).below(10.0)).value_or(o.step);
  o.rounds = static_cast<int>(given.whole("rounds", 1, 1000).value_or(static_cast<std::uint64_t>(o.rounds)));
  o.seed = given.whole("seed").value_or(o.seed);
  o.summaryMarkdown = given.text("summary-md").value_or("");
  o.validityAlone = given.has("validity-alone");
  return o;
}

/// A joint vector drawn uniformly within the limits (a continuous joint over [-pi, pi)).
std::vector<double> uniformJoints(const ap::ArmModel& model, adsd::bench::SeededRandom& random) {
  std::vector<double> q(model.dof());
  for (std::size_t i = 0; i < q.size(); ++i) {
    const ap::ArmJoint& j = model.joints[model.activeJoints[i]];
    q[i] = random.uniform(j.lower, j.upper);
  }
  return q;
}

/// Runs one problem; returns the exit status it calls for (0 or 3).
int runProblem(const std::string& cfg, const Options& o, ProblemRow& row) {
  ap::CheckingOptions checking;  // our checker, exact clearance
  const ap::ArmPlanningProblem problem(ap::readMotionBenchMakerProblem(cfg), checking);
  const ob::SpaceInformationPtr& si = problem.spaceInformation();
  if (!si->isSetup()) si->setup();  // the discrete validator's resolution (longest valid segment)
  const ap::ArmValidityCheckerBase& ours = *problem.checker();
  const ap::FclArmValidityChecker fcl(si, problem.scene());
  const ap::ArmModel& model = problem.model();
  const auto& space = static_cast<const ap::ArmStateSpace&>(*si->getStateSpace());
  row.name = problem.name();
  row.dof = model.dof();
  row.links = ours.linkBodies();
  row.obstacles = problem.scene().environment.size();
  row.selfPairs = problem.scene().selfPairs.enabledPairs().size();

  adsd::bench::SeededRandom random(o.seed);
  std::vector<ob::State*> states;
  for (std::size_t i = 0; i < o.states; ++i) {
    ob::State* s = si->allocState();
    space.fromJoints(uniformJoints(model, random).data(), s);
    states.push_back(s);
  }
  std::vector<char> validOurs(states.size()), validFcl(states.size());
  std::vector<double> clearOurs(states.size()), clearFcl(states.size());
  std::vector<adsd::bench::TimedMethod> methods = {
      {"ours valid", [&](std::size_t i) { validOurs[i] = ours.isValid(states[i]); }, {}, {}},
      {"fcl valid", [&](std::size_t i) { validFcl[i] = fcl.isValid(states[i]); }, {}, {}},
      {"ours clearance", [&](std::size_t i) { clearOurs[i] = ours.clearance(states[i]); }, {}, {}},
      {"fcl clearance", [&](std::size_t i) { clearFcl[i] = fcl.clearance(states[i]); }, {}, {}},
  };
  if (o.validityAlone) {
    std::vector<adsd::bench::TimedMethod> validity(methods.begin(), methods.begin() + 2);
    adsd::bench::runInterleaved(validity, states.size(), o.rounds);
    row.oursValidAlone = adsd::bench::median(validity[0].micros);
    row.fclValidAlone = adsd::bench::median(validity[1].micros);
  }
  adsd::bench::runInterleaved(methods, states.size(), o.rounds);
  row.oursValid = adsd::bench::median(methods[0].micros);
  row.fclValid = adsd::bench::median(methods[1].micros);
  row.oursClear = adsd::bench::median(methods[2].micros);
  row.fclClear = adsd::bench::median(methods[3].micros);

  int status = 0;
  std::size_t valid = 0;
  const double tolerance = 1e-9 * ours.scale();
  for (std::size_t i = 0; i < states.size(); ++i) {
    valid += validOurs[i] != 0;
    if (validOurs[i] != validFcl[i]) {
      std::fprintf(stderr, "bench_arms: %s state %zu: ours says %s, FCL %s\n", row.name.c_str(), i,
                   validOurs[i] ? "valid" : "invalid", validFcl[i] ? "valid" : "invalid");
      status = 3;
    } else if (validOurs[i] && std::abs(clearOurs[i] - clearFcl[i]) > tolerance) {
      std::fprintf(stderr, "bench_arms: %s state %zu: clearance %.17g against FCL's %.17g\n", row.name.c_str(), i,
                   clearOurs[i], clearFcl[i]);
      status = 3;
    }
  }
  row.validShare = static_cast<double>(valid) / static_cast<double>(states.size());

  // Motions from valid states, each joint moved by up to the step, kept within the limits.
  std::vector<std::pair<ob::State*, ob::State*>> motions;
  for (std::size_t attempt = 0; motions.size() < o.motions && attempt < 100 * o.motions + 1000; ++attempt) {
    std::vector<double> q = uniformJoints(model, random);
    ob::State* from = si->allocState();
    space.fromJoints(q.data(), from);
    if (!ours.isValid(from)) {
      si->freeState(from);
      continue;
    }
    for (std::size_t j = 0; j < q.size(); ++j) {
      const ap::ArmJoint& joint = model.joints[model.activeJoints[j]];
      q[j] = std::clamp(q[j] + random.uniform(-o.step, o.step), joint.lower, joint.upper);
    }
    ob::State* to = si->allocState();
    space.fromJoints(q.data(), to);
    motions.emplace_back(from, to);
  }
  if (!motions.empty()) {
    const auto self = std::shared_ptr<const ap::ArmValidityCheckerBase>(problem.checker());
    const ap::ArmMotionValidator certified(si, self);
    const ob::DiscreteMotionValidator discrete(si);
    std::vector<char> acceptedDiscrete(motions.size()), acceptedCertified(motions.size());
    std::vector<adsd::bench::TimedMethod> motionMethods = {
        {"discrete", [&](std::size_t i) { acceptedDiscrete[i] = discrete.checkMotion(motions[i].first, motions[i].second); },
         {}, {}},
        {"certified",
         [&](std::size_t i) { acceptedCertified[i] = certified.checkMotion(motions[i].first, motions[i].second); },
         {}, {}},
    };
    adsd::bench::runInterleaved(motionMethods, motions.size(), o.rounds, 0);
    row.discreteMicros = adsd::bench::median(motionMethods[0].micros);
    row.certifiedMicros = adsd::bench::median(motionMethods[1].micros);
    double segments = 0;
    for (std::size_t i = 0; i < motions.size(); ++i) {
      segments += si->getStateSpace()->validSegmentCount(motions[i].first, motions[i].second);
      row.motionsAccepted[0] += acceptedDiscrete[i] != 0;
      row.motionsAccepted[1] += acceptedCertified[i] != 0;
      if (acceptedCertified[i] && !acceptedDiscrete[i]) {
        std::fprintf(stderr, "bench_arms: %s motion %zu: certified free, but the discrete check found a collision\n",
                     row.name.c_str(), i);
        status = 3;
      }
    }
    const double runs = static_cast<double>(motions.size()) * o.rounds;
    row.discreteChecks = segments / static_cast<double>(motions.size());
    row.certifiedQueries = static_cast<double>(certified.counts().clearanceQueries) / runs;
    for (auto& [from, to] : motions) si->freeState(from), si->freeState(to);
  }
  for (ob::State* s : states) si->freeState(s);
  return status;
}

std::string markdownTable(const std::vector<ProblemRow>& rows, const Options& o) {
  std::string out =
      "| problem | dof | links / obstacles / self pairs | valid | validity µs, ours | FCL | ours ÷ FCL | clearance µs, "
      "ours | FCL | ours ÷ FCL | checks per motion, discrete | certified | µs per motion, discrete | certified | "
      "motions accepted, discrete | certified |\n|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
      "---:|\n";
  char line[512];
  for (const ProblemRow& r : rows) {
    std::snprintf(line, sizeof line,
                  "| %s | %zu | %zu / %zu / %zu | %.0f %% | %.1f | %.1f | %.2f | %.1f | %.1f | %.2f | %.1f | %.1f | %.0f | "
                  "%.0f | %zu | %zu |\n",
                  r.name.c_str(), r.dof, r.links, r.obstacles, r.selfPairs, 100.0 * r.validShare, r.oursValid, r.fclValid,
                  r.oursValid / r.fclValid, r.oursClear, r.fclClear, r.oursClear / r.fclClear, r.discreteChecks,
                  r.certifiedQueries, r.discreteMicros, r.certifiedMicros, r.motionsAccepted[0], r.motionsAccepted[1]);
    out += line;
  }
  std::vector<double> valid, clear;
  for (const ProblemRow& r : rows) valid.push_back(r.oursValid / r.fclValid), clear.push_back(r.oursClear / r.fclClear);
  if (!rows.empty()) {
    std::snprintf(line, sizeof line,
                  "\nMedian over the problems, ours ÷ FCL: validity %.2f (worst %.2f), clearance %.2f (worst %.2f). %zu "
                  "states and %zu motions per problem (step %.2f rad), %d rounds, seed %llu.\n",
                  adsd::bench::median(valid), *std::max_element(valid.begin(), valid.end()), adsd::bench::median(clear),
                  *std::max_element(clear.begin(), clear.end()), o.states, o.motions, o.step, o.rounds,
                  static_cast<unsigned long long>(o.seed));
    out += line;
  }
  if (o.validityAlone && !rows.empty()) {
    std::vector<double> alone;
    for (const ProblemRow& r : rows) alone.push_back(r.oursValidAlone / r.fclValidAlone);
    std::snprintf(line, sizeof line,
                  "Validity timed alone (not interleaved with the clearance queries), ours ÷ FCL: median %.2f (worst "
                  "%.2f).\n",
                  adsd::bench::median(alone), *std::max_element(alone.begin(), alone.end()));
    out += line;
  }
  return out;
}

int run(const Options& o) {
  std::vector<std::string> cfgs;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(o.problems, ec)) {
    const fs::path cfg = entry.path() / "problem.cfg";
    if (!fs::exists(cfg)) continue;
    const std::string name = entry.path().filename().string();
    if (!o.only.empty() && std::find(o.only.begin(), o.only.end(), name) == o.only.end()) continue;
    cfgs.push_back(cfg.string());
  }
  if (ec) throw adsd::InputError(o.problems + ": cannot list the directory (" + ec.message() + ")");
  if (cfgs.empty()) throw adsd::InputError(o.problems + ": no NAME/problem.cfg (or none of --only)");
  std::sort(cfgs.begin(), cfgs.end());
  std::printf("bench_arms: %zu problems, %zu states and %zu motions each, %d rounds, seed %llu; median microseconds\n",
              cfgs.size(), o.states, o.motions, o.rounds, static_cast<unsigned long long>(o.seed));
  std::vector<ProblemRow> rows;
  int status = 0;
  for (const std::string& cfg : cfgs) {
    ProblemRow row;
    try {
      status = std::max(status, runProblem(cfg, o, row));
    } catch (const adsd::InputError& e) {  // a broken problem: said, the others still measured
      std::fprintf(stderr, "bench_arms: %s\n", e.what());
      status = std::max(status, 2);
      continue;
    }
    rows.push_back(row);
    std::printf("%-18s dof %zu valid %3.0f%%  validity %7.1f / %7.1f = %.2f  clearance %7.1f / %7.1f = %.2f  motion: %.1f "
                "discrete checks, %.1f certified queries; %.0f / %.0f us\n",
                row.name.c_str(), row.dof, 100.0 * row.validShare, row.oursValid, row.fclValid, row.oursValid / row.fclValid,
                row.oursClear, row.fclClear, row.oursClear / row.fclClear, row.discreteChecks, row.certifiedQueries,
                row.discreteMicros, row.certifiedMicros);
    if (o.validityAlone) {
      std::printf("%-18s validity alone %7.1f / %7.1f = %.2f\n", "", row.oursValidAlone, row.fclValidAlone,
                  row.oursValidAlone / row.fclValidAlone);
    }
    std::fflush(stdout);
  }
  const std::string table = markdownTable(rows, o);
  std::printf("\n%s", table.c_str());
  if (!o.summaryMarkdown.empty()) {
    std::ofstream out(o.summaryMarkdown);
    out << table;
    if (!out) throw adsd::InputError(o.summaryMarkdown + ": cannot write");
  }
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  return adsd::cli::runProgram(commandLine(), argc, argv,
                               [&](const adsd::cli::Arguments& given) { return run(optionsFrom(given)); });
}
