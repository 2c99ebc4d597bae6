// ArmThreads (label "threads"; tests/check.sh runs it under ThreadSanitizer): one arm checker and
// one motion validator called from several threads at once give the answers of one thread, and
// RRTConnect with the certified validator solves a KR5 problem in a parallel planner (PRM, two threads).

#include <gtest/gtest.h>

#include <cstdlib>
#include <random>
#include <thread>

#include <ompl/base/SpaceInformation.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/prm/PRM.h>

#include "adsd/planner/arm_motion_validator.h"
#include "adsd/planner/arm_validity_checker.h"
#include "arm_scenes.h"

namespace adsd::planner {
namespace {

constexpr int kThreads = 4;

int callsPerThread() {
  // A call here is a validity check, a clearance and (from a valid state) a certified motion of up
  // to 0.05 rad per joint, some milliseconds: a hundredth of the planner thread tests' count.
  if (const char* text = std::getenv("ADSD_THREAD_CALLS"); text && *text) return std::max(10, std::atoi(text) / 100);
  return 100;
}

TEST(ArmThreads, ConcurrentChecksAndMotionsMatchOneThread) {
  ADSD_REQUIRE_ROBOTS();
  const ArmScene scene = test::kr5BoxScene();
  auto si = std::make_shared<ompl::base::SpaceInformation>(std::make_shared<ArmStateSpace>(*scene.model));
  auto checker = std::make_shared<ArmValidityChecker>(si, scene);
  si->setStateValidityChecker(checker);
  auto validator = std::make_shared<ArmMotionValidator>(si, checker);
  si->setMotionValidator(validator);
  si->setup();
  const int calls = callsPerThread();
  // Each thread's states are drawn from its own seed: the same on every run.
  struct Answer {
    bool valid;
    double clearance;
    bool motion;
  };
  const auto run = [&](int t, std::vector<Answer>& out) {
    std::mt19937_64 rng(100 + t);
    const ArmModel& model = checker->model();
    const auto* space = si->getStateSpace()->as<ArmStateSpace>();
    std::vector<double> q(space->dof());
    ompl::base::State* a = si->allocState();
    ompl::base::State* b = si->allocState();
    out.clear();
    for (int i = 0; i < calls; ++i) {
      for (std::size_t j = 0; j < q.size(); ++j) {
        const ArmJoint& joint = model.joints[model.activeJoints[j]];
        q[j] = std::uniform_real_distribution<double>(joint.lower, joint.upper)(rng);
      }
      space->fromJoints(q.data(), a);
      for (double& v : q) v += std::uniform_real_distribution<double>(-0.05, 0.05)(rng);
      space->fromJoints(q.data(), b);
      si->enforceBounds(b);
      Answer x{checker->isValid(a), checker->clearance(a), false};
      if (x.valid) x.motion = validator->checkMotion(a, b);
      out.push_back(x);
    }
    si->freeState(a);
    si->freeState(b);
  };
  std::vector<std::vector<Answer>> expected(kThreads), got(kThreads);
  for (int t = 0; t < kThreads; ++t) run(t, expected[t]);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) threads.emplace_back(run, t, std::ref(got[t]));
  for (std::thread& th : threads) th.join();
  for (int t = 0; t < kThreads; ++t) {
    ASSERT_EQ(got[t].size(), expected[t].size());
    for (std::size_t i = 0; i < got[t].size(); ++i) {
      EXPECT_EQ(got[t][i].valid, expected[t][i].valid);
      EXPECT_EQ(got[t][i].clearance, expected[t][i].clearance);
      EXPECT_EQ(got[t][i].motion, expected[t][i].motion);
    }
  }
}

TEST(ArmThreads, PrmWithTwoThreadsSolvesAKr5Problem) {
  ADSD_REQUIRE_ROBOTS();
  const ArmScene scene = test::kr5BoxScene();
  ompl::geometric::SimpleSetup ss(std::make_shared<ArmStateSpace>(*scene.model));
  auto si = ss.getSpaceInformation();
  auto checker = std::make_shared<ArmValidityChecker>(si, scene);
  ss.setStateValidityChecker(checker);
  si->setMotionValidator(std::make_shared<ArmMotionValidator>(si, checker));
  const auto* space = si->getStateSpace()->as<ArmStateSpace>();
  ompl::base::ScopedState<> start(si->getStateSpace()), goal(si->getStateSpace());
  const double qs[6] = {0.0, 0.3, -0.5, 0.0, 0.5, 0.0}, qg[6] = {1.5, 0.0, -0.8, 0.5, 0.3, 1.0};
  space->fromJoints(qs, start.get());
  space->fromJoints(qg, goal.get());
  ASSERT_TRUE(checker->isValid(start.get()));
  ASSERT_TRUE(checker->isValid(goal.get()));
  ss.setStartAndGoalStates(start, goal);
  auto prm = std::make_shared<ompl::geometric::PRM>(si);  // grows its roadmap in a second thread
  ss.setPlanner(prm);
  double seconds = 10.0;
  if (const char* text = std::getenv("ADSD_PLANNER_SECONDS"); text && *text) seconds = std::atof(text);
  const ompl::base::PlannerStatus solved = ss.solve(seconds);
  ASSERT_TRUE(solved == ompl::base::PlannerStatus::EXACT_SOLUTION);
  EXPECT_TRUE(ss.getSolutionPath().check());
}

}  // namespace
}  // namespace adsd::planner
