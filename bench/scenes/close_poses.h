#pragma once
/// \file
/// \brief Close-proximity poses for a mesh pair: random orientations, gaps drawn from a band of
/// fractions of the scene size, convex hulls overlapping (the case the paper's sec. 6 is for).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "adsd/mesh.h"
#include "seeded_random.h"

namespace adsd::bench {

/// \brief One query's placement: poses of A and B and the gap the placement aimed at.
struct PosePair {
  Pose a = Pose::Identity();
  Pose b = Pose::Identity();
  /// The gap aimed at, in scene units (the placement reaches it to within the bisection's
  /// resolution; the exact distance is what the methods under test compute).
  double targetGap = 0.0;
};

struct ClosePoseSpec {
  std::size_t count = 60;
  std::uint64_t seed = 20240601;
  /// Gaps are log-uniform between these fractions of the reference length (the larger of the
  /// two meshes' bounding-box diagonals).
  double minGapFraction = 0.001;
  double maxGapFraction = 0.05;
  /// Drawings to try before giving up (each rejected one had non-overlapping hulls or no
  /// crossing of the target gap along its direction).
  std::size_t maxAttempts = 20000;
};

/// Minimum distance between the meshes at the given poses, 0 when they intersect.
using GapFunction = std::function<double(const Pose& poseA, const Pose& poseB)>;
/// Whether the convex hulls of the meshes intersect at the given poses.
using HullOverlapFunction = std::function<bool(const Pose& poseA, const Pose& poseB)>;

struct ClosePoseStats {
  std::size_t attempts = 0;
  std::size_t rejectedSeparateHulls = 0;
  std::size_t rejectedNoCrossing = 0;
  std::size_t gapEvaluations = 0;
};

/// Bisection steps along the approach line, at least: each halves the bracket
/// [0, 1.1 (rA + rB) + max(1, band's top) L], 2.1 L long for bands up to L, so 40 steps leave it
/// under 2e-12 L: the gap reached exceeds the target by far less than the band's width (the near
/// band's low end is 1e-3 L). Bands reaching lower take more (placementBisectionSteps).
constexpr int kPlacementBisectionSteps = 40;

/// Steps that leave a bracket of length \p bracket under 1e-6 of the smallest gap aimed at.
inline int placementBisectionSteps(double bracket, double smallestGap) {
  const double needed = std::ceil(std::log2(bracket / (1e-6 * smallestGap)));
  return std::max(kPlacementBisectionSteps, std::isfinite(needed) ? static_cast<int>(needed) : 0);
}

/// \brief Reference length of a pair: the larger bounding-box diagonal (mesh frames).
inline double referenceLength(const Mesh& a, const Mesh& b) {
  return std::max(a.bounds().diagonal().norm(), b.bounds().diagonal().norm());
}

/// Steps of bracketFromOutside's march before it gives up on a line.
constexpr int kPlacementMarchSteps = 600;

/// Brackets the outermost crossing of the target gap along B's approach line, for a drawing whose
/// centres coinciding leave the meshes apart (a small mesh inside a large closed one: the dragon
/// at the centre of a bunny 60 times its size). B comes in from \p hi, where the gap exceeds the
/// target, in steps of the gap's excess over the target: moving B by s changes the gap by at most
/// s, so such a step passes no crossing. Steps are at least hi / 512 (one that long may pass a
/// narrow dip below the target, and the crossing found is then not the outermost), and bisection
/// finishes from the first bracket. On success [lo, hi] holds a crossing with gap(lo) < target <= gap(hi); false
/// when the line never comes within the target.
template <typename PlaceB>
bool bracketFromOutside(const GapFunction& gap, const Pose& poseA, const PlaceB& placeB, double target, double& lo,
                        double& hi, ClosePoseStats& stats) {
  const double minStep = hi / 512.0;
  double outside = hi;
  for (int step = 0; step < kPlacementMarchSteps; ++step) {
    ++stats.gapEvaluations;
    const double excess = gap(poseA, placeB(outside)) - target;
    if (excess < 0.0) {
      lo = outside;
      return true;
    }
    hi = outside;
    outside -= std::max(excess, minStep);
    if (outside < 0.0) return false;
  }
  return false;
}

/// \brief Draws poses where B, turned at random, approaches A (turned at random) along a random
/// line through A's bounding-box centre, stopping where the gap equals a target drawn log-uniform
/// from the spec's band. Both meshes rotate about their bounding-box centres; A's centre sits at
/// the world origin.
///
/// The stop is found by bisection on the offset s of B's centre along the line: at s = 0 the
/// centres coincide (for our scenes the meshes then intersect, gap 0 < target); beyond
/// s = rA + rB + L the bounding spheres are L apart (gap > target). The gap is continuous in s, so
/// a crossing exists whenever gap(0) < target; the bisection keeps gap(s_hi) >= target and
/// returns s_hi. Where gap(0) >= target (B inside a large closed A), bracketFromOutside finds the
/// first crossing coming in from s_hi. Drawings whose hulls do not overlap are rejected. Throws std::runtime_error if
/// fewer than spec.count poses are found within spec.maxAttempts drawings.
inline std::vector<PosePair> makeClosePoses(const Mesh& a, const Mesh& b, const ClosePoseSpec& spec,
                                            const GapFunction& gap, const HullOverlapFunction& hullsOverlap,
                                            ClosePoseStats* stats = nullptr) {
  const Eigen::AlignedBox3d boxA = a.bounds(), boxB = b.bounds();
  const Vec3 centreA = boxA.center(), centreB = boxB.center();
  const double radiusA = 0.5 * boxA.diagonal().norm(), radiusB = 0.5 * boxB.diagonal().norm();
  const double length = referenceLength(a, b);

  SeededRandom random(spec.seed);
  ClosePoseStats local;
  std::vector<PosePair> poses;
  while (poses.size() < spec.count) {
    if (local.attempts++ >= spec.maxAttempts) {
      throw std::runtime_error("makeClosePoses: only " + std::to_string(poses.size()) + " of " +
                               std::to_string(spec.count) + " poses found in " +
                               std::to_string(spec.maxAttempts) + " drawings");
    }
    const Eigen::Quaterniond turnA = random.rotation(), turnB = random.rotation();
    const Vec3 line = random.direction();
    const double target =
        length * std::exp(random.uniform(std::log(spec.minGapFraction), std::log(spec.maxGapFraction)));

    PosePair pair;
    pair.targetGap = target;
    pair.a = Pose::Identity();
    pair.a.rotate(turnA).translate(-centreA);
    auto placeB = [&](double s) {
      Pose p = Pose::Identity();
      p.translate(s * line).rotate(turnB).translate(-centreB);
      return p;
    };

    double lo = 0.0, hi = 1.1 * (radiusA + radiusB) + std::max(1.0, spec.maxGapFraction) * length;
    ++local.gapEvaluations;
    if (gap(pair.a, placeB(lo)) >= target && !bracketFromOutside(gap, pair.a, placeB, target, lo, hi, local)) {
      ++local.rejectedNoCrossing;
      continue;
    }
    const int steps = placementBisectionSteps(hi - lo, spec.minGapFraction * length);
    for (int step = 0; step < steps; ++step) {
      const double mid = 0.5 * (lo + hi);
      ++local.gapEvaluations;
      (gap(pair.a, placeB(mid)) < target ? lo : hi) = mid;
    }
    pair.b = placeB(hi);
    if (!hullsOverlap(pair.a, pair.b)) {
      ++local.rejectedSeparateHulls;
      continue;
    }
    poses.push_back(pair);
  }
  if (stats) *stats = local;
  return poses;
}

}  // namespace adsd::bench
