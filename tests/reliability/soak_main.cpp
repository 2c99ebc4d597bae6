// adsd_soak: the soak's workload (tests/reliability/soak.sh samples its resident memory from
// outside). One process plans the same problem again and again for a given time, as a benchmark
// does: each run a fresh planner on the loaded problem (RRTConnect, then PRM with its two
// threads, in turn), solve, simplify, measure the path's clearance; every tenth run the problem
// is rebuilt from its file (meshes loaded again). Memory that survives a run would show as growth.
//
//   adsd_soak PROBLEM.cfg MINUTES [SECONDS_PER_RUN]
#include <chrono>
#include <cstdio>
#include <cstdlib>
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

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s PROBLEM.cfg MINUTES [SECONDS_PER_RUN]\n", argv[0]);
    return 2;
  }
  const std::string cfg = argv[1];
  const double minutes = std::atof(argv[2]);
  const double secondsPerRun = argc > 3 ? std::atof(argv[3]) : 1.0;
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
      ++runs;
      const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
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
