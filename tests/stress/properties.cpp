#include "properties.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <sstream>
#include <string>

#include "adsd/mesh_hierarchy.h"
#include "adsd/tolerances.h"
#include "oracle.h"
#include "shape_kit.h"

namespace adsd::stress {

namespace {

/// "distance D [lower, upper] status S" with every number exact.
std::string describe(const DistanceResult& r) {
  std::ostringstream out;
  out << "distance " << exactNumber(r.distance) << " lower " << exactNumber(r.lower) << " upper "
      << exactNumber(r.upper) << " status " << toString(r.status);
  return out.str();
}

void fail(std::vector<Failure>& out, const std::string& query, const std::string& property, const DistanceResult& r,
          const std::string& extra = "") {
  out.push_back({query + ": " + property, describe(r) + (extra.empty() ? "" : "; " + extra)});
}

double maxTranslation(const StressCase& c) {
  return std::max(c.poseA.translation().cwiseAbs().maxCoeff(), c.poseB.translation().cwiseAbs().maxCoeff());
}

}  // namespace

double workingMagnitude(const StressCase& c) {
  const double frames = (c.poseB.translation() - c.poseA.translation()).norm();
  return std::sqrt(3.0) * (c.a.maxAbsCoordinate() + c.b.maxAbsCoordinate()) + frames;
}

Truth consultOracle(const StressCase& c) {
  Truth t;
  t.diagonal = sceneDiagonal(c);
  t.roundoff = tolerance::kBoundSafetyUlps * tolerance::kEpsilon * workingMagnitude(c);
  t.tolerance = kAccuracy * t.diagonal + t.roundoff;
  const oracle::MeshPairDistance o = oracle::meshDistance(c.a, c.poseA, c.b, c.poseB);
  t.distance = o.value;
  t.oraclePairs = o.trianglePairsEvaluated;
  t.intersecting = t.distance <= kPredicateBand * t.diagonal && oracle::meshesIntersect(c.a, c.poseA, c.b, c.poseB);
  const double magnitude = std::max(worldMagnitude(c), maxTranslation(c));
  t.witnessSlack = t.tolerance + kWitnessRoundingUlps * tolerance::kEpsilon * magnitude;
  return t;
}

void checkResultSanity(const DistanceResult& r, const std::string& query, std::vector<Failure>& out) {
  // distance.h: upper "may be infinite" for beyondCap; everything else is a number.
  const bool upperOk = std::isfinite(r.upper) || (r.status == DistanceStatus::beyondCap && r.upper == INFINITY);
  if (!std::isfinite(r.distance) || !std::isfinite(r.lower) || !upperOk || !r.witnessA.allFinite() ||
      !r.witnessB.allFinite()) {
    std::ostringstream w;
    w.precision(17);
    w << "witnessA (" << r.witnessA.transpose() << ") witnessB (" << r.witnessB.transpose() << ")";
    fail(out, query, "non-finite field", r, w.str());
  }
  const DistanceCounters& k = r.counters;
  if (k.gjkMaxIterations > tolerance::kGjkMaxIterations || k.gjkMaxIterations < 0 ||
      k.gjkIterations > k.gjkCalls * std::uint64_t(tolerance::kGjkMaxIterations) || k.maxDepth < 0) {
    std::ostringstream w;
    w << "gjkMaxIterations " << k.gjkMaxIterations << " (cap " << tolerance::kGjkMaxIterations << "), gjkIterations "
      << k.gjkIterations << " over " << k.gjkCalls << " runs, maxDepth " << k.maxDepth;
    fail(out, query, "counters beyond their caps", r, w.str());
  }
}

void checkExact(const Truth& t, const DistanceResult& r, bool penetrating, const std::string& query,
                std::vector<Failure>& out) {
  const double error = std::abs(r.distance - t.distance);
  const std::string numbers = "error " + exactNumber(error) + " tolerance " + exactNumber(t.tolerance);
  if (!(error <= t.tolerance)) fail(out, query, r.distance > t.distance ? "too large" : "too small", r, numbers);
  if (r.status != DistanceStatus::exact) fail(out, query, "status not exact", r);
  if (!(r.lower == r.distance && r.upper == r.distance)) fail(out, query, "interval not [d, d]", r);
  // The collision decision: apart by more than the tolerance must not read as contact.
  if (t.distance > t.tolerance && !(r.distance > 0.0)) fail(out, query, "false contact", r, numbers);
  if (penetrating && r.distance != 0.0) fail(out, query, "penetrating but not exactly 0", r);
}

void checkTolerance(const Truth& t, double absTolerance, double relTolerance, const DistanceResult& r,
                    const std::string& query, std::vector<Failure>& out) {
  std::ostringstream asked;
  asked << "absTolerance " << exactNumber(absTolerance) << " relTolerance " << exactNumber(relTolerance);
  const double o = t.distance, tol = t.tolerance;
  if (!(r.lower <= o + tol && o - tol <= r.upper)) fail(out, query, "interval misses the oracle", r, asked.str());
  if (!(r.upper - r.lower <= std::max(absTolerance, relTolerance * r.upper) + tol)) {
    fail(out, query, "interval wider than asked", r, asked.str());
  }
  if (!(r.distance >= o - tol && r.distance <= r.upper + tol && r.distance >= r.lower - tol)) {
    fail(out, query, "distance outside the interval or below the oracle", r, asked.str());
  }
  if (r.status != DistanceStatus::withinTolerance && r.status != DistanceStatus::exact) fail(out, query, "status", r, asked.str());
  if (r.status == DistanceStatus::exact && !(r.lower == r.upper)) fail(out, query, "status exact with lower != upper", r, asked.str());
}

void checkThreshold(const Truth& t, double margin, bool penetrating, const DistanceResult& r, const std::string& query,
                    std::vector<Failure>& out) {
  const std::string asked = "threshold " + exactNumber(margin);
  const double o = t.distance, tol = t.tolerance;
  const bool above = r.status == DistanceStatus::aboveThreshold;
  if (!above && r.status != DistanceStatus::withinThreshold) fail(out, query, "status", r, asked);
  if (o > margin + tol && !above) fail(out, query, "should be above", r, asked);
  if ((o < margin - tol || penetrating) && above) fail(out, query, "should be within", r, asked);
  // Intersecting meshes must read as touching at threshold 0, up to the roundoff of the working
  // magnitude (distance.h): a lower bound beyond it is a missed collision.
  if (t.intersecting && margin == 0.0 && above && r.lower > t.roundoff) {
    fail(out, query, "intersecting, but above threshold 0", r, asked);
  }
  // distance.h: aboveThreshold = "proven: minimum distance > threshold (lower >= threshold: pairs
  // culled at the threshold count with it as their bound)", and then every distance found, upper
  // included, is above it; withinThreshold = "proven: minimum distance <= threshold (upper <=
  // threshold; distance = upper)".
  if (above && !(r.lower >= margin && r.upper > margin)) fail(out, query, "above, but the interval is not above the threshold", r, asked);
  if (above && !(r.lower <= o + tol)) fail(out, query, "lower bound above the oracle", r, asked);
  if (r.status == DistanceStatus::withinThreshold) {
    if (!(r.upper <= margin && r.distance == r.upper)) fail(out, query, "within, but upper is above the threshold", r, asked);
    if (!(r.distance >= o - tol)) fail(out, query, "distance below the oracle", r, asked);
  }
}

void checkCap(const Truth& t, double cap, const DistanceResult& r, const std::string& query, std::vector<Failure>& out) {
  const std::string asked = "cap " + exactNumber(cap);
  const double o = t.distance, tol = t.tolerance;
  if (r.status != DistanceStatus::exact && r.status != DistanceStatus::beyondCap) fail(out, query, "status", r, asked);
  if (o < cap - tol && !(r.status == DistanceStatus::exact && std::abs(r.distance - o) <= tol)) {
    fail(out, query, "should be the exact distance", r, asked);
  }
  if (o > cap + tol && !(r.status == DistanceStatus::beyondCap)) fail(out, query, "should be beyond the cap", r, asked);
  if (r.status == DistanceStatus::beyondCap && !(r.distance == cap && r.lower == cap)) {
    fail(out, query, "beyond the cap, but distance or lower is not the cap", r, asked);
  }
  if (r.status == DistanceStatus::exact && !(r.lower == r.distance && r.upper == r.distance && r.distance < cap)) {
    fail(out, query, "exact below the cap, but the interval is not [d, d] below it", r, asked);
  }
}

void checkWitnesses(const StressCase& c, const Truth& t, const DistanceResult& r, bool swapped, const std::string& query,
                    std::vector<Failure>& out) {
  const Mesh& first = swapped ? c.b : c.a;
  const Mesh& second = swapped ? c.a : c.b;
  const Pose& poseFirst = swapped ? c.poseB : c.poseA;
  const Pose& poseSecond = swapped ? c.poseA : c.poseB;
  const bool valid = r.triangleA >= 0 && std::size_t(r.triangleA) < first.triangleCount() && r.triangleB >= 0 &&
                     std::size_t(r.triangleB) < second.triangleCount();
  if (!valid) {
    fail(out, query, "witness triangle index out of range", r,
         "triangles " + std::to_string(r.triangleA) + ", " + std::to_string(r.triangleB));
    return;
  }
  const auto ta = oracle::posedTriangle(first, poseFirst, std::size_t(r.triangleA));
  const auto tb = oracle::posedTriangle(second, poseSecond, std::size_t(r.triangleB));
  const double offA = double(oracle::pointTriangleDistance(oracle::Quad3(r.witnessA), ta[0], ta[1], ta[2]));
  const double offB = double(oracle::pointTriangleDistance(oracle::Quad3(r.witnessB), tb[0], tb[1], tb[2]));
  const double realized = (r.witnessA - r.witnessB).norm();
  std::ostringstream w;
  w << "witnessA " << exactNumber(offA) << " off triangle " << r.triangleA << ", witnessB " << exactNumber(offB)
    << " off triangle " << r.triangleB << ", |wA - wB| " << exactNumber(realized) << ", slack "
    << exactNumber(t.witnessSlack);
  if (!(offA <= t.witnessSlack && offB <= t.witnessSlack)) fail(out, query, "witness off its triangle", r, w.str());
  if (!(std::abs(realized - r.distance) <= t.witnessSlack)) fail(out, query, "witnesses do not realize the distance", r, w.str());
}

void checkHierarchy(const Mesh& mesh, const std::string& query, std::vector<Failure>& out) {
  const MeshHierarchy* tree = mesh.hierarchy();
  if (tree == nullptr) {
    out.push_back({query + ": no hierarchy after buildHierarchy()", mesh.name()});
    return;
  }
  // positionInOrder must invert order: the traversal asks by it whether a node holds a triangle.
  const std::vector<std::uint32_t>& order = tree->order();
  const std::vector<std::uint32_t>& position = tree->positionInOrder();
  bool inverse = order.size() == mesh.triangleCount() && position.size() == order.size();
  for (std::size_t k = 0; inverse && k < order.size(); ++k) {
    inverse = order[k] < position.size() && position[order[k]] == k;
  }
  if (!inverse) out.push_back({query + ": positionInOrder is not the inverse of order", mesh.name()});
  double worst = 0.0, worstSlack = 0.0, worstOrthogonality = 0.0;
  std::size_t worstNode = 0;
  for (std::size_t i = 0; i < tree->nodes().size(); ++i) {
    const MeshHierarchy::Node& node = tree->nodes()[i];
    // The representative point the traversal offers as an upper bound must be a corner of one of
    // the node's own triangles, or the bound would not be a distance between the two meshes.
    const auto first = tree->order().begin() + node.t0, last = tree->order().begin() + node.t1;
    if (std::find(first, last, node.repTriangle) == last || node.repCorner > 2 ||
        node.repPoint != mesh.corner(node.repTriangle, static_cast<int>(node.repCorner))) {
      out.push_back({query + ": node's representative point is not on its triangles",
                     "node " + std::to_string(i) + ": triangle " + std::to_string(node.repTriangle) + " corner " +
                         std::to_string(node.repCorner)});
    }
    const OrientedBox& box = node.box;
    const double magnitude =
        std::max(mesh.maxAbsCoordinate(), box.center.cwiseAbs().maxCoeff() + box.half.cwiseAbs().maxCoeff());
    const double slack = kBoxRoundingUlps * tolerance::kEpsilon * magnitude;
    for (std::uint32_t k = node.t0; k < node.t1; ++k) {
      for (int corner = 0; corner < 3; ++corner) {
        const Vec3& p = mesh.corner(tree->order()[k], corner);
        for (int axis = 0; axis < 3; ++axis) {
          for (double sign : {1.0, -1.0}) {
            const Vec3 d = sign * box.axes.col(axis);
            const double outside = d.dot(p) - box.support(d);
            if (outside - slack > worst - worstSlack) {
              worst = outside;
              worstSlack = slack;
              worstNode = i;
              worstOrthogonality = (box.axes.transpose() * box.axes - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
            }
          }
        }
      }
    }
  }
  if (worst > worstSlack) {
    DistanceResult none;
    std::ostringstream w;
    w << "node " << worstNode << " of " << tree->nodes().size() << ": a corner lies " << exactNumber(worst)
      << " outside its box along a box axis (allowance " << exactNumber(worstSlack) << "), |axes^T axes - I| "
      << exactNumber(worstOrthogonality);
    out.push_back({query + ": vertex outside its node box", w.str()});
  }
}

namespace {

/// The settings a case's queries rotate through (by case index and path), chosen around the
/// oracle's value so that the decisions are sharp: 2 x tolerance on either side of it included.
struct Settings {
  double absTolerance, relTolerance, thresholds[2], cap;
};

Settings settingsFor(const Truth& t, std::uint64_t index, int path) {
  const double o = t.distance, d = t.diagonal, tol = t.tolerance;
  static constexpr double kTolerances[5][2] = {{1e-3, 0}, {0, 1e-2}, {1e-2, 1e-1}, {1e-6, 1e-6}, {0, 0}};
  const std::uint64_t k = index * 2 + std::uint64_t(path);
  Settings s;
  s.absTolerance = kTolerances[k % 5][0] * d;
  s.relTolerance = kTolerances[k % 5][1];
  const double positive = o > 0 ? o : 1e-3 * d;  // a length to take fractions of
  const double margins[8] = {0.0, 0.5 * positive, 0.97 * positive, 1.03 * positive, 2.0 * positive,
                             std::max(0.0, o - 2 * tol), o + 2 * tol, o};
  s.thresholds[0] = margins[k % 8];
  s.thresholds[1] = margins[(k + 3) % 8];
  const double caps[3] = {0.5 * positive, 2.0 * positive, o + 2 * tol};
  s.cap = caps[k % 3];
  if (!(s.cap > 0)) s.cap = 1e-3 * d > 0 ? 1e-3 * d : 1.0;  // cap must be > 0 (zero-size scenes)
  return s;
}

std::uint64_t caseStream(const StressCase& c) {
  std::uint64_t h = c.seed * 0x9e3779b97f4a7c15ULL + c.index;
  for (unsigned char ch : c.family) h = (h ^ ch) * 0x100000001b3ULL;
  return h;
}

Mesh withTree(const Mesh& m) {
  Mesh copy = m;
  copy.buildHierarchy();
  return copy;
}

}  // namespace

CaseReport checkCase(const StressCase& c, DistanceScratch& scratch) {
  CaseReport report;
  report.truth = consultOracle(c);
  const Truth& t = report.truth;
  std::vector<Failure>& out = report.failures;
  if (t.intersecting && t.distance > t.tolerance) {
    out.push_back({"oracle: predicate and distance disagree", "distance " + exactNumber(t.distance) + " but intersecting"});
  }
  if (c.penetrating && !t.intersecting) {
    out.push_back({kNotPenetrating, "distance " + exactNumber(t.distance)});
  }

  SeededRandom random(caseStream(c));
  const Mesh permutedA = permutedMesh(c.a, random), permutedB = permutedMesh(c.b, random);
  const Mesh treeA = withTree(c.a), treeB = withTree(c.b);
  const Mesh treePermutedA = withTree(permutedA), treePermutedB = withTree(permutedB);
  checkHierarchy(treeA, "tree A", out);
  checkHierarchy(treeB, "tree B", out);

  for (int path = 0; path < 2; ++path) {
    const std::string name = path == 0 ? "scratch " : "tree ";
    const Mesh& a = path == 0 ? c.a : treeA;
    const Mesh& b = path == 0 ? c.b : treeB;
    const Mesh& pa = path == 0 ? permutedA : treePermutedA;
    const Mesh& pb = path == 0 ? permutedB : treePermutedB;
    const Settings s = settingsFor(t, c.index, path);

    // Runs one query, records what every answer must satisfy, and returns it (or nothing if the
    // library threw: bad input is impossible here, so any exception is a failure).
    auto run = [&](const std::string& query, const Mesh& first, const Pose& poseFirst, const Mesh& second,
                   const Pose& poseSecond, const DistanceOptions& options, DistanceResult& r) {
      try {
        r = distance(first, poseFirst, second, poseSecond, options, scratch);
      } catch (const std::exception& e) {
        out.push_back({name + query + ": threw", e.what()});
        return false;
      }
      checkResultSanity(r, name + query, out);
      report.gjkMaxIterations = std::max(report.gjkMaxIterations, r.counters.gjkMaxIterations);
      return true;
    };
    auto recordError = [&](const DistanceResult& r) {
      const double e = std::abs(r.distance - t.distance);
      report.worstError = std::max(report.worstError, t.diagonal > 0 ? e / t.diagonal : e);
    };

    DistanceResult r;
    if (run("exact", a, c.poseA, b, c.poseB, DistanceOptions::exactDistance(), r)) {
      checkExact(t, r, c.penetrating, name + "exact", out);
      checkWitnesses(c, t, r, false, name + "exact", out);
      recordError(r);
      (path == 0 ? report.maxDepthScratch : report.maxDepthTree) = r.counters.maxDepth;
      if (path == 0) report.rootSplit = r.counters.pairsSplit > 0;
    }
    if (run("swapped", b, c.poseB, a, c.poseA, DistanceOptions::exactDistance(), r)) {
      checkExact(t, r, c.penetrating, name + "swapped", out);
      checkWitnesses(c, t, r, true, name + "swapped", out);
      recordError(r);
    }
    if (run("permuted", pa, c.poseA, pb, c.poseB, DistanceOptions::exactDistance(), r)) {
      checkExact(t, r, c.penetrating, name + "permuted", out);
      recordError(r);
    }
    if (run("tolerance", a, c.poseA, b, c.poseB, DistanceOptions::withTolerance(s.absTolerance, s.relTolerance), r)) {
      checkTolerance(t, s.absTolerance, s.relTolerance, r, name + "tolerance", out);
    }
    for (double margin : s.thresholds) {
      if (run("threshold", a, c.poseA, b, c.poseB, DistanceOptions::aboveThreshold(margin), r)) {
        checkThreshold(t, margin, c.penetrating, r, name + "threshold", out);
      }
    }
    if (run("cap", a, c.poseA, b, c.poseB, DistanceOptions::cappedAt(s.cap), r)) checkCap(t, s.cap, r, name + "cap", out);
  }
  return report;
}

std::string describeFailure(const Failure& f, const Truth& t) {
  std::ostringstream out;
  out << f.check << "\n    " << f.detail << "\n    oracle " << exactNumber(t.distance) << " diagonal "
      << exactNumber(t.diagonal) << " tolerance " << exactNumber(t.tolerance) << " intersecting "
      << (t.intersecting ? "yes" : "no");
  return out.str();
}

}  // namespace adsd::stress
