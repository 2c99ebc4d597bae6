#pragma once
/// \file
/// \brief Measuring a solution path and writing it in OMPL.app's `.path` format.

#include <cstddef>
#include <string>
#include <vector>

#include <ompl/geometric/PathGeometric.h>

#include "adsd/planner/arm_clearance_objective.h"
#include "adsd/planner/arm_state_space.h"
#include "adsd/planner/rigid_body_validity_checker.h"

namespace adsd::planner {

/// \brief Length and clearance of a path.
struct PathMeasures {
  double length = 0.0;
  double minClearance = 0.0;   ///< over the states sampled along the path
  double meanClearance = 0.0;
  std::size_t statesSampled = 0;
  bool coarserThanResolution = false;  ///< measuredStates capped the states (kMaxMeasuredStates)
};

/// \brief At most this many states are measured along a path (measuredStates), unless the path
/// has more states of its own. A path file of 20 000 random states, interpolated to the
/// validity-checking resolution, became millions of states: `adsd view` took 25 s and 830 MB and
/// wrote a 138 MB page, and 200 000 states would have needed some 8 GB.
inline constexpr std::size_t kMaxMeasuredStates = 20000;

/// \brief \p path's states, each motion cut into the pieces of the space's validity-checking
/// resolution (as PathGeometric::interpolate() cuts it); when that would make more than
/// kMaxMeasuredStates states, each motion's pieces are scaled down in proportion (at least one
/// piece a motion), and \p coarser, when given, is set. The path itself is unchanged.
ompl::geometric::PathGeometric measuredStates(const ompl::geometric::PathGeometric& path, bool* coarser = nullptr);

/// \brief Measures \p path: its length, and the checker's clearance at measuredStates(path).
/// The clearance queries count on the checker like any other.
/// Any checker with a clearance: RigidBodyValidityChecker, ArmValidityCheckerBase.
PathMeasures measurePath(const ompl::geometric::PathGeometric& path, const ompl::base::StateValidityChecker& checker);

/// leastClearanceAlong's absolute tolerance, a fraction of the scene's length scale (dimensionless).
inline constexpr double kAbsoluteToleranceFraction = 1e-6;

/// \brief The least clearance along a rigid body's path, its motions included.
struct PathLeastClearance {
  double least = 0.0;       ///< the least clearance found, at a state of the path (exact)
  double lowerBound = 0.0;  ///< no state anywhere along the path is nearer (certified)
  std::size_t queries = 0;  ///< clearance queries spent
};

/// \brief The least clearance along \p path, motions included: the clearance at states a
/// validity-checking resolution apart misses what lies between them (a path past a corner at 5e-5
/// was measured at 1.4e-4 from its states). Between two states of a motion every robot point moves
/// at most L |t' - t| (L as CertifiedMotionValidator's), so the clearance between states measured
/// at t and t' is at least (c + c' - L |t' - t|) / 2; the interval of the smallest such bound is
/// halved, by one query at its middle, until that bound is within \p relativeTolerance of the least
/// found, or kAbsoluteToleranceFraction of the scene's scale, and until a state within the
/// checker's safety margin is found or every bound is beyond it (or \p maxQueries are spent:
/// lowerBound says what was proven). Starts from the states measurePath measures (measuredStates).
PathLeastClearance leastClearanceAlong(const ompl::geometric::PathGeometric& path,
                                       const RigidBodyValidityChecker& checker, double relativeTolerance = 0.01,
                                       std::size_t maxQueries = 20000);

/// \brief An arm path's clearance as the clearance objective measures it (ArmMotionClearance).
struct ArmPathClearance {
  double min = 0.0;   ///< exact, the least at the states sampled
  double mean = 0.0;  ///< over the states sampled
  std::size_t statesSampled = 0;
  double certifiedMin = 0.0;  ///< a lower bound of the least clearance anywhere along the path
};

/// \brief Measures \p path with \p clearance: its exact clearance at the states of \p samples (the
/// path interpolated: the same states another measure took, so that the two compare), and the
/// least of the path's motions' certified lower bounds (ArmMotionClearance::along).
ArmPathClearance measureArmPathClearance(const ompl::geometric::PathGeometric& path,
                                         const ompl::geometric::PathGeometric& samples,
                                         const ArmMotionClearance& clearance);

/// \brief Writes one state per line, its real values separated by spaces (SE(2): x y yaw;
/// SE(3): x y z qx qy qz qw). Written to a temporary file renamed on success, so a failure
/// leaves nothing half-written; throws adsd::InputError naming the file when it cannot be written.
void writePathFile(const std::string& file, const ompl::geometric::PathGeometric& path, RigidBodySpace space);

/// \brief Writes an arm's path: a header comment line "# joints: NAME ..." (\p jointNames, the
/// model's joint-vector order), then one state per line, its joint values (radians or metres)
/// separated by spaces. Written as writePathFile writes.
void writeArmPathFile(const std::string& file, const ompl::geometric::PathGeometric& path,
                      const ArmStateSpace& space, const std::vector<std::string>& jointNames);

}  // namespace adsd::planner
