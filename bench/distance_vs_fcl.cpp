/// \file
/// \brief Issue 2's benchmark: our exact distance from scratch against FCL's build-both-BVHs-and-
/// query, on a pair of real 5 000+ triangle meshes in close proximity with overlapping hulls.
///
///   bench_distance_vs_fcl [--quick] [--poses N] [--rounds R] [--seed S] [MESH_A [MESH_B]]
///
/// Defaults: the CGAL cow (5 804 triangles) twice, from the cache of problems/data/fetch_meshes.sh;
/// 60 poses, 3 rounds (--quick: 12 poses, 1 round). Gaps are 0.1 %–5 % of the larger bounding-box
/// diagonal L, log-uniform; hull overlap is checked with FCL's GJK on the vertex hulls.
///
/// Three methods run interleaved on the same poses (bench/timing.h):
///   ours            adsd::distance, exact mode, one DistanceScratch reused for all queries;
///   fcl build+dist  both BVHModel<OBBRSS> built from the vertices, then fcl::distance (exact,
///                   nearest points on): what FCL costs when the geometry is new each query;
///   fcl prebuilt    fcl::distance on models built once before timing.
/// Prints median and p90 times, the ratios, the median counters of ours, a checksum (sum of
/// distances) per method, and the largest disagreement between methods. Exit status: 0 when all
/// methods agree to kAgreementTolerance × L, 3 when they do not, 2 on bad input or usage.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "adsd/cli/command_line.h"
#include "adsd/distance.h"
#include "adsd/error.h"
#include "adsd/io/load_mesh.h"
#include "scenes/close_poses.h"
#include "fcl_models.h"
#include "scenes/mesh_cache.h"
#include "timing.h"

namespace {

using adsd::bench::TimedMethod;

/// Methods agree when their distances differ by at most this fraction of L. The same bound
/// issue 2 sets for exact mode against the brute-force oracle (1e-10 × the scene's bounding-box
/// diagonal); FCL's triangle distance is exact up to rounding too, so rounding differences
/// (~1e-15 L for well-scaled meshes) sit far below it.
constexpr double kAgreementTolerance = 1e-10;

struct Options {
  std::string meshA;
  std::string meshB;
  std::size_t poses = 60;
  int rounds = 3;
  std::uint64_t seed = 20240601;
};

adsd::cli::CommandLine commandLine() {
  adsd::cli::CommandLine line(
      "bench_distance_vs_fcl", "bench_distance_vs_fcl [--quick] [--poses N] [--rounds R] [--seed S] [MESH_A [MESH_B]]",
      "Our exact distance from scratch against FCL building both OBBRSS trees and querying, and against FCL\n"
      "on prebuilt trees, on one pair of meshes in close proximity.",
      "Defaults: cow.off twice from the mesh cache, 60 poses, 3 rounds (--quick: 12 poses, 1 round).\n"
      "Exit status 0 when all methods agree, 3 when they do not, 2 on bad input or usage.");
  line.options()
      ("quick", "12 poses, 1 round")
      ("poses", adsd::cli::value("N"), "poses, from 1 (default 60)")
      ("rounds", adsd::cli::value("R"), "rounds over the poses, from 1 (default 3)")
      ("seed", adsd::cli::value("S"), "the poses' random seed (default 20240601)");
  line.positional("mesh");
  return line;
}

Options parseOptions(const adsd::cli::Arguments& given) {
  Options options;
  if (given.has("quick")) {
    options.poses = 12;
    options.rounds = 1;
  }
  options.poses = given.whole("poses", 1, std::numeric_limits<std::size_t>::max()).value_or(options.poses);
  options.rounds = static_cast<int>(given.whole("rounds", 1, std::numeric_limits<int>::max()).value_or(options.rounds));
  options.seed = given.whole("seed").value_or(options.seed);
  const std::vector<std::string> paths = given.texts("mesh");
  if (paths.size() > 2) throw adsd::cli::UsageError("at most two mesh paths");
  options.meshA = paths.size() > 0 ? paths[0] : adsd::bench::cachedMesh("cow.off");
  options.meshB = paths.size() > 1 ? paths[1] : options.meshA;
  return options;
}

adsd::Mesh loadOrExplain(const std::string& path) {
  if (std::FILE* f = std::fopen(path.c_str(), "rb")) {
    std::fclose(f);
  } else {
    throw adsd::InputError(path + ": cannot open; " + adsd::bench::fetchHint());
  }
  return adsd::io::loadMesh(path);
}

std::string baseName(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

double sum(const std::vector<double>& values) {
  double total = 0.0;
  for (double v : values) total += v;
  return total;
}

struct Disagreement {
  double maxAbs = 0.0;
  std::size_t worstPose = 0;
};

Disagreement compare(const std::vector<double>& x, const std::vector<double>& y) {
  Disagreement d;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double diff = std::abs(x[i] - y[i]);
    if (!(diff <= d.maxAbs)) {  // also catches NaN
      d.maxAbs = diff;
      d.worstPose = i;
    }
  }
  return d;
}

int run(const Options& options) {
  const adsd::Mesh meshA = loadOrExplain(options.meshA);
  const adsd::Mesh meshB = options.meshB == options.meshA ? meshA : loadOrExplain(options.meshB);
  const double length = adsd::bench::referenceLength(meshA, meshB);

  std::printf("bench_distance_vs_fcl: %s (%zu triangles) vs %s (%zu triangles), FCL %s\n",
              baseName(options.meshA).c_str(), meshA.triangleCount(), baseName(options.meshB).c_str(),
              meshB.triangleCount(), FCL_VERSION);

  // FCL's side, prepared outside any timing: index conversion, prebuilt models, vertex hulls.
  const std::vector<fcl::Triangle> trianglesA = adsd::bench::fclTriangles(meshA);
  const std::vector<fcl::Triangle> trianglesB = adsd::bench::fclTriangles(meshB);
  const auto prebuiltA = adsd::bench::buildObbrss(meshA.vertices(), trianglesA);
  const auto prebuiltB = adsd::bench::buildObbrss(meshB.vertices(), trianglesB);
  const auto hullA = adsd::bench::fclHull(meshA);
  const auto hullB = adsd::bench::fclHull(meshB);

  // Poses are placed with FCL's distance (prebuilt), not ours, so the set of test cases does not
  // depend on the code under test.
  adsd::bench::ClosePoseSpec spec;
  spec.count = options.poses;
  spec.seed = options.seed;
  adsd::bench::ClosePoseStats placement;
  const std::vector<adsd::bench::PosePair> poses = adsd::bench::makeClosePoses(
      meshA, meshB, spec,
      [&](const adsd::Pose& pa, const adsd::Pose& pb) {
        return std::max(0.0, adsd::bench::fclDistance(*prebuiltA, pa, *prebuiltB, pb).min_distance);
      },
      [&](const adsd::Pose& pa, const adsd::Pose& pb) {
        return adsd::bench::fclHullsOverlap(*hullA, pa, *hullB, pb);
      },
      &placement);
  std::printf("poses: %zu (seed %llu), gaps log-uniform in [%.1f%%, %.1f%%] of L = %.6g, hulls overlapping "
              "(FCL GJK on vertex hulls); %zu drawings, %zu rejected for separate hulls\n",
              poses.size(), static_cast<unsigned long long>(options.seed), 100 * spec.minGapFraction,
              100 * spec.maxGapFraction, length, placement.attempts, placement.rejectedSeparateHulls);
  std::printf("rounds: %d, methods interleaved per pose\n\n", options.rounds);

  const std::size_t n = poses.size();
  std::vector<double> ours(n), fclBuilt(n), fclPrebuilt(n);
  std::vector<adsd::DistanceCounters> counters(n);
  std::vector<double> ourWitnessError(n), fclWitnessError(n);
  std::vector<adsd::DistanceStatus> statuses(n);

  adsd::DistanceScratch scratch;
  const adsd::DistanceOptions exact = adsd::DistanceOptions::exactDistance();
  std::vector<TimedMethod> methods;
  methods.push_back({"ours exact (from scratch)", [&](std::size_t i) {
                       const adsd::DistanceResult r =
                           adsd::distance(meshA, poses[i].a, meshB, poses[i].b, exact, scratch);
                       ours[i] = r.distance;
                       counters[i] = r.counters;
                       statuses[i] = r.status;
                       ourWitnessError[i] = std::abs((r.witnessA - r.witnessB).norm() - r.distance);
                     }, {}, {}});
  methods.push_back({"fcl build both OBBRSS + distance", [&](std::size_t i) {
                       const auto a = adsd::bench::buildObbrss(meshA.vertices(), trianglesA);
                       const auto b = adsd::bench::buildObbrss(meshB.vertices(), trianglesB);
                       fclBuilt[i] = adsd::bench::fclDistance(*a, poses[i].a, *b, poses[i].b).min_distance;
                     }, {}, {}});
  methods.push_back({"fcl prebuilt OBBRSS distance", [&](std::size_t i) {
                       const fcl::DistanceResultd r =
                           adsd::bench::fclDistance(*prebuiltA, poses[i].a, *prebuiltB, poses[i].b);
                       fclPrebuilt[i] = r.min_distance;
                       fclWitnessError[i] =
                           std::abs((r.nearest_points[0] - r.nearest_points[1]).norm() - r.min_distance);
                     }, {}, {}});
  adsd::bench::runInterleaved(methods, n, options.rounds, /*warmupCases=*/std::min<std::size_t>(n, 3));

  const std::vector<double>* answers[] = {&ours, &fclBuilt, &fclPrebuilt};
  std::printf("%-34s %12s %12s %12s   %s\n", "method", "median_us", "p90_us", "mean_us", "checksum (sum of distances)");
  for (std::size_t k = 0; k < methods.size(); ++k) {
    const auto& m = methods[k];
    std::printf("%-34s %12.1f %12.1f %12.1f   %.15e\n", m.name.c_str(), adsd::bench::median(m.micros),
                adsd::bench::p90(m.micros), sum(m.micros) / static_cast<double>(m.micros.size()),
                sum(*answers[k]));
  }
  const double oursMedian = adsd::bench::median(methods[0].micros);
  const double builtMedian = adsd::bench::median(methods[1].micros);
  const double prebuiltMedian = adsd::bench::median(methods[2].micros);
  std::printf("\nratio ours / fcl(build+distance), medians: %.4f   (target <= 0.2)\n", oursMedian / builtMedian);
  std::printf("ratio ours / fcl(prebuilt distance), medians: %.4f\n", oursMedian / prebuiltMedian);
  std::printf("ratio ours / fcl(build+distance), means (total time): %.4f\n",
              sum(methods[0].micros) / sum(methods[1].micros));
  {
    // The same ratio pose by pose (each pose's median over rounds), then its median: robust to
    // a few slow poses dominating one method's distribution.
    const auto o = adsd::bench::perCaseMedians(methods[0], n), b = adsd::bench::perCaseMedians(methods[1], n);
    std::vector<double> ratios;
    for (std::size_t i = 0; i < n; ++i) ratios.push_back(o[i] / b[i]);
    std::printf("ratio ours / fcl(build+distance), median over poses: %.4f (p90 %.4f)\n",
                adsd::bench::median(ratios), adsd::bench::p90(ratios));
  }

  std::printf("\nour counters, median over poses (max):\n");
  auto counterLine = [&](const char* name, auto field) {
    std::vector<double> values;
    for (const auto& c : counters) values.push_back(static_cast<double>(field(c)));
    std::printf("  %-24s %12.0f  (%.0f)\n", name, adsd::bench::median(values),
                adsd::bench::quantile(values, 1.0));
  };
  counterLine("maxDepth", [](const adsd::DistanceCounters& c) { return c.maxDepth; });
  counterLine("subMeshPairs", [](const adsd::DistanceCounters& c) { return c.subMeshPairs; });
  counterLine("pairsRejectedByBounds", [](const adsd::DistanceCounters& c) { return c.pairsRejectedByBounds; });
  counterLine("pairsHashed", [](const adsd::DistanceCounters& c) { return c.pairsHashed; });
  counterLine("pairsSplit", [](const adsd::DistanceCounters& c) { return c.pairsSplit; });
  counterLine("trianglesHashed", [](const adsd::DistanceCounters& c) { return c.trianglesHashed; });
  counterLine("trianglePairsTested", [](const adsd::DistanceCounters& c) { return c.trianglePairsTested; });
  counterLine("gjkCalls", [](const adsd::DistanceCounters& c) { return c.gjkCalls; });
  counterLine("gjkIterations", [](const adsd::DistanceCounters& c) { return c.gjkIterations; });
  counterLine("gjkMaxIterations", [](const adsd::DistanceCounters& c) { return c.gjkMaxIterations; });

  std::size_t notExact = 0;
  for (auto s : statuses) notExact += s != adsd::DistanceStatus::exact;
  double minGap = INFINITY, maxGap = 0;
  for (double d : fclPrebuilt) minGap = std::min(minGap, d), maxGap = std::max(maxGap, d);
  std::printf("\ngaps reached (fcl prebuilt): %.4f%% .. %.4f%% of L\n", 100 * minGap / length, 100 * maxGap / length);
  std::printf("witness consistency, max | |wA - wB| - distance |: ours %.3e, fcl %.3e\n",
              adsd::bench::quantile(ourWitnessError, 1.0), adsd::bench::quantile(fclWitnessError, 1.0));

  const Disagreement oursVsBuilt = compare(ours, fclBuilt), oursVsPrebuilt = compare(ours, fclPrebuilt),
                     builtVsPrebuilt = compare(fclBuilt, fclPrebuilt);
  std::printf("max |ours - fcl build+distance| = %.3e (%.3e L, pose %zu)\n", oursVsBuilt.maxAbs,
              oursVsBuilt.maxAbs / length, oursVsBuilt.worstPose);
  std::printf("max |ours - fcl prebuilt|       = %.3e (%.3e L, pose %zu)\n", oursVsPrebuilt.maxAbs,
              oursVsPrebuilt.maxAbs / length, oursVsPrebuilt.worstPose);
  std::printf("max |fcl built - fcl prebuilt|  = %.3e\n", builtVsPrebuilt.maxAbs);

  const double tolerance = kAgreementTolerance * length;
  bool agree = true;
  if (notExact > 0) {
    std::printf("PROBLEM: %zu of our exact queries did not return status exact\n", notExact);
    agree = false;
  }
  for (const Disagreement* d : {&oursVsBuilt, &oursVsPrebuilt, &builtVsPrebuilt}) {
    if (!(d->maxAbs <= tolerance)) agree = false;
  }
  if (!agree) {
    const std::size_t i = oursVsPrebuilt.worstPose;
    std::printf("DISAGREEMENT beyond %.0e L: pose %zu: ours %.17g, fcl built %.17g, fcl prebuilt %.17g\n",
                kAgreementTolerance, i, ours[i], fclBuilt[i], fclPrebuilt[i]);
    return 3;
  }
  std::printf("all methods agree within %.0e L\n", kAgreementTolerance);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return adsd::cli::runProgram(commandLine(), argc, argv,
                                 [](const adsd::cli::Arguments& given) { return run(parseOptions(given)); });
  } catch (const adsd::InputError& e) {
    std::fprintf(stderr, "bench_distance_vs_fcl: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_distance_vs_fcl: error: %s\n", e.what());
    return 1;
  }
}
