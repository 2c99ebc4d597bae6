/// \file
/// \brief Every query mode against FCL, band by band: near contact, mid range, far apart,
/// uniform states over a planning problem's environment box, and in collision.
///
///   bench_bands [--scenes a,b,...] [--pairs A.off:B.off,...] [--bands near,...] [--poses N]
///               [--rounds R] [--seed S] [--csv FILE] [--summary-md FILE] [--quick] [--counters]
///               [--scratch]
///
/// Why bands: a planner asks for clearance at every distance, mostly far from contact, while
/// bench_scenes places its queries near contact only. Each band is drawn with FCL (placement
/// never uses the code under test); both libraries keep their trees (ours: buildHierarchy, FCL:
/// prebuilt OBBRSS). Methods, interleaved query by query (timing.h): our exact distance, our 1 %
/// tolerance, our validity query (D = 0), our distance capped at 5 % of the reference length, FCL's
/// exact distance and FCL's collide. Bands (fractions of the reference length L: the larger
/// bounding-box diagonal of a mesh pair, the robot's diagonal for a planning problem):
///
/// | band      | how the poses are drawn                                                     |
/// |-----------|-----------------------------------------------------------------------------|
/// | near      | gaps log-uniform in [0.1 %, 5 %] of L                                       |
/// | mid       | gaps log-uniform in [5 %, 30 %] of L                                        |
/// | far       | gaps log-uniform in [30 %, 100 %] of L                                      |
/// | uniform   | planning problems: uniform states over the environment's box (valid or not) |
/// | collision | in contact (FCL's collide): validity only, the distance modes answer 0      |
///
/// Two more bands run only when --bands names them (the default run, and the issue's figures, are
/// the five above; drawn after them, so naming them leaves the five's poses unchanged):
///
/// | band      | how the poses are drawn                                                     |
/// |-----------|-----------------------------------------------------------------------------|
/// | touching  | gaps log-uniform in [1e-6, 1e-3] of L: grazing contact, below the near band |
/// | distant   | gaps log-uniform in [1, 10] × L: beyond the far band                        |
///
/// Mesh pairs approach along a random line (close_poses.h, without its hull-overlap filter: far
/// pairs' hulls are apart); a problem's robot slides from a random state until its clearance is
/// the target (near_obstacle_poses.h). Every exact answer must agree with FCL's within 1e-9 L and
/// every validity answer with FCL's collide; the program exits 3 otherwise, so a speed-up cannot
/// hide a wrong answer. Prints per scene and band the median microseconds of each method, the
/// ratios of medians, the median node pairs of our exact, tolerance and validity queries and the
/// largest error against FCL; then a summary per band over the scenes (median and worst scene).
/// --csv writes one row per query, method and round.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "adsd/cli/command_line.h"
#include "adsd/distance.h"
#include "adsd/error.h"
#include "adsd/io/load_mesh.h"
#include "fcl_models.h"
#include "fcl_placement.h"
#include "scenes/close_poses.h"
#include "scenes/distance_scenes.h"
#include "scenes/near_obstacle_poses.h"
#include "scenes/seeded_random.h"
#include "timing.h"

namespace {

using adsd::Mesh;
using adsd::Pose;
using adsd::Vec3;
using adsd::bench::PosePair;

struct Options {
  std::vector<std::string> scenes;
  std::vector<std::pair<std::string, std::string>> pairs;
  std::size_t poses = 40;
  int rounds = 3;
  std::uint64_t seed = 2611;
  std::string csv;
  std::string summaryMarkdown;
  std::vector<std::string> bands;  // empty: every band
  bool counters = false;           // also print each band's work per query, ours and FCL's
  bool scratch = false;            // also time both libraries without kept trees (deforming meshes)
};

/// One band's poses and how they were drawn.
struct Band {
  std::string name;
  double minFraction = 0.0, maxFraction = 0.0;  // gap band (fractions of L); 0, 0: not a gap band
  std::vector<PosePair> poses;
};

/// The cap of the capped mode, as a fraction of L: a clearance objective that saturates at a
/// safety margin (a planner needs no clearance beyond it).
constexpr double kCapFraction = 0.05;
/// The relative tolerance of the tolerance mode (the issue's 1 %).
constexpr double kRelativeTolerance = 0.01;
/// Largest disagreement with FCL's exact distance, as a fraction of L, before the run fails: both
/// are exact to about 1e-15 L; FCL's triangle distance loses a few digits on slivers.
constexpr double kAgreement = 1e-9;
/// Every band, in the order the summary lists them.
const std::string kBandNames[] = {"touching", "near", "mid", "far", "distant", "uniform", "collision"};

std::vector<std::string> splitList(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    if (!item.empty()) out.push_back(item);
  }
  return out;
}

/// The command line (adsd::cli: the same rules and messages as every program here).
adsd::cli::CommandLine commandLine() {
  adsd::cli::CommandLine line(
      "bench_bands",
      "bench_bands [--scenes a,b,...] [--pairs A:B,...] [--bands near,...] [--poses N] [--rounds R] [--seed S]\n"
      "            [--csv FILE] [--summary-md FILE] [--quick] [--counters] [--scratch]",
      "Every query mode against FCL, band by band: near contact, mid range, far apart, uniform planning states, "
      "in collision.",
      "Exit status: 0, 2 for a bad command line or a missing mesh, 3 when an answer disagrees with FCL's.");
  line.options()("scenes", adsd::cli::value("LIST"),
                 "scenes of bench_scenes (mesh pairs, problem_NAME planning problems), comma-separated, or 'all' for "
                 "every rigid one (default cows,bunnies,camels)")(
      "pairs", adsd::cli::value("A:B,..."), "more mesh pairs, FILE_A:FILE_B, comma-separated (any mesh file adsd reads)")(
      "bands", adsd::cli::value("LIST"),
      "bands to run, comma-separated (default near,mid,far,uniform,collision; touching, gaps 1e-6 to 1e-3 L, and "
      "distant, 1 to 10 L, only when named)")(
      "poses", adsd::cli::value("N"), "queries per band (default 40)")(
      "rounds", adsd::cli::value("R"), "timed rounds over each band's queries (default 3)")(
      "seed", adsd::cli::value("S"), "seed of every band's drawing (default 2611)")(
      "csv", adsd::cli::value("FILE"), "one row per query and method: scene, band, method, query, L, answer, microseconds")(
      "summary-md", adsd::cli::value("FILE"), "also write the per-band summary as a Markdown table")(
      "quick", "10 poses, 1 round: a smoke run")(
      "counters", "also print each band's mean work per exact query, ours (node pairs, splits, GJK runs, triangle "
                  "pairs) and FCL's (bounding-volume and triangle tests), counted in an untimed pass, and a 1 % "
                  "tolerance's work in per cent of it, ours and FCL's (rel_err 0.01)")(
      "scratch", "also time, per band, our exact query from scratch (the paper's stages, no trees: what a deforming "
                 "mesh gets) against FCL rebuilding both OBBRSS trees and then measuring");
  return line;
}

Options optionsFrom(const adsd::cli::Arguments& given) {
  Options o;
  o.poses = given.whole("poses", 1, 100000).value_or(o.poses);
  o.rounds = static_cast<int>(given.whole("rounds", 1, 1000).value_or(static_cast<std::uint64_t>(o.rounds)));
  o.seed = given.whole("seed").value_or(o.seed);
  o.csv = given.text("csv").value_or("");
  o.summaryMarkdown = given.text("summary-md").value_or("");
  if (given.has("quick")) o.poses = 10, o.rounds = 1;
  o.counters = given.has("counters");
  o.scratch = given.has("scratch");
  o.bands = splitList(given.text("bands").value_or(""));
  for (const std::string& band : o.bands) {
    if (std::find(std::begin(kBandNames), std::end(kBandNames), band) == std::end(kBandNames)) {
      throw adsd::cli::UsageError("--bands: expected touching, near, mid, far, distant, uniform or collision, got '" +
                                  band + "'");
    }
  }
  const std::string scenes = given.text("scenes").value_or("cows,bunnies,camels");
  if (scenes == "all") {
    for (const std::string& name : adsd::bench::distanceSceneNames()) {
      if (name != "teddies_deforming") o.scenes.push_back(name);
    }
  } else {
    o.scenes = splitList(scenes);
  }
  for (const std::string& pair : splitList(given.text("pairs").value_or(""))) {
    const auto colon = pair.find(':');
    if (colon == std::string::npos) throw adsd::cli::UsageError("--pairs: expected FILE_A:FILE_B, got '" + pair + "'");
    o.pairs.emplace_back(pair.substr(0, colon), pair.substr(colon + 1));
  }
  return o;
}

/// Uniform states over \p region: SE(2) (yaw, z = 0) or SE(3), as OMPL's samplers draw them.
std::vector<PosePair> uniformStates(const Eigen::AlignedBox3d& region, bool planar, std::size_t count,
                                    adsd::bench::SeededRandom& random, const adsd::bench::GapFunction* keepIfColliding) {
  std::vector<PosePair> out;
  for (std::size_t attempt = 0; out.size() < count; ++attempt) {
    if (attempt > 200000) throw std::runtime_error("too few states in collision among 200000 uniform ones");
    PosePair p;
    const Vec3 lo = region.min(), hi = region.max();
    if (planar) {
      p.a = Eigen::Translation3d(random.uniform(lo.x(), hi.x()), random.uniform(lo.y(), hi.y()), 0.0) *
            Eigen::AngleAxisd(random.uniform(-M_PI, M_PI), Vec3::UnitZ());
    } else {
      p.a = Eigen::Translation3d(random.uniform(lo.x(), hi.x()), random.uniform(lo.y(), hi.y()),
                                 random.uniform(lo.z(), hi.z())) *
            random.rotation();
    }
    if (keepIfColliding && (*keepIfColliding)(p.a, p.b) > 0.0) continue;
    out.push_back(p);
  }
  return out;
}

/// Mesh-pair poses in contact: B's centre placed at a random offset within half the radii's sum
/// of A's, random turns, kept when FCL says they collide.
std::vector<PosePair> collidingPairPoses(const Mesh& a, const Mesh& b, std::size_t count,
                                         adsd::bench::SeededRandom& random, const adsd::bench::GapFunction& gap) {
  const Vec3 ca = a.bounds().center(), cb = b.bounds().center();
  const double reach = 0.25 * (a.bounds().diagonal().norm() + b.bounds().diagonal().norm());
  std::vector<PosePair> out;
  for (std::size_t attempt = 0; out.size() < count; ++attempt) {
    if (attempt > 200000) throw std::runtime_error("too few colliding poses among 200000");
    PosePair p;
    p.a = Pose::Identity();
    p.a.rotate(random.rotation()).translate(-ca);
    p.b = Pose::Identity();
    p.b.translate(random.uniform(0.0, reach) * random.direction()).rotate(random.rotation()).translate(-cb);
    if (gap(p.a, p.b) > 0.0) continue;
    out.push_back(p);
  }
  return out;
}

struct BandResult {
  std::string scene, band;
  double ours = 0, tolerance = 0, validity = 0, capped = 0, fclDistance = 0, fclCollide = 0;  // median us
  double nodePairsExact = 0, nodePairsTolerance = 0, nodePairsValidity = 0;  // medians
  double worstError = 0;          // max |ours - FCL| / L
  bool distances = true;          // false: the collision band (validity only)
  double scratch = 0, fclRebuild = 0;  // --scratch: median us from scratch, ours and FCL's (0: not run)
};

/// The mean work of an exact query over \p poses, ours on the trees and FCL's, in an untimed pass
/// (--counters): what explains a band's ratio (node pairs against bounding-volume tests, triangle
/// pairs against FCL's triangle tests). Then the same for a 1 % tolerance, ours and FCL's own
/// (rel_err 0.01), each in per cent of its exact query's: how much of the work a tolerance of that
/// size lets the best-first traversals of either library skip.
void printWork(const Mesh& a, const Mesh& b, const adsd::bench::FclObbrssModel& fa,
               const adsd::bench::FclObbrssModel& fb, const std::vector<PosePair>& poses) {
  // One scratch per mode, as the timed runs keep: a query's witness hint must not come from the
  // other mode's query of the same pose.
  adsd::DistanceScratch scratch, scratchTolerance;
  double nodePairs = 0, split = 0, gjk = 0, triangles = 0, fclVolumes = 0, fclTriangles = 0;
  double nodePairsTolerance = 0, trianglesTolerance = 0, fclVolumesTolerance = 0, fclTrianglesTolerance = 0;
  for (const PosePair& p : poses) {
    const adsd::DistanceResult t =
        adsd::distance(a, p.a, b, p.b, adsd::DistanceOptions::withTolerance(0.0, 0.01), scratchTolerance);
    nodePairsTolerance += static_cast<double>(t.counters.subMeshPairs);
    trianglesTolerance += static_cast<double>(t.counters.trianglePairsTested);
    const adsd::bench::FclDistanceWork wt = adsd::bench::fclDistanceWork(fa, p.a, fb, p.b, 0.01);
    fclVolumesTolerance += wt.boundingVolumeTests;
    fclTrianglesTolerance += wt.triangleTests;
    const adsd::DistanceResult r = adsd::distance(a, p.a, b, p.b, adsd::DistanceOptions::exactDistance(), scratch);
    nodePairs += static_cast<double>(r.counters.subMeshPairs);
    split += static_cast<double>(r.counters.pairsSplit);
    gjk += static_cast<double>(r.counters.gjkCalls);
    triangles += static_cast<double>(r.counters.trianglePairsTested);
    const adsd::bench::FclDistanceWork w = adsd::bench::fclDistanceWork(fa, p.a, fb, p.b);
    fclVolumes += w.boundingVolumeTests;
    fclTriangles += w.triangleTests;
  }
  const double n = static_cast<double>(poses.size());
  std::printf("%-34s work per exact query: ours %.0f node pairs (%.0f split, %.1f GJK), %.1f triangle pairs; FCL "
              "%.0f volume tests, %.1f triangle pairs\n",
              "", nodePairs / n, split / n, gjk / n, triangles / n, fclVolumes / n, fclTriangles / n);
  auto percent = [](double part, double whole) { return whole > 0 ? 100.0 * part / whole : 100.0; };
  std::printf("%-34s 1 %% tolerance, per cent of exact's work: ours %.0f %% of the node pairs, %.0f %% of the triangle "
              "pairs; FCL (rel_err 0.01) %.0f %% of the volume tests, %.0f %% of the triangle tests\n",
              "", percent(nodePairsTolerance, nodePairs), percent(trianglesTolerance, triangles),
              percent(fclVolumesTolerance, fclVolumes), percent(fclTrianglesTolerance, fclTriangles));
}

int runScene(const std::string& sceneName, const Mesh& a, const Mesh& b, bool planning, bool planar,
             double length, const Options& o, std::vector<BandResult>& results, std::ofstream* csv) {
  Mesh ta = a, tb = b;
  ta.buildHierarchy();
  tb.buildHierarchy();
  // FCL's triangles once: the prebuilt models use them, and --scratch's rebuilds (the indices stay).
  const std::vector<fcl::Triangle> fclTrianglesA = adsd::bench::fclTriangles(a);
  const std::vector<fcl::Triangle> fclTrianglesB = adsd::bench::fclTriangles(b);
  const auto fa = adsd::bench::buildObbrss(a.vertices(), fclTrianglesA);
  const auto fb = adsd::bench::buildObbrss(b.vertices(), fclTrianglesB);
  const adsd::bench::GapFunction gap = [&](const Pose& pa, const Pose& pb) {
    return std::max(0.0, adsd::bench::fclDistance(*fa, pa, *fb, pb).min_distance);
  };
  // Each scene draws from its own stream: the seed mixed with the scene's name (libstdc++'s string
  // hash, fixed for a given name, so a command draws the same poses on every run here).
  adsd::bench::SeededRandom random(o.seed ^ std::hash<std::string>{}(sceneName));

  auto drawGapBand = [&](Band& band) {
    if (planning) {
      adsd::bench::NearObstacleSpec spec;
      spec.count = o.poses;
      spec.seed = random.next();
      spec.minGapFraction = band.minFraction;
      spec.maxGapFraction = band.maxFraction;
      spec.planar = planar;
      spec.region = b.bounds();
      spec.maxAttempts = 20 * o.poses + 2000;
      try {
        band.poses = adsd::bench::makeNearObstaclePoses(a, b, spec, gap);
      } catch (const std::runtime_error& e) {
        // Some problems leave no room for a band (the alpha puzzle's robot is never 30 % of its
        // size from every obstacle inside the environment's box): said, and the band left out.
        std::printf("%-24s %-9s not drawn: %s\n", sceneName.c_str(), band.name.c_str(), e.what());
      }
    } else {
      adsd::bench::ClosePoseSpec spec;
      spec.count = o.poses;
      spec.seed = random.next();
      spec.minGapFraction = band.minFraction;
      spec.maxGapFraction = band.maxFraction;
      try {
        band.poses = adsd::bench::makeClosePoses(a, b, spec, gap, [](const Pose&, const Pose&) { return true; });
      } catch (const std::runtime_error& e) {
        // A pair given by --pairs may leave no room for a band either: said, and left out.
        std::printf("%-24s %-9s not drawn: %s\n", sceneName.c_str(), band.name.c_str(), e.what());
      }
    }
  };
  std::vector<Band> bands = {{"near", 0.001, 0.05, {}}, {"mid", 0.05, 0.3, {}}, {"far", 0.3, 1.0, {}}};
  for (Band& band : bands) drawGapBand(band);
  if (planning) {
    bands.push_back({"uniform", 0, 0, uniformStates(b.bounds(), planar, o.poses, random, nullptr)});
    bands.push_back({"collision", 0, 0, uniformStates(b.bounds(), planar, o.poses, random, &gap)});
  } else {
    bands.push_back({"collision", 0, 0, {}});
    try {
      bands.back().poses = collidingPairPoses(a, b, o.poses, random, gap);
    } catch (const std::runtime_error& e) {
      std::printf("%-24s %-9s not drawn: %s\n", sceneName.c_str(), "collision", e.what());
    }
  }
  // The bands beyond the issue's five, drawn last and only when named, so that the five draw the
  // same poses with or without them.
  for (Band extra : {Band{"touching", 1e-6, 1e-3, {}}, Band{"distant", 1.0, 10.0, {}}}) {
    if (std::find(o.bands.begin(), o.bands.end(), extra.name) == o.bands.end()) continue;
    drawGapBand(extra);
    bands.push_back(std::move(extra));
  }

  int status = 0;
  // One scratch per method: the scratch remembers the last answer's witness triangles (a hint for
  // the next query), and methods run back to back on the same pose, so a shared scratch would hand
  // each method the answer of the one before it. Per method, the hint comes from another pose of
  // the band, as it would from a planner's previous, unrelated query.
  adsd::DistanceScratch scratchExact, scratchTolerance, scratchCapped, scratchValidity, scratchFromScratch;
  for (const Band& band : bands) {
    if (!o.bands.empty() && std::find(o.bands.begin(), o.bands.end(), band.name) == o.bands.end()) continue;
    const std::size_t n = band.poses.size();
    if (n == 0) continue;
    const bool distances = band.name != "collision";
    // Each method's answer per query, by the method's name (validity: 1 free, 0 in contact); the
    // checks below and the CSV read them from here.
    std::map<std::string, std::vector<double>> answers;
    for (const char* name :
         {"exact", "tolerance", "capped", "fcl_distance", "validity", "fcl_collide", "scratch", "fcl_rebuild"}) {
      answers[name].assign(n, 0.0);
    }
    std::vector<double>& exact = answers["exact"];
    std::vector<double>& tolerance = answers["tolerance"];
    std::vector<double>& capped = answers["capped"];
    std::vector<double>& fclD = answers["fcl_distance"];
    std::vector<double>& freeOurs = answers["validity"];
    std::vector<double>& freeFcl = answers["fcl_collide"];
    std::vector<double>& fromScratch = answers["scratch"];
    std::vector<double>& fclRebuilt = answers["fcl_rebuild"];
    std::vector<double> pairsExact(n), pairsTolerance(n), pairsValidity(n);
    auto query = [&](std::size_t i, const adsd::DistanceOptions& options, adsd::DistanceScratch& scratch) {
      const PosePair& p = band.poses[i];
      return adsd::distance(ta, p.a, tb, p.b, options, scratch);
    };
    std::vector<adsd::bench::TimedMethod> methods;
    if (distances) {
      methods.push_back({"exact", [&](std::size_t i) {
                           const adsd::DistanceResult r = query(i, adsd::DistanceOptions::exactDistance(), scratchExact);
                           exact[i] = r.distance;
                           pairsExact[i] = static_cast<double>(r.counters.subMeshPairs);
                         }, {}, {}});
      methods.push_back({"tolerance", [&](std::size_t i) {
                           const adsd::DistanceResult r = query(i, adsd::DistanceOptions::withTolerance(0.0, kRelativeTolerance), scratchTolerance);
                           tolerance[i] = r.distance;
                           pairsTolerance[i] = static_cast<double>(r.counters.subMeshPairs);
                         }, {}, {}});
      methods.push_back({"capped", [&](std::size_t i) {
                           capped[i] = query(i, adsd::DistanceOptions::cappedAt(kCapFraction * length), scratchCapped).distance;
                         }, {}, {}});
      methods.push_back({"fcl_distance", [&](std::size_t i) {
                           const PosePair& p = band.poses[i];
                           fclD[i] = std::max(0.0, adsd::bench::fclDistance(*fa, p.a, *fb, p.b).min_distance);
                         }, {}, {}});
    }
    if (distances && o.scratch) {
      // Without trees, as for a deforming mesh: our query on the meshes as given (the paper's
      // stages), FCL's after rebuilding both trees from the vertices (the triangles' indices stay).
      methods.push_back({"scratch", [&](std::size_t i) {
                           const PosePair& p = band.poses[i];
                           fromScratch[i] = adsd::distance(a, p.a, b, p.b, adsd::DistanceOptions::exactDistance(),
                                                           scratchFromScratch).distance;
                         }, {}, {}});
      methods.push_back({"fcl_rebuild", [&](std::size_t i) {
                           const PosePair& p = band.poses[i];
                           const auto ra = adsd::bench::buildObbrss(a.vertices(), fclTrianglesA);
                           const auto rb = adsd::bench::buildObbrss(b.vertices(), fclTrianglesB);
                           fclRebuilt[i] = std::max(0.0, adsd::bench::fclDistance(*ra, p.a, *rb, p.b).min_distance);
                         }, {}, {}});
    }
    methods.push_back({"validity", [&](std::size_t i) {
                         const adsd::DistanceResult r = query(i, adsd::DistanceOptions::aboveThreshold(0.0), scratchValidity);
                         freeOurs[i] = r.status == adsd::DistanceStatus::aboveThreshold ? 1.0 : 0.0;
                         pairsValidity[i] = static_cast<double>(r.counters.subMeshPairs);
                       }, {}, {}});
    methods.push_back({"fcl_collide", [&](std::size_t i) {
                         const PosePair& p = band.poses[i];
                         freeFcl[i] = adsd::bench::fclCollide(*fa, p.a, *fb, p.b) ? 0.0 : 1.0;
                       }, {}, {}});
    adsd::bench::runInterleaved(methods, n, o.rounds);

    BandResult r;
    r.scene = sceneName;
    r.band = band.name;
    r.distances = distances;
    std::map<std::string, double> medians;
    for (const auto& m : methods) medians[m.name] = adsd::bench::median(m.micros);
    auto med = [&](const char* name) { return medians.at(name); };
    r.validity = med("validity");
    r.nodePairsValidity = adsd::bench::median(pairsValidity);
    r.fclCollide = med("fcl_collide");
    std::size_t validityDisagreements = 0;
    for (std::size_t i = 0; i < n; ++i) validityDisagreements += freeOurs[i] != freeFcl[i];
    if (validityDisagreements > 0) {
      std::fprintf(stderr, "bench_bands: %s %s: %zu validity answers differ from FCL's collide\n", sceneName.c_str(),
                   band.name.c_str(), validityDisagreements);
      status = 3;
    }
    if (distances) {
      r.ours = med("exact"), r.tolerance = med("tolerance"), r.capped = med("capped"), r.fclDistance = med("fcl_distance");
      if (o.scratch) r.scratch = med("scratch"), r.fclRebuild = med("fcl_rebuild");
      r.nodePairsExact = adsd::bench::median(pairsExact);
      r.nodePairsTolerance = adsd::bench::median(pairsTolerance);
      const double cap = kCapFraction * length;
      for (std::size_t i = 0; i < n; ++i) {
        r.worstError = std::max(r.worstError, std::abs(exact[i] - fclD[i]) / length);
        const bool capOk = exact[i] >= cap ? capped[i] >= cap * (1.0 - 1e-12) : std::abs(capped[i] - exact[i]) <= kAgreement * length;
        const bool tolOk = tolerance[i] >= exact[i] - kAgreement * length &&
                           tolerance[i] <= exact[i] * (1.0 + kRelativeTolerance) + kAgreement * length;
        const bool scratchOk = !o.scratch || (std::abs(fromScratch[i] - fclD[i]) <= kAgreement * length &&
                                              std::abs(fclRebuilt[i] - fclD[i]) <= kAgreement * length);
        if (std::abs(exact[i] - fclD[i]) > kAgreement * length || !capOk || !tolOk || !scratchOk) {
          std::fprintf(stderr,
                       "bench_bands: %s %s query %zu: exact %.17g, FCL %.17g, tolerance %.17g, capped %.17g, from "
                       "scratch %.17g, FCL rebuilt %.17g\n",
                       sceneName.c_str(), band.name.c_str(), i, exact[i], fclD[i], tolerance[i], capped[i],
                       fromScratch[i], fclRebuilt[i]);
          status = 3;
        }
      }
    }
    if (csv) {
      for (const auto& m : methods) {
        for (std::size_t k = 0; k < m.micros.size(); ++k) {
          const std::size_t i = k % n;
          const double value = answers.at(m.name)[i];
          *csv << sceneName << ',' << band.name << ',' << m.name << ',' << i << ',';
          char buffer[96];
          std::snprintf(buffer, sizeof buffer, "%.17g,%.17g,%.4f\n", length, value, m.micros[k]);
          *csv << buffer;
        }
      }
    }
    if (distances) {
      std::printf("%-24s %-9s %9.1f %9.1f %9.1f %9.1f %9.1f %9.1f | %6.3f %6.3f %6.3f %6.3f | %7.0f %7.0f %7.0f %8.1e\n",
                  sceneName.c_str(), band.name.c_str(), r.ours, r.tolerance, r.capped, r.fclDistance, r.validity,
                  r.fclCollide, r.ours / r.fclDistance, r.tolerance / r.ours, r.validity / r.fclCollide,
                  r.capped / r.fclDistance, r.nodePairsExact, r.nodePairsTolerance, r.nodePairsValidity, r.worstError);
    } else {
      std::printf("%-24s %-9s %9s %9s %9s %9s %9.1f %9.1f | %6s %6s %6.3f %6s | %7s %7s %7.0f\n", sceneName.c_str(),
                  band.name.c_str(), "", "", "", "", r.validity, r.fclCollide, "", "", r.validity / r.fclCollide, "", "",
                  "", r.nodePairsValidity);
    }
    if (o.scratch && distances) {
      std::printf("%-34s from scratch (no trees): ours %.1f us, FCL rebuild + distance %.1f us: %.4f\n", "",
                  r.scratch, r.fclRebuild, r.scratch / r.fclRebuild);
    }
    if (o.counters && distances) printWork(ta, tb, *fa, *fb, band.poses);
    std::fflush(stdout);
    results.push_back(r);
  }
  return status;
}

/// The per-band summary: for each ratio, the median over the scenes and the worst scene, as
/// text on stdout and, when \p markdown is given, as a Markdown table there.
void summary(const std::vector<BandResult>& results, const std::string& markdown) {
  struct Row {
    std::string band, scenes, exact, tolerance, validity, capped, scratch;
  };
  // --scratch: the from-scratch column, where any band measured it.
  const bool anyScratch =
      std::any_of(results.begin(), results.end(), [](const BandResult& r) { return r.fclRebuild > 0; });
  std::vector<Row> rows;
  for (const std::string& band : kBandNames) {
    std::vector<double> e, t, v, c, f;
    std::string worstE, worstT, worstV, worstC, worstF;
    auto track = [](std::vector<double>& x, std::string& worst, double value, const std::string& scene) {
      if (x.empty() || value > *std::max_element(x.begin(), x.end())) worst = scene;
      x.push_back(value);
    };
    for (const BandResult& r : results) {
      if (r.band != band) continue;
      track(v, worstV, r.validity / r.fclCollide, r.scene);
      if (!r.distances) continue;
      track(e, worstE, r.ours / r.fclDistance, r.scene);
      track(t, worstT, r.tolerance / r.ours, r.scene);
      track(c, worstC, r.capped / r.fclDistance, r.scene);
      if (r.fclRebuild > 0) track(f, worstF, r.scratch / r.fclRebuild, r.scene);
    }
    if (v.empty()) continue;
    // Three decimals, or three significant digits for the from-scratch ratios (hundredths and less).
    auto cell = [](const std::vector<double>& x, const std::string& worst,
                   const char* format = "%.3f (worst %.3f, %s)") {
      if (x.empty()) return std::string("-");
      char buffer[128];
      std::snprintf(buffer, sizeof buffer, format, adsd::bench::median(x),
                    *std::max_element(x.begin(), x.end()), worst.c_str());
      return std::string(buffer);
    };
    rows.push_back({band, std::to_string(v.size()), cell(e, worstE), cell(t, worstT), cell(v, worstV), cell(c, worstC),
                    cell(f, worstF, "%.3g (worst %.3g, %s)")});
  }
  std::printf("\nSummary per band over the scenes: median of the ratios of medians (worst scene)\n");
  std::printf("%-9s %6s  %-40s %-40s %-40s %-40s%s\n", "band", "scenes", "exact / FCL distance",
              "1% tolerance / exact", "validity / FCL collide", "capped / FCL distance",
              anyScratch ? " from scratch / FCL rebuild + distance" : "");
  for (const Row& r : rows) {
    std::printf("%-9s %6s  %-40s %-40s %-40s %-40s %s\n", r.band.c_str(), r.scenes.c_str(), r.exact.c_str(),
                r.tolerance.c_str(), r.validity.c_str(), r.capped.c_str(), anyScratch ? r.scratch.c_str() : "");
  }
  if (markdown.empty()) return;
  std::ofstream out(markdown);
  out << "| band | scenes | exact ÷ FCL distance | 1 % tolerance ÷ exact | validity (D = 0) ÷ FCL collide | "
         "capped at 5 % L ÷ FCL distance |"
      << (anyScratch ? " from scratch ÷ FCL rebuild + distance |" : "") << "\n";
  out << "|---|---:|---|---|---|---|" << (anyScratch ? "---|" : "") << "\n";
  for (const Row& r : rows) {
    out << "| " << r.band << " | " << r.scenes << " | " << r.exact << " | " << r.tolerance << " | " << r.validity << " | "
        << r.capped << " |";
    if (anyScratch) out << " " << r.scratch << " |";
    out << "\n";
  }
  if (!out) throw std::runtime_error("cannot write " + markdown);
}

}  // namespace

int run(const Options& o, int argc, char** argv);

int main(int argc, char** argv) {
  return adsd::cli::runProgram(commandLine(), argc, argv,
                               [&](const adsd::cli::Arguments& given) { return run(optionsFrom(given), argc, argv); });
}
int run(const Options& o, int argc, char** argv) {
  std::printf("bench_bands:");
  for (int i = 1; i < argc; ++i) std::printf(" %s", argv[i]);
  std::printf("\n%zu queries per band, %d rounds, seed %llu; median microseconds per query (both libraries keep "
              "their trees); ratios of medians; node pairs: median of our exact, tolerance and validity queries; error: max "
              "|ours - FCL| / L\n",
              o.poses, o.rounds, static_cast<unsigned long long>(o.seed));
  std::printf("%-24s %-9s %9s %9s %9s %9s %9s %9s | %6s %6s %6s %6s | %7s %7s %7s %8s\n", "scene", "band", "exact",
              "tol 1%", "capped", "fcl dist", "valid", "fcl coll", "ex/fcl", "tol/ex", "va/fcl", "cap/fc", "pairs",
              "pairs t", "pairs v", "error");
  std::ofstream csvFile;
  if (!o.csv.empty()) {
    csvFile.open(o.csv);
    if (!csvFile) {
      std::fprintf(stderr, "bench_bands: cannot write %s\n", o.csv.c_str());
      return 2;
    }
    csvFile << "scene,band,method,query,reference_length,answer,microseconds\n";
  }
  std::vector<BandResult> results;
  int status = 0;
  try {
    // Scenes are built with one placed pose (their own bands are drawn here).
    adsd::bench::SceneSize size;
    size.rigidPoses = 1;
    for (const std::string& name : o.scenes) {
      const adsd::bench::DistanceScene scene = adsd::bench::makeDistanceScene(name, size, adsd::bench::fclPlacement);
      if (scene.deforming) throw adsd::InputError("bench_bands: " + name + " is a deforming scene (bench_scenes has it)");
      const bool planar = scene.planning && scene.description.find("SE(2)") != std::string::npos;
      status = std::max(status, runScene(name, scene.a, scene.b, scene.planning, planar, scene.referenceLength, o,
                                         results, csvFile.is_open() ? &csvFile : nullptr));
    }
    for (const auto& [fileA, fileB] : o.pairs) {
      const Mesh a = adsd::io::loadMesh(fileA), b = adsd::io::loadMesh(fileB);
      auto stem = [](const std::string& path) {
        const auto slash = path.find_last_of('/');
        const std::string file = slash == std::string::npos ? path : path.substr(slash + 1);
        return file.substr(0, file.find('.'));
      };
      status = std::max(status, runScene(stem(fileA) + "_" + stem(fileB), a, b, false, false,
                                         adsd::bench::referenceLength(a, b), o, results,
                                         csvFile.is_open() ? &csvFile : nullptr));
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_bands: %s\n", e.what());
    return 2;
  }
  try {
    summary(results, o.summaryMarkdown);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_bands: %s\n", e.what());
    return 2;
  }
  return status;
}
