#include <cmath>

#include "adsd/problem_scenes.h"
#include "adsd/shapes.h"

namespace adsd::shapes {

namespace {

constexpr double kLoopRadius = 1.0;
constexpr double kTubeRadius = 0.1;
/// Rise of the helix over one turn: the tails cross 0.5 apart, leaving a 0.3 gap between their
/// surfaces for the other tube (0.2 thick) to pass: the narrow passage of the puzzle.
constexpr double kPitch = 0.5;
/// How far (radians) each tail runs past the crossing before turning into a straight leg.
constexpr double kOverlap = 0.5;
constexpr double kLegLength = 0.8;

/// Centre line of one piece: a helical loop about z of one turn plus 2 kOverlap, its tails crossing
/// at the bottom (y = -R) kPitch apart in z, then straight legs continuing the ends along their
/// tangents. Angle a runs from -pi/2 - kOverlap to 3 pi/2 + kOverlap; the height is
/// kPitch (a - pi/2) / 2 pi, so the loop's top (a = pi/2) is at z = 0 and angle 0 is at
/// (R, 0, -kPitch / 4).
std::vector<Vec3> alphaCentreLine() {
  constexpr int samples = 96;
  const double begin = -0.5 * M_PI - kOverlap;
  const double end = 1.5 * M_PI + kOverlap;
  const auto at = [](double a) {
    return Vec3(kLoopRadius * std::cos(a), kLoopRadius * std::sin(a), kPitch * (a - 0.5 * M_PI) / (2.0 * M_PI));
  };
  const auto tangent = [](double a) {
    return Vec3(-kLoopRadius * std::sin(a), kLoopRadius * std::cos(a), kPitch / (2.0 * M_PI)).normalized();
  };
  std::vector<Vec3> line;
  line.push_back(at(begin) - kLegLength * tangent(begin));
  for (int i = 0; i <= samples; ++i) line.push_back(at(begin + (end - begin) * i / samples));
  line.push_back(at(end) + kLegLength * tangent(end));
  return line;
}

}  // namespace

// Piece A (the environment) lies in the xy plane; piece B (the robot), centred on its vertex
// mean, starts at the origin turned 90° about x, so its loop stands in the xz plane with its axis
// along y. A is placed so that its tube at angle 0 (running along y there) passes through the
// centre of B's loop, and B's loop passes through the middle of A's: linked like chain links.
// The goal puts B at (0, 0, 3.5), unlinked.
ProblemScene alphaPuzzleScene() {
  const Mesh piece = sweptTube(alphaCentreLine(), kTubeRadius, 16);
  const Mesh robot = centredOnVertexMean(piece);
  Vec3 mean = Vec3::Zero();
  for (const Vec3& v : piece.vertices()) mean += v;
  mean /= static_cast<double>(piece.vertices().size());
  // B's loop axis is the piece frame's z axis; its loop is centred (mid-height) on the piece
  // frame's origin, which is at -mean in the robot's body frame.
  const Eigen::AngleAxisd startRotation(0.5 * M_PI, Vec3::UnitX());
  const Vec3 loopCentreB = startRotation * (-mean);
  Pose placeA = Pose::Identity();
  placeA.translate(loopCentreB - Vec3(kLoopRadius, 0, -kPitch / 4));
  return {"alpha_puzzle", {robot}, merge({piece}, {placeA})};
}

}  // namespace adsd::shapes
