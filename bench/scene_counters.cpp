// bench_scene_counters: what one scene's queries cost, in work counted rather than in time alone:
// for each query mode on prebuilt trees, the median time per query over R repetitions of the
// scene's poses next to FCL's (prebuilt OBBRSS distance and collide, interleaved pose by pose),
// and the mean number of node pairs, pairs dropped by bounds, and exact triangle pairs per query.
// It is the profile behind issue 6's "say what bounds a ratio"; perf is then pointed at it with
// `perf record bench_scene_counters --scenes problem_bug_trap --modes exact`.
//
//   bench_scene_counters [--scenes a,b,...] [--modes exact,known,tol,threshold,contact] [--repeat R]
//
// Default: the seven planning problems (problem_NAME), every mode, R = 20.
//
// Mode `known` is an exact query told its answer in advance: capped just above the exact distance
// (worked out first, untimed), it must still find the closest pair and prove every other pair
// farther, but never meets a larger upper bound. Its node pairs are what proving the minimum costs
// with these trees' bounds; a tolerance query can drop only the part of them whose bounds lie
// within the tolerance of the answer (issue 6's "say what bounds a ratio" for the tolerance row).
//
// The poses are bench_scenes' (FCL places them; see bench/scenes/distance_scenes.h).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "adsd/cli/command_line.h"
#include "adsd/distance.h"
#include "adsd/error.h"
#include "fcl_models.h"
#include "fcl_placement.h"
#include "scenes/distance_scenes.h"
#include "timing.h"

namespace {

using adsd::bench::microsecondsOf;

std::vector<std::string> splitList(const std::string& text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = text.find(',', start);
    const std::size_t end = comma == std::string::npos ? text.size() : comma;
    if (end > start) out.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return out;
}


double medianOf(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

/// The bench_scenes threshold: 1 % of the scene's reference length.
constexpr double kThresholdFraction = 0.01;

}  // namespace

/// Where each mode's answers go (volatile: the queries must run).
volatile double answers = 0.0;

namespace {

adsd::cli::CommandLine commandLine() {
  adsd::cli::CommandLine line(
      "bench_scene_counters", "bench_scene_counters [--scenes a,b,...] [--modes exact,known,tol,threshold,contact] [--repeat R]",
      "Per query mode on prebuilt trees: the median time per query next to FCL's, and the mean work per query\n"
      "(node pairs, pairs dropped by bounds, exact triangle pairs).",
      "Exit status 0; 2 on bad usage or a missing mesh.");
  line.options()
      ("scenes", adsd::cli::value("a,b,..."), "bench_scenes' scenes (default: the seven planning problems)")
      ("modes", adsd::cli::value("m,..."), "exact, known, tol, threshold, contact (default: all)")
      ("repeat", adsd::cli::value("R"), "repetitions of each scene's poses, from 1 (default 20)");
  return line;
}

int run(const adsd::cli::Arguments& given) {
  std::vector<std::string> scenes = {"problem_office",   "problem_maze",           "problem_thin_wall",
                                     "problem_bug_trap", "problem_twisted_passage", "problem_alpha_puzzle",
                                     "problem_cow_doorway"};
  std::vector<std::string> modes = {"exact", "known", "tol", "threshold", "contact"};
  if (const auto list = given.text("scenes")) scenes = splitList(*list);
  if (const auto list = given.text("modes")) modes = splitList(*list);
  for (const std::string& mode : modes) {
    if (mode != "exact" && mode != "known" && mode != "tol" && mode != "threshold" && mode != "contact") {
      throw adsd::cli::UsageError("--modes: unknown mode '" + mode + "' (exact, known, tol, threshold, contact)");
    }
  }
  const int repeat = static_cast<int>(given.whole("repeat", 1, 1000000).value_or(20));
  std::printf("Median microseconds per query over each scene's poses x %d, ours on prebuilt sub-mesh trees and FCL on\n"
              "prebuilt OBBRSS, interleaved pose by pose; work counters are means per query. Modes: exact (FCL: distance),\n"
              "known (exact, capped just above its answer, found first and untimed: the cost of the proof alone),\n"
              "tol (relative 1 %%; FCL: distance), threshold (D = 1 %% of the robot's diagonal; FCL: collide, which answers\n"
              "D = 0: reference only), contact (D = 0, the validity question; FCL: collide).\n",
              repeat);
  try {
    for (const std::string& name : scenes) {
      adsd::bench::DistanceScene scene = adsd::bench::makeDistanceScene(name, {}, adsd::bench::fclPlacement);
      scene.a.buildHierarchy();
      scene.b.buildHierarchy();
      const auto fclA = adsd::bench::buildObbrss(scene.a.vertices(), adsd::bench::fclTriangles(scene.a));
      const auto fclB = adsd::bench::buildObbrss(scene.b.vertices(), adsd::bench::fclTriangles(scene.b));
      std::printf("%s: %zu + %zu triangles, %zu poses x %d\n", name.c_str(), scene.a.triangleCount(),
                  scene.b.triangleCount(), scene.queryCount(), repeat);
      for (const std::string& mode : modes) {
        adsd::DistanceOptions options;
        bool collide = false;
        const bool known = mode == "known";
        if (mode == "exact" || known) {
          options = adsd::DistanceOptions{};
        } else if (mode == "tol") {
          options = adsd::DistanceOptions::withTolerance(0.0, 1e-2);
        } else if (mode == "threshold") {
          options = adsd::DistanceOptions::aboveThreshold(kThresholdFraction * scene.referenceLength);
          collide = true;
        } else if (mode == "contact") {  // a validity check without a safety margin, as planners make
          options = adsd::DistanceOptions::aboveThreshold(0.0);
          collide = true;
        } else {
          std::fprintf(stderr, "bench_scene_counters: unknown mode '%s'\n", mode.c_str());
          return 2;
        }
        adsd::DistanceScratch scratch;
        // Mode known: each pose's cap, just above its exact distance (and positive, as a cap must be).
        std::vector<adsd::DistanceOptions> capped;
        if (known) {
          for (const adsd::bench::PosePair& p : scene.poses) {
            const double exact = adsd::distance(scene.a, p.a, scene.b, p.b, options, scratch).distance;
            capped.push_back(adsd::DistanceOptions::cappedAt(exact * (1.0 + 1e-9) + 1e-12 * scene.referenceLength));
          }
        }
        std::vector<double> ours, theirs;
        adsd::DistanceCounters total;
        std::size_t queries = 0;
        double sink = 0.0;
        for (int r = 0; r < repeat; ++r) {
          for (std::size_t k = 0; k < scene.poses.size(); ++k) {
            const adsd::bench::PosePair& p = scene.poses[k];
            const adsd::DistanceOptions& poseOptions = known ? capped[k] : options;
            adsd::DistanceResult result;
            ours.push_back(microsecondsOf(
                [&] { result = adsd::distance(scene.a, p.a, scene.b, p.b, poseOptions, scratch); }));
            sink += result.distance;
            total.subMeshPairs += result.counters.subMeshPairs;
            total.pairsRejectedByBounds += result.counters.pairsRejectedByBounds;
            total.trianglePairsTested += result.counters.trianglePairsTested;
            ++queries;
            theirs.push_back(microsecondsOf([&] {
              sink += collide ? static_cast<double>(adsd::bench::fclCollide(*fclA, p.a, *fclB, p.b))
                              : adsd::bench::fclDistance(*fclA, p.a, *fclB, p.b).min_distance;
            }));
          }
        }
        const double n = static_cast<double>(queries);
        std::printf("  %-9s ours %8.2f us  fcl %-8s %8.2f us  ratio %5.3f  node pairs %7.1f  dropped %7.1f  triangle pairs %6.1f\n",
                    mode.c_str(), medianOf(ours), collide ? "collide" : "distance", medianOf(theirs),
                    medianOf(ours) / medianOf(theirs), total.subMeshPairs / n, total.pairsRejectedByBounds / n,
                    total.trianglePairsTested / n);
        answers = sink;  // the answers are used, so no query can be optimized away
      }
    }
  } catch (const adsd::InputError& e) {
    std::fprintf(stderr, "bench_scene_counters: %s\n", e.what());
    return 2;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return adsd::cli::runProgram(commandLine(), argc, argv, run); }
