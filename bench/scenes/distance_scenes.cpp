#include "distance_scenes.h"

#include <cmath>
#include <cstdio>

#include "adsd/error.h"
#include "adsd/io/load_mesh.h"
#include "adsd/problem_scenes.h"
#include "adsd/shapes.h"
#include "mesh_cache.h"

namespace adsd::bench {
namespace {

Mesh loadCached(const std::string& fileName) {
  const std::string path = cachedMesh(fileName);
  if (std::FILE* f = std::fopen(path.c_str(), "rb")) {
    std::fclose(f);
  } else {
    throw InputError(path + ": not in the mesh cache; " + fetchHint());
  }
  return io::loadMesh(path);
}

/// A rigid scene: \p count close poses of the pair, placed with the caller's placement.
DistanceScene rigidScene(std::string name, std::string description, Mesh a, Mesh b, std::uint64_t seed,
                         std::size_t count, const PlacementFactory& placement) {
  DistanceScene scene(std::move(name), std::move(description), std::move(a), std::move(b));
  scene.referenceLength = referenceLength(scene.a, scene.b);
  ClosePoseSpec spec;
  spec.count = count;
  spec.seed = seed;
  const Placement place = placement(scene.a, scene.b);
  scene.poses = makeClosePoses(scene.a, scene.b, spec, place.gap, place.hullsOverlap);
  return scene;
}

// The deforming teddies (paper sec. 7, "deforming teddy bears"): B rests at a gap of
// kTeddyRestGap · L from A, then sways along the line between the centres by up to
// kTeddySway · L while both surfaces ripple by up to kTeddyRipple · L per coordinate. The
// closest approach (rest gap - sway - 2 · √3 · ripple ≈ 0.005 L) keeps most frames apart, and
// the surfaces touch where a ripple crest meets the sway's nearest point, as in the paper's
// animation. Periods in frames: sway 400, ripple 250, so 1 000 frames hold several of each.
constexpr double kTeddyRestGap = 0.025;    // fraction of L
constexpr double kTeddySway = 0.01;        // fraction of L
constexpr double kTeddyRipple = 0.003;     // fraction of L
constexpr double kTeddyWavelength = 0.5;   // fraction of L: a few bumps across a bear
constexpr double kTeddySwayPeriod = 400;   // frames
constexpr double kTeddyRipplePeriod = 250; // frames

SmoothDeformation ripple(SeededRandom& random, double length) {
  SmoothDeformation d;
  d.amplitude = kTeddyRipple * length;
  const double waveNumber = 2.0 * M_PI / (kTeddyWavelength * length);
  for (int k = 0; k < 3; ++k) {
    d.waveVector[k] = waveNumber * random.direction();
    d.phase[k] = random.uniform(0.0, 2.0 * M_PI);
  }
  d.angularFrequency = 2.0 * M_PI / kTeddyRipplePeriod;
  return d;
}

DistanceScene teddies(std::size_t frames, const PlacementFactory& placement) {
  Mesh bear = loadCached("bear.off");
  DistanceScene scene("teddies_deforming",
                      "CGAL bear x 2, " + std::to_string(frames) + " frames of a smooth ripple, B swaying close",
                      bear, bear);
  scene.deforming = true;
  scene.referenceLength = referenceLength(scene.a, scene.b);
  const double length = scene.referenceLength;

  ClosePoseSpec spec;
  spec.count = 1;
  spec.seed = 0x7EDD1E5;
  spec.minGapFraction = spec.maxGapFraction = kTeddyRestGap;
  const Placement place = placement(scene.a, scene.b);
  const PosePair rest = makeClosePoses(scene.a, scene.b, spec, place.gap, place.hullsOverlap).front();
  const Vec3 line =
      (rest.b * scene.b.bounds().center() - rest.a * scene.a.bounds().center()).normalized();

  SeededRandom random(spec.seed + 1);
  scene.deformA = ripple(random, length);
  scene.deformB = ripple(random, length);
  for (std::size_t i = 0; i < frames; ++i) {
    const double sway = -kTeddySway * length * std::sin(2.0 * M_PI * static_cast<double>(i) / kTeddySwayPeriod);
    PosePair frame = rest;
    frame.b = Eigen::Translation3d(sway * line) * rest.b;
    frame.targetGap = rest.targetGap + sway;
    scene.poses.push_back(frame);
  }
  return scene;
}

// The SE(2) problems, as problems/scenes/include/adsd/problem_scenes.h lists them: their robots
// only turn about z and stay at z = 0. The others are SE(3).
bool isPlanarProblem(const std::string& problem) {
  return problem == "office" || problem == "maze" || problem == "thin_wall";
}

constexpr const char* kProblemPrefix = "problem_";

// FNV-1a: the same seed for a problem on every compiler (std::hash is not specified).
std::uint64_t stableHash(const std::string& text) {
  std::uint64_t h = 0xCBF29CE484222325ull;
  for (unsigned char c : text) h = (h ^ c) * 0x100000001B3ull;
  return h;
}

DistanceScene planningScene(const std::string& problem, std::size_t count, const PlacementFactory& placement) {
  for (shapes::ProblemScene& p : shapes::allProblemScenes()) {
    if (p.name != problem) continue;
    // cow_doorway's robot is the real cow, re-centred on its vertex mean as the planner does.
    Mesh robot = p.robot.empty() ? shapes::centredOnVertexMean(loadCached("cow.off")) : std::move(p.robot.front());
    DistanceScene scene(kProblemPrefix + problem,
                        "planning problem " + problem + (isPlanarProblem(problem) ? " (SE(2))" : " (SE(3))") +
                            ": robot near obstacles",
                        std::move(robot), std::move(p.environment));
    scene.planning = true;
    scene.referenceLength = scene.a.bounds().diagonal().norm();
    NearObstacleSpec spec;
    spec.count = count;
    spec.seed = stableHash(problem);
    spec.planar = isPlanarProblem(problem);
    spec.region = scene.b.bounds();
    const Placement place = placement(scene.a, scene.b);
    scene.poses = makeNearObstaclePoses(scene.a, scene.b, spec, place.gap);
    return scene;
  }
  throw InputError("unknown planning problem '" + problem + "'");
}

}  // namespace

void DistanceScene::verticesAt(std::size_t i, std::vector<Vec3>& verticesA, std::vector<Vec3>& verticesB) const {
  if (!deforming) {
    verticesA = a.vertices();
    verticesB = b.vertices();
    return;
  }
  const double t = static_cast<double>(i);
  deformA.apply(a.vertices(), t, verticesA);
  deformB.apply(b.vertices(), t, verticesB);
}

const std::vector<std::string>& distanceSceneNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all = {"cows", "stick_dragon", "teddies_deforming", "camels", "bunnies"};
    for (const shapes::ProblemScene& p : shapes::allProblemScenes()) all.push_back(kProblemPrefix + p.name);
    return all;
  }();
  return names;
}

DistanceScene makeDistanceScene(const std::string& name, const SceneSize& size, const PlacementFactory& placement) {
  if (name == "cows") {
    return rigidScene(name, "CGAL cow x 2", loadCached("cow.off"), loadCached("cow.off"), 0xC0C0, size.rigidPoses,
                      placement);
  }
  if (name == "stick_dragon") {
    // The paper's stick: a thin rod about half the dragon's length (radius 1.5 %, length 60 % of
    // the dragon's bounding-box diagonal).
    Mesh dragon = loadCached("dragon_res4.ply");
    const double size0 = dragon.bounds().diagonal().norm();
    return rigidScene(name, "capsule stick x npm dragon (res4)", shapes::capsule(0.015 * size0, 0.3 * size0, 32),
                      std::move(dragon), 0xD2A60, size.rigidPoses, placement);
  }
  if (name == "teddies_deforming") return teddies(size.frames, placement);
  if (name == "camels") {
    return rigidScene(name, "CGAL camel x 2 (horse stand-in)", loadCached("camel.off"), loadCached("camel.off"),
                      0xCA3E1, size.rigidPoses, placement);
  }
  if (name == "bunnies") {
    return rigidScene(name, "npm bunny x 2", loadCached("bunny.off"), loadCached("bunny.off"), 0xB0B, size.rigidPoses,
                      placement);
  }
  if (name.rfind(kProblemPrefix, 0) == 0) {
    return planningScene(name.substr(std::char_traits<char>::length(kProblemPrefix)), size.rigidPoses, placement);
  }
  throw InputError("unknown distance scene '" + name + "'");
}

}  // namespace adsd::bench
