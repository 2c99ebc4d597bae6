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

#include <ompl/util/Console.h>

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

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s PROBLEM.cfg MINUTES [SECONDS_PER_RUN]\n", argv[0]);
    return 2;
  }
  const std::string cfg = argv[1];
  const double minutes = std::atof(argv[2]);
  const double secondsPerRun = argc > 3 ? std::atof(argv[3]) : 1.0;
  std::FILE* heapLog = nullptr;
  if (argc > 4) {
    heapLog = std::fopen(argv[4], "w");
    if (heapLog == nullptr) {
      std::fprintf(stderr, "adsd_soak: cannot write '%s'\n", argv[4]);
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
