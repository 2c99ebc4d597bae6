// Threads: one checker queried from several threads at once gives bit-identical answers to one
// thread (no shared scratch, no lock), also when each thread alternates between two checkers
// (the per-thread scratch is shared by checkers); PRM and CForest run with two threads. Meant to
// run under ThreadSanitizer as well (ADSD_SANITIZE=thread).
#include <gtest/gtest.h>

#include <limits>
#include <thread>

#include <ompl/geometric/planners/cforest/CForest.h>
#include <ompl/geometric/planners/prm/PRM.h>
#include <ompl/util/Console.h>

#include "adsd/planner/mesh_validity_checker.h"
#include "adsd/planner/planning_problem.h"
#include "scene_fixtures.h"

namespace adsd::planner {
namespace {

namespace ob = ompl::base;
using test::SceneFixture;

constexpr int kThreads = 4;
constexpr int kCallsPerThread = 150;

/// One answer per call: which query, and its bits.
struct Answer {
  bool valid = false;
  double distance = 0.0;
  bool operator==(const Answer& o) const { return valid == o.valid && distance == o.distance; }
};

/// Call k of the sequence: isValid, clearance and isValid(state, dist) in turn.
Answer query(const RigidBodyValidityChecker& checker, const ob::State* s, int k) {
  Answer a;
  switch (k % 3) {
    case 0:
      a.valid = checker.isValid(s);
      break;
    case 1:
      a.distance = checker.clearance(s);
      break;
    default:
      a.valid = checker.isValid(s, a.distance);
      break;
  }
  return a;
}

std::vector<ob::State*> randomStates(const SceneFixture& f, int n, std::uint64_t seed) {
  test::PoseSampler sampler(f, seed);
  std::vector<ob::State*> states;
  for (int i = 0; i < n; ++i) {
    states.push_back(f.si->allocState());
    poseToState(sampler.next(), f.scene->space, states.back());
  }
  return states;
}

TEST(Threads, ConcurrentQueriesOnTwoCheckersAreBitIdenticalToOneThread) {
  const SceneFixture office = test::officeFixture(), maze = test::mazeFixture();
  const MeshValidityChecker a(office.si, office.scene), b(maze.si, maze.scene);
  const std::vector<ob::State*> sa = randomStates(office, kCallsPerThread, 21);
  const std::vector<ob::State*> sb = randomStates(maze, kCallsPerThread, 22);
  // Thread t runs call k on checker (k + t) % 2, state k: every thread mixes both checkers and
  // all three queries, in a different interleaving.
  const auto run = [&](int t, std::vector<Answer>& out) {
    out.resize(kCallsPerThread);
    for (int k = 0; k < kCallsPerThread; ++k) {
      const bool onA = (k + t) % 2 == 0;
      out[k] = onA ? query(a, sa[k], k + t) : query(b, sb[k], k + t);
    }
  };
  std::vector<std::vector<Answer>> expected(kThreads), got(kThreads);
  for (int t = 0; t < kThreads; ++t) run(t, expected[t]);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) threads.emplace_back(run, t, std::ref(got[t]));
  for (std::thread& th : threads) th.join();
  for (int t = 0; t < kThreads; ++t) {
    for (int k = 0; k < kCallsPerThread; ++k) {
      EXPECT_TRUE(got[t][k] == expected[t][k]) << "thread " << t << " call " << k;
    }
  }
  // Every call counted exactly once, whatever the interleaving.
  const QueryCounts ca = a.counts(), cb = b.counts();
  EXPECT_EQ(ca.validityChecks + ca.clearanceQueries + cb.validityChecks + cb.clearanceQueries,
            static_cast<std::uint64_t>(2 * kThreads * kCallsPerThread));
  for (ob::State* s : sa) office.si->freeState(s);
  for (ob::State* s : sb) maze.si->freeState(s);
}

/// thin_wall.cfg in memory, with the certified validator (the discrete one would cross the wall).
PlanningProblem thinWallProblem() {
  const SceneFixture f = test::thinWallFixture();
  Pose start = Pose::Identity(), goal = Pose::Identity();
  start.translate(Vec3(-2.03, -1, 0));
  goal.translate(Vec3(1.97, -1, 0));
  CheckingOptions options;
  options.motion = MotionKind::certified;
  PlanningProblem problem(f.scene, start, goal, f.volume, options);
  // Any path will do: the planners stop at the first solution instead of refining until the time
  // limit, so the limit below is only a cap (sanitizer builds are several times slower).
  problem.setup().getOptimizationObjective()->setCostThreshold(
      ob::Cost(std::numeric_limits<double>::infinity()));
  return problem;
}

/// Cap on the planners' time: the thin wall takes well under a second in an optimized build.
constexpr double kPlanningCapSeconds = 30.0;

void solveWith(const ob::PlannerPtr& planner, PlanningProblem& problem, double seconds) {
  ompl::geometric::SimpleSetup& ss = problem.setup();
  ss.setPlanner(planner);
  const ob::PlannerStatus status = ss.solve(seconds);
  ASSERT_EQ(status, ob::PlannerStatus::EXACT_SOLUTION) << status.asString();
  EXPECT_TRUE(ss.getSolutionPath().check());
  // The solution goes round the wall, not through it: somewhere it is above the wall's end.
  double highest = -10.0;
  for (std::size_t i = 0; i < ss.getSolutionPath().getStateCount(); ++i) {
    highest = std::max(highest, ss.getSolutionPath().getState(i)->as<ob::SE2StateSpace::StateType>()->getY());
  }
  EXPECT_GT(highest, 2.0);
}

TEST(Threads, PrmWithTwoThreadsSolvesTheThinWall) {
  ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
  PlanningProblem problem = thinWallProblem();
  // OMPL's PRM grows its roadmap in one thread while another adds goal samples and checks for a
  // solution: two threads in the checker and the motion validator at once.
  solveWith(std::make_shared<ompl::geometric::PRM>(problem.spaceInformation()), problem, kPlanningCapSeconds);
  EXPECT_GT(problem.certifiedValidator()->counts().motions, 0u);
}

TEST(Threads, CForestWithTwoThreadsSolvesTheThinWall) {
  ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
  PlanningProblem problem = thinWallProblem();
  auto cforest = std::make_shared<ompl::geometric::CForest>(problem.spaceInformation());
  cforest->setNumThreads(2);
  solveWith(cforest, problem, kPlanningCapSeconds);
}

}  // namespace
}  // namespace adsd::planner
