#pragma once
/// \file
/// \brief Robot states near obstacles for the planning problems: the robot starts free at a random
/// state and slides along a random direction until its clearance to the environment equals a
/// target drawn from a band (the states a planner's validity checker sees next to walls).

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "close_poses.h"
#include "seeded_random.h"

namespace adsd::bench {

struct NearObstacleSpec {
  std::size_t count = 60;
  std::uint64_t seed = 1;
  /// Clearances log-uniform between these fractions of the robot's bounding-box diagonal.
  double minGapFraction = 0.001;
  double maxGapFraction = 0.05;
  /// SE(2): yaw only, z = 0, sliding in the xy plane. Otherwise any rotation and direction.
  bool planar = false;
  /// Where the robot's origin may start and slide (the environment's bounds, say).
  Eigen::AlignedBox3d region;
  std::size_t maxAttempts = 20000;
};

/// Sliding stops when the clearance exceeds the target by at most this fraction of the target:
/// the clearance reached is then the target to 6 digits, plenty for a band two decades wide.
constexpr double kSlideConvergence = 1e-6;
/// Steps of one slide before it is abandoned (grazing a wall almost parallel converges slowly).
constexpr int kMaxSlideSteps = 400;

/// \brief States of \p robot (pose a of each PosePair) against \p environment (pose b, the
/// identity) with clearances in the spec's band.
///
/// Sliding is conservative advancement: translating the robot by δ without turning it changes its
/// clearance by at most δ, so a step of (clearance − target) never passes the target; the
/// clearance decreases towards the target along the ray until the first obstacle in the way.
/// A state that starts with clearance below the target, or whose slide leaves the region or does
/// not converge, is drawn again. Throws std::runtime_error when spec.maxAttempts run out.
inline std::vector<PosePair> makeNearObstaclePoses(const Mesh& robot, const Mesh& environment,
                                                   const NearObstacleSpec& spec, const GapFunction& gap) {
  (void)environment;  // reached only through gap(); named for the reader
  const double robotSize = robot.bounds().diagonal().norm();
  SeededRandom random(spec.seed);
  std::vector<PosePair> poses;
  std::size_t attempts = 0;
  while (poses.size() < spec.count) {
    if (attempts++ >= spec.maxAttempts) {
      throw std::runtime_error("makeNearObstaclePoses: only " + std::to_string(poses.size()) + " of " +
                               std::to_string(spec.count) + " states found in " +
                               std::to_string(spec.maxAttempts) + " drawings");
    }
    Eigen::Quaterniond turn;
    Vec3 position, direction;
    const Vec3 lo = spec.region.min(), hi = spec.region.max();
    if (spec.planar) {
      const double yaw = random.uniform(-M_PI, M_PI), heading = random.uniform(-M_PI, M_PI);
      turn = Eigen::AngleAxisd(yaw, Vec3::UnitZ());
      position = Vec3(random.uniform(lo.x(), hi.x()), random.uniform(lo.y(), hi.y()), 0.0);
      direction = Vec3(std::cos(heading), std::sin(heading), 0.0);
    } else {
      turn = random.rotation();
      position = Vec3(random.uniform(lo.x(), hi.x()), random.uniform(lo.y(), hi.y()), random.uniform(lo.z(), hi.z()));
      direction = random.direction();
    }
    const double target =
        robotSize * std::exp(random.uniform(std::log(spec.minGapFraction), std::log(spec.maxGapFraction)));
    auto place = [&](const Vec3& p) {
      Pose pose = Pose::Identity();
      pose.translate(p).rotate(turn);
      return pose;
    };

    double clearance = gap(place(position), Pose::Identity());
    if (!(clearance >= target)) continue;
    bool converged = false;
    for (int step = 0; step < kMaxSlideSteps; ++step) {
      if (clearance - target <= kSlideConvergence * target) {
        converged = true;
        break;
      }
      position += (clearance - target) * direction;
      if (!spec.region.contains(position)) break;
      clearance = gap(place(position), Pose::Identity());
    }
    if (!converged) continue;
    PosePair pair;
    pair.a = place(position);
    pair.b = Pose::Identity();
    pair.targetGap = target;
    poses.push_back(pair);
  }
  return poses;
}

}  // namespace adsd::bench
