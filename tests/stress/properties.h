#pragma once
/// \file
/// \brief The properties of issue 3 item 3, checked on one case for both query paths (from
/// scratch, and with Mesh::buildHierarchy() on both meshes) and every query mode, against the
/// independent oracle (tests/oracle).
///
/// Each check is a plain function of the oracle's truth and one DistanceResult, so the checks
/// themselves can be tested on fabricated results (properties_test.cpp): a check that cannot fail
/// would prove nothing.

#include <cstdint>
#include <string>
#include <vector>

#include "adsd/distance.h"
#include "oracle.h"
#include "stress_case.h"

namespace adsd::stress {

/// Accuracy promised by issues 2 and 3, relative to the scene's bounding-box diagonal.
inline constexpr double kAccuracy = oracle::kPromisedAccuracy;
/// The magnitude of the numbers a query computes with: what distance.h's accuracy bound
/// (kAccuracy x diagonal + tolerance::kBoundSafetyUlps x eps x this) is relative to. The largest
/// coordinate of either mesh in its own frame (sqrt 3 x the largest |coordinate|) plus the
/// distance between the two frames' origins: the same in both orders of A and B.
double workingMagnitude(const StressCase& c);
/// The oracle's exact intersection predicate is evaluated when the oracle's distance is at most
/// this x the diagonal (dimensionless). The oracle's distance is exact to ~1e-30 relative, so
/// farther meshes cannot meet; closer ones need the predicate to say whether they do.
inline constexpr double kPredicateBand = 1e-9;
/// Witness points are world-frame doubles: a coordinate of magnitude M carries about M x 2^-53
/// per operation that produced it (the pose applied, the frame change into mesh A's frame, the
/// closest-point arithmetic). 16 units of roundoff of the largest coordinate or translation in
/// play is the allowance on top of kAccuracy x diagonal for "lies on its triangle" and "realizes
/// the distance"; without it no double witness could pass at offsets of 1e8 x the scene.
inline constexpr double kWitnessRoundingUlps = 16.0;
/// checkHierarchy()'s allowance for a corner outside its node box, in units of roundoff of the
/// mesh's largest coordinate (or the box's magnitude if larger): half of
/// tolerance::kBoundSafetyUlps, the margin every query subtracts from its lower bounds. A miss
/// below it is rounding that the query's margin absorbs with room to spare for the bound's own
/// rounding; a miss beyond it can make a bound prune the closest pair.
inline constexpr double kBoxRoundingUlps = 32.0;

/// \brief What the oracle says about a case.
struct Truth {
  double distance = 0.0;   ///< oracle's minimum distance (binary128, rounded to double)
  double diagonal = 0.0;   ///< scene bounding-box diagonal (world frame)
  /// The allowed error of any distance answer: kAccuracy x diagonal, plus the roundoff of the
  /// working magnitude (tolerance::kBoundSafetyUlps x eps x workingMagnitude), which matters only
  /// when mesh frames lie far from their geometry (family mesh/offset-frames; distance.h).
  double tolerance = 0.0;
  /// The roundoff part of `tolerance` alone (kBoundSafetyUlps x eps x workingMagnitude): how far
  /// from 0 an answer may put intersecting meshes (at threshold 0) without contradicting them.
  double roundoff = 0.0;
  /// The exact predicate, evaluated only when distance <= kPredicateBand x diagonal (else false).
  bool intersecting = false;
  double witnessSlack = 0.0;  ///< tolerance plus the rounding allowance of world-frame witnesses
  std::uint64_t oraclePairs = 0;  ///< triangle pairs the oracle evaluated
};

/// \brief Runs the oracle on the case (brute force in binary128, plus the predicate when close).
Truth consultOracle(const StressCase& c);

/// \brief A violated property: a short stable label ("<path> <query>: <property>", the key by
/// which failures are counted and minimized) and the exact numbers.
struct Failure {
  std::string check;
  std::string detail;
};

/// The label of the failure that says a case claimed to be penetrating is not intersecting.
inline constexpr const char* kNotPenetrating = "generator: penetrating case is not intersecting";

// --- the checks on one answer (query: a label such as "tree exact" that prefixes the check) ---

/// No NaN or infinity in any field (`upper` may be infinite for beyondCap, as distance.h says);
/// counters consistent; GJK within tolerance::kGjkMaxIterations.
void checkResultSanity(const DistanceResult& r, const std::string& query, std::vector<Failure>& out);
/// Exact mode: within the tolerance of the oracle; status exact and lower == upper == distance;
/// the collision decision (distance 0 or not) right whenever the oracle's distance exceeds the
/// tolerance; exactly 0 when the case is penetrating.
void checkExact(const Truth& t, const DistanceResult& r, bool penetrating, const std::string& query,
                std::vector<Failure>& out);
/// Tolerance mode: the interval contains the oracle's value, is no wider than asked, holds the
/// reported distance; status withinTolerance or exact.
void checkTolerance(const Truth& t, double absTolerance, double relTolerance, const DistanceResult& r,
                    const std::string& query, std::vector<Failure>& out);
/// Threshold mode: the decision right whenever the oracle is more than the tolerance from the
/// margin (and always within for a penetrating case); what each status claims holds.
void checkThreshold(const Truth& t, double margin, bool penetrating, const DistanceResult& r, const std::string& query,
                    std::vector<Failure>& out);
/// Cap mode: the exact distance below the cap, ">= cap" beyond it (outside the tolerance band).
void checkCap(const Truth& t, double cap, const DistanceResult& r, const std::string& query, std::vector<Failure>& out);
/// Exact mode's witnesses: valid triangle indices; each witness on its (posed) triangle and the two
/// witnesses as far apart as the distance, within Truth::witnessSlack. \p swapped: the answer is
/// for (B, A).
void checkWitnesses(const StressCase& c, const Truth& t, const DistanceResult& r, bool swapped, const std::string& query,
                    std::vector<Failure>& out);

/// mesh_hierarchy.h: every node's box ("bounds of the node's vertices", axes "unit") holds every
/// corner of the node's triangles: along each box axis, no corner lies beyond the box's support
/// by more than kBoxRoundingUlps of the magnitudes in play. A corner outside lets the tree's
/// bounds prune the closest pair.
void checkHierarchy(const Mesh& mesh, const std::string& query, std::vector<Failure>& out);

/// \brief Everything learned from one case.
struct CaseReport {
  Truth truth;
  double worstError = 0.0;   ///< max |exact-mode distance - oracle| / diagonal, both paths, all orders
  int gjkMaxIterations = 0;  ///< most iterations of one GJK run, any query
  int maxDepthScratch = 0;   ///< deepest recursion, exact query from scratch
  int maxDepthTree = 0;      ///< deepest recursion, exact query with hierarchies
  bool rootSplit = false;    ///< the hulls overlapped at the root (exact query from scratch)
  std::vector<Failure> failures;
};

/// \brief All properties of issue 3 item 3 on one case: for each path (scratch, tree) the exact
/// query (A, B), the swapped query (B, A), the query on permuted meshes (vertices within
/// triangles, triangles within meshes, vertex arrays), one tolerance query, two threshold queries
/// and one cap query, with settings rotating over the case index.
CaseReport checkCase(const StressCase& c, DistanceScratch& scratch);

/// \brief The failure's report: the check, its numbers, the oracle's truth.
std::string describeFailure(const Failure& f, const Truth& t);

}  // namespace adsd::stress
