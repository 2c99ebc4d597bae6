#include "adsd/planner/path_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <limits>
#include <sstream>

#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/base/spaces/SE3StateSpace.h>

#include "adsd/error.h"

namespace adsd::planner {

namespace ob = ompl::base;

PathMeasures measurePath(const ompl::geometric::PathGeometric& path, const ob::StateValidityChecker& checker) {
  PathMeasures m;
  m.length = path.length();
  ompl::geometric::PathGeometric dense(path);
  dense.interpolate();  // states at the space's validity-checking resolution
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

namespace {

/// Writes \p file through a temporary name renamed on success; \p body writes the lines.
void writeAtomically(const std::string& file, const std::function<void(std::ostream&)>& body) {
  const std::string temporary = file + ".partial";
  {
    std::ofstream out(temporary);
    if (!out) throw InputError(file + ": cannot write the path file");
    out << std::setprecision(17);
    body(out);
    out.flush();
    if (!out) {
      out.close();
      std::remove(temporary.c_str());
      throw InputError(file + ": writing the path file failed");
    }
  }
  std::error_code ec;
  std::filesystem::rename(temporary, file, ec);
  if (ec) {
    std::remove(temporary.c_str());
    throw InputError(file + ": cannot rename the finished path file into place: " + ec.message());
  }
}

}  // namespace

void writePathFile(const std::string& file, const ompl::geometric::PathGeometric& path, RigidBodySpace space) {
  writeAtomically(file, [&](std::ostream& out) {
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
  writeAtomically(file, [&](std::ostream& out) {
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
