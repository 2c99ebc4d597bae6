// adsd_soak: the soak's workload (tests/reliability/soak.sh samples its resident memory from
// outside). One process plans the same problem again and again for a given time, as a benchmark
// does: each run a fresh planner on the loaded problem (RRTConnect, then PRM with its two
// threads, in turn), solve, simplify, measure the path's clearance; every tenth run the problem
// is rebuilt from its file (meshes loaded again). Memory that survives a run would show as growth.
//
//   adsd_soak PROBLEM.cfg MINUTES [SECONDS_PER_RUN [HEAP.csv]]
//
// With HEAP.csv, one line per run, written after the run has released everything it made: the
// heap bytes in use (glibc mallinfo2: uordblks, the small blocks in the arenas, plus hblkhd, the
// blocks mmapped on their own), the arenas' size (arena: what the heap holds from the kernel,
// in use or free) and the resident memory (VmRSS). In-use bytes that stay flat while the
// resident memory creeps mean the allocator keeps freed memory, not that we hold it.
#include <malloc.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <ompl/util/Console.h>

#include "adsd/cli/command_line.h"
#include "adsd/error.h"
#include "adsd/planner/path_report.h"
#include "adsd/planner/planner_registry.h"
#include "adsd/planner/planning_problem.h"
#include "adsd/planner/problem_file.h"

namespace {

using namespace adsd::planner;
using Clock = std::chrono::steady_clock;

/// Runs between two rebuilds of the problem from its file.
constexpr int kRunsPerLoad = 10;
const char* const kPlanners[] = {"rrtconnect", "prm"};

/// Resident memory of this process in KiB (VmRSS of /proc/self/status), 0 if unreadable.
long residentKib() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmRSS:", 0) == 0) return std::atol(line.c_str() + 6);
  }
  return 0;
}

int soak(const adsd::cli::Arguments& given) {
  const std::vector<std::string> args = given.texts("argument");
  if (args.size() < 2 || args.size() > 4) {
    throw adsd::cli::UsageError("expected PROBLEM.cfg MINUTES [SECONDS_PER_RUN [HEAP.csv]], got " +
                                std::to_string(args.size()) + " arguments");
  }
  const adsd::cli::RealInterval positive = adsd::cli::RealInterval::above(0.0).below(1e7);
  const std::string cfg = args[0];
  const double minutes = adsd::cli::parseReal(args[1], "MINUTES", positive);
  const double secondsPerRun = args.size() > 2 ? adsd::cli::parseReal(args[2], "SECONDS_PER_RUN", positive) : 1.0;
  std::FILE* heapLog = nullptr;
  if (args.size() > 3) {
    heapLog = std::fopen(args[3].c_str(), "w");
    if (heapLog == nullptr) {
      std::fprintf(stderr, "adsd_soak: cannot write '%s'\n", args[3].c_str());
      return 2;
    }
    std::fprintf(heapLog, "run,seconds,in_use_bytes,arena_bytes,mmapped_bytes,rss_kib\n");
  }
  ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
  try {
    const Clock::time_point end =
        Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(minutes * 60.0));
    const ProblemFile file = readProblemFile(cfg);
    std::unique_ptr<PlanningProblem> problem;
    long runs = 0, solved = 0;
    double lastReport = 0.0;
    const Clock::time_point start = Clock::now();
    while (Clock::now() < end) {
      if (runs % kRunsPerLoad == 0) problem = std::make_unique<PlanningProblem>(file, CheckingOptions{});
      ompl::geometric::SimpleSetup& ss = problem->setup();
      const char* name = kPlanners[runs % 2];
      ss.clear();
      ss.setPlanner(makePlanner(name, problem->spaceInformation()));
      ss.setup();
      if (ss.solve(secondsPerRun) == ompl::base::PlannerStatus::EXACT_SOLUTION) {
        ++solved;
        ss.simplifySolution(secondsPerRun);
        const PathMeasures m = measurePath(ss.getSolutionPath(), *problem->checker());
        if (!(m.minClearance >= 0.0)) {
          std::fprintf(stderr, "adsd_soak: run %ld: a solution with clearance %g\n", runs, m.minClearance);
          return 1;
        }
      }
      // The run's planner, its graph and its solution go now, not when the next run replaces them,
      // so that what the heap holds between runs is what survives a run.
      ss.clear();
      ss.setPlanner(ompl::base::PlannerPtr());
      ++runs;
      const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
      if (heapLog != nullptr) {
        const struct mallinfo2 heap = mallinfo2();
        std::fprintf(heapLog, "%ld,%.1f,%zu,%zu,%zu,%ld\n", runs, elapsed, heap.uordblks + heap.hblkhd, heap.arena,
                     heap.hblkhd, residentKib());
        std::fflush(heapLog);
      }
      if (elapsed - lastReport >= 60.0) {
        lastReport = elapsed;
        std::printf("%.0f s: %ld runs, %ld solved\n", elapsed, runs, solved);
        std::fflush(stdout);
      }
    }
    std::printf("done: %ld runs, %ld solved\n", runs, solved);
    return 0;
  } catch (const adsd::InputError& e) {
    std::fprintf(stderr, "adsd_soak: %s\n", e.what());
    return 2;
  }
}

}  // namespace

int main(int argc, char** argv) {
  adsd::cli::CommandLine line("adsd_soak", "adsd_soak PROBLEM.cfg MINUTES [SECONDS_PER_RUN [HEAP.csv]]",
                              "The soak's workload: plans the problem again and again for MINUTES "
                              "(tests/reliability/soak.sh samples its memory).",
                              "Exit status 0; 1 when a solution has a negative clearance; 2 on bad usage or input.");
  line.positional("argument");
  return adsd::cli::runProgram(line, argc, argv, soak);
}
