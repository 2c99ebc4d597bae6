#include "adsd/planner/path_report.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>

#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/base/spaces/SE3StateSpace.h>

#include "adsd/planner/certified_motion_validator.h"
#include "adsd/planner/state_pose.h"
#include "output_file.h"

namespace adsd::planner {

namespace ob = ompl::base;

namespace {

/// How many pieces each motion of \p path is cut into by measuredStates (and leastClearanceAlong's
/// first pass, which starts from the same states); sets \p coarser when the cap scaled them down.
std::vector<unsigned> measuredPieces(const ompl::geometric::PathGeometric& path, bool& coarser) {
  const ob::StateSpacePtr& space = path.getSpaceInformation()->getStateSpace();
  std::vector<unsigned> pieces;
  double total = 1.0;  // the first state
  for (std::size_t k = 0; k + 1 < path.getStateCount(); ++k) {
    pieces.push_back(std::max(1u, space->validSegmentCount(path.getState(k), path.getState(k + 1))));
    total += pieces.back();
  }
  coarser = total > static_cast<double>(kMaxMeasuredStates);
  if (coarser) {
    const double scale = static_cast<double>(kMaxMeasuredStates) / total;
    for (unsigned& p : pieces) p = std::max(1u, static_cast<unsigned>(std::floor(p * scale)));
  }
  return pieces;
}

}  // namespace

ompl::geometric::PathGeometric measuredStates(const ompl::geometric::PathGeometric& path, bool* coarser) {
  bool capped = false;
  const std::vector<unsigned> pieces = measuredPieces(path, capped);
  if (coarser != nullptr) *coarser = capped;
  const ob::SpaceInformationPtr& si = path.getSpaceInformation();
  ompl::geometric::PathGeometric dense(si);
  if (path.getStateCount() == 0) return dense;
  dense.append(path.getState(0));
  ob::State* state = si->allocState();
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    for (unsigned i = 1; i < pieces[k]; ++i) {
      si->getStateSpace()->interpolate(path.getState(k), path.getState(k + 1), static_cast<double>(i) / pieces[k],
                                       state);
      dense.append(state);
    }
    dense.append(path.getState(k + 1));
  }
  si->freeState(state);
  return dense;
}

PathMeasures measurePath(const ompl::geometric::PathGeometric& path, const ob::StateValidityChecker& checker) {
  PathMeasures m;
  m.length = path.length();
  const ompl::geometric::PathGeometric dense = measuredStates(path, &m.coarserThanResolution);
  double sum = 0.0;
  m.minClearance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < dense.getStateCount(); ++i) {
    const double c = checker.clearance(dense.getState(i));
    m.minClearance = std::min(m.minClearance, c);
    sum += c;
  }
  m.statesSampled = dense.getStateCount();
  if (m.statesSampled == 0) {
    m.minClearance = 0.0;
  } else {
    m.meanClearance = sum / static_cast<double>(m.statesSampled);
  }
  return m;
}

PathLeastClearance leastClearanceAlong(const ompl::geometric::PathGeometric& path,
                                       const RigidBodyValidityChecker& checker, double relativeTolerance,
                                       std::size_t maxQueries) {
  PathLeastClearance r;
  if (path.getStateCount() == 0) return r;
  const ob::SpaceInformationPtr& si = path.getSpaceInformation();
  const RigidBodySpace space = checker.space();
  // What a distance is trusted to (kDistanceTrustFraction): every bound gives it away.
  const double trust = kDistanceTrustFraction * checker.scale();
  // A path that slides along an obstacle at 1e-6 would need its every micrometre measured to bound
  // its least clearance within 1 % of that: below a millionth of the scene, closeness is enough.
  const double floor = kAbsoluteToleranceFraction * checker.scale() + trust;
  struct Interval {
    std::size_t motion;
    double t0, t1, c0, c1, lower;
  };
  const auto later = [](const Interval& x, const Interval& y) { return x.lower > y.lower; };
  std::vector<Interval> heap;
  std::vector<double> sweep(path.getStateCount(), 0.0);
  ob::State* state = si->allocState();
  const auto clearanceAt = [&](std::size_t motion, double t) {
    si->getStateSpace()->interpolate(path.getState(motion), path.getState(motion + 1), t, state);
    ++r.queries;
    const double c = checker.clearance(state);
    r.least = std::min(r.least, c);
    return c;
  };
  const auto push = [&](std::size_t motion, double t0, double t1, double c0, double c1) {
    const double lower = 0.5 * (c0 + c1 - sweep[motion] * (t1 - t0)) - trust;
    heap.push_back({motion, t0, t1, c0, c1, std::max(lower, 0.0)});
    std::push_heap(heap.begin(), heap.end(), later);
  };
  bool coarser = false;
  const std::vector<unsigned> firstPieces = measuredPieces(path, coarser);
  // A motion's first state is the last one's end: measured once.
  double c = checker.clearance(path.getState(0));
  r.least = c;
  r.queries = 1;
  for (std::size_t k = 0; k + 1 < path.getStateCount(); ++k) {
    const ob::State *from = path.getState(k), *to = path.getState(k + 1);
    sweep[k] = translationDistance(from, to, space) + rotationAngle(from, to, space) * checker.robotRadius();
    // As measurePath samples it: the motion cut at the validity-checking resolution, or coarser
    // on a path of more than kMaxMeasuredStates such states.
    const unsigned pieces = firstPieces[k];
    double t = 0.0;
    for (unsigned i = 1; i <= pieces; ++i) {
      const double next = static_cast<double>(i) / pieces;
      const double cNext = clearanceAt(k, next);
      push(k, t, next, c, cNext);
      t = next;
      c = cNext;
    }
  }
  // Whether the path comes within the checker's safety margin is decided too, not only the least
  // clearance within the tolerance: that tolerance's floor let a path whose least measured
  // clearance was 5e-6 stop with intervals bounded at 0 unexamined, and a cow's path through a
  // window that crossed its edge (FCL found 17 colliding states between two measured ones) was
  // reported free (an outside review). So the lowest interval is halved while its bound is within
  // the margin and no state within the margin has been found.
  const double margin = checker.safetyMargin();
  const auto decided = [&](const Interval& worst) {
    return r.least <= margin || worst.lower > margin;
  };
  while (!heap.empty()) {
    const Interval worst = heap.front();
    const bool closeEnough = worst.lower >= r.least - std::max(relativeTolerance * r.least, floor);
    if ((closeEnough && decided(worst)) || r.queries >= maxQueries) break;
    std::pop_heap(heap.begin(), heap.end(), later);
    heap.pop_back();
    const double middle = 0.5 * (worst.t0 + worst.t1);
    if (!(middle > worst.t0 && middle < worst.t1)) continue;  // as fine as doubles go: its ends decide it
    const double atMiddle = clearanceAt(worst.motion, middle);
    push(worst.motion, worst.t0, middle, worst.c0, atMiddle);
    push(worst.motion, middle, worst.t1, atMiddle, worst.c1);
  }
  si->freeState(state);
  r.lowerBound = heap.empty() ? r.least : std::min(r.least, heap.front().lower);
  return r;
}

ArmPathClearance measureArmPathClearance(const ompl::geometric::PathGeometric& path,
                                         const ompl::geometric::PathGeometric& samples,
                                         const ArmMotionClearance& clearance) {
  ArmPathClearance m;
  m.min = m.certifiedMin = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < path.getStateCount(); ++i) {
    m.certifiedMin = std::min(m.certifiedMin, clearance.along(path.getState(i), path.getState(i + 1)).lower);
  }
  double sum = 0.0;
  for (std::size_t i = 0; i < samples.getStateCount(); ++i) {
    const double c = clearance.at(samples.getState(i));
    m.min = std::min(m.min, c);
    sum += c;
  }
  m.statesSampled = samples.getStateCount();
  if (m.statesSampled > 0) m.mean = sum / static_cast<double>(m.statesSampled);
  if (path.getStateCount() < 2) m.certifiedMin = m.min;
  return m;
}

void writePathFile(const std::string& file, const ompl::geometric::PathGeometric& path, RigidBodySpace space) {
  writeOutputFile(file, "path file", [&](std::ostream& out) {
    out << std::setprecision(17);
    for (std::size_t i = 0; i < path.getStateCount(); ++i) {
      const ob::State* s = path.getState(i);
      if (space == RigidBodySpace::se2) {
        const auto* se2 = s->as<ob::SE2StateSpace::StateType>();
        out << se2->getX() << ' ' << se2->getY() << ' ' << se2->getYaw() << '\n';
      } else {
        const auto* se3 = s->as<ob::SE3StateSpace::StateType>();
        const auto& q = se3->rotation();
        out << se3->getX() << ' ' << se3->getY() << ' ' << se3->getZ() << ' ' << q.x << ' ' << q.y << ' ' << q.z
            << ' ' << q.w << '\n';
      }
    }
  });
}

void writeArmPathFile(const std::string& file, const ompl::geometric::PathGeometric& path,
                      const ArmStateSpace& space, const std::vector<std::string>& jointNames) {
  writeOutputFile(file, "path file", [&](std::ostream& out) {
    out << std::setprecision(17);
    out << "# joints:";
    for (const std::string& name : jointNames) out << ' ' << name;
    out << '\n';
    std::vector<double> q(space.dof());
    for (std::size_t i = 0; i < path.getStateCount(); ++i) {
      space.toJoints(path.getState(i), q.data());
      for (std::size_t j = 0; j < q.size(); ++j) out << (j == 0 ? "" : " ") << q[j];
      out << '\n';
    }
  });
}

}  // namespace adsd::planner
