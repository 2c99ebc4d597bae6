#pragma once
/// \file
/// \brief Timing for the benchmarks: methods run interleaved on the same cases, summarized by
/// median and 90th percentile.
///
/// Why interleaved: on a shared 2-core machine the clock frequency and the load of other
/// processes drift over seconds. Running method A on all cases and then method B would charge
/// that drift to one of them; running every method back to back on each case, in an order that
/// rotates from case to case, charges it to all alike, so ratios measured in one run are fair.

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <functional>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace adsd::bench {

/// \brief Wall-clock microseconds taken by \p work (steady clock: never jumps).
template <class Work>
double microsecondsOf(Work&& work) {
  const auto start = std::chrono::steady_clock::now();
  work();
  const auto stop = std::chrono::steady_clock::now();
  return std::chrono::duration<double, std::micro>(stop - start).count();
}

/// \brief The q-quantile (0 <= q <= 1) of \p samples, interpolating linearly between the two
/// nearest order statistics (so the median of an even count is the mean of the middle two).
/// Throws std::invalid_argument on an empty sample.
inline double quantile(std::vector<double> samples, double q) {
  if (samples.empty()) throw std::invalid_argument("quantile of an empty sample");
  std::sort(samples.begin(), samples.end());
  const double position = std::clamp(q, 0.0, 1.0) * static_cast<double>(samples.size() - 1);
  const auto below = static_cast<std::size_t>(position);
  const std::size_t above = std::min(below + 1, samples.size() - 1);
  const double weight = position - static_cast<double>(below);
  return samples[below] * (1.0 - weight) + samples[above] * weight;
}

inline double median(std::vector<double> samples) { return quantile(std::move(samples), 0.5); }
inline double p90(std::vector<double> samples) { return quantile(std::move(samples), 0.9); }

/// \brief One contender of a benchmark: a name and the work of one query on case i.
///
/// `run(i)` must do exactly the work being measured (whatever it needs that is not part of the
/// measurement is prepared before the run) and keep its answer somewhere the compiler cannot
/// drop it (a vector the caller reads afterwards).
struct TimedMethod {
  std::string name;
  std::function<void(std::size_t caseIndex)> run;
  /// Optional: the cases this method runs on (empty: all). A method too slow for every case
  /// (FCL rebuilding large deforming meshes) can sample them; its timings then cover only those.
  std::function<bool(std::size_t caseIndex)> appliesTo;
  /// Filled by runInterleaved: microseconds per query it ran, in run order (round-major: round r's
  /// cases follow round r-1's).
  std::vector<double> micros;
};

/// \brief Runs every method once on each of \p caseCount cases, \p rounds times, interleaved.
///
/// On case i of round r the methods run back to back starting at method (i + r) mod m, so every
/// method runs first equally often, the others after it in a seeded random order, so that the
/// method run just before each one varies and the cache warmth it leaves is shared out evenly. (In
/// a fixed cyclic order every method had the same predecessor on most cases: bench_bands' 1 %
/// tolerance query always ran right after the exact query of the same pose, on nodes that query
/// had just brought into cache, and read 0.72-0.77 of it near contact instead of 0.83-0.99:
/// bench_bands --scenes cows,camels,problem_bug_trap --bands near, both orders.)
/// Before timing, each method runs untimed on the first \p warmupCases cases: scratch memory
/// grows, code and data reach the caches.
///
/// \p prepare, when given, runs untimed before the methods on each case (and each warm-up case):
/// the place for work that belongs to the case, not to any method, such as computing a deforming
/// mesh's vertices for frame i.
inline void runInterleaved(std::vector<TimedMethod>& methods, std::size_t caseCount, int rounds,
                           std::size_t warmupCases = 1,
                           const std::function<void(std::size_t caseIndex)>& prepare = {}) {
  const std::size_t m = methods.size();
  for (auto& method : methods) {
    method.micros.clear();
    method.micros.reserve(caseCount * static_cast<std::size_t>(std::max(rounds, 0)));
  }
  for (std::size_t i = 0; i < std::min(warmupCases, caseCount); ++i) {
    if (prepare) prepare(i);
    for (auto& method : methods) {
      if (!method.appliesTo || method.appliesTo(i)) method.run(i);
    }
  }
  std::vector<std::size_t> order(m);
  std::mt19937_64 shuffler(0x5eed);  // fixed: a command times the same orders on every run
  for (int round = 0; round < rounds; ++round) {
    for (std::size_t i = 0; i < caseCount; ++i) {
      if (prepare) prepare(i);
      for (std::size_t k = 0; k < m; ++k) order[k] = (i + static_cast<std::size_t>(round) + k) % m;
      std::shuffle(order.begin() + 1, order.end(), shuffler);
      for (std::size_t k = 0; k < m; ++k) {
        TimedMethod& method = methods[order[k]];
        if (method.appliesTo && !method.appliesTo(i)) continue;
        method.micros.push_back(microsecondsOf([&] { method.run(i); }));
      }
    }
  }
}

/// \brief Per-case time: the median over rounds of case i's samples (round-major layout above;
/// only for a method that runs on every case).
inline std::vector<double> perCaseMedians(const TimedMethod& method, std::size_t caseCount) {
  std::vector<double> out;
  if (caseCount == 0) return out;
  const std::size_t rounds = method.micros.size() / caseCount;
  for (std::size_t i = 0; i < caseCount; ++i) {
    std::vector<double> samples;
    for (std::size_t r = 0; r < rounds; ++r) samples.push_back(method.micros[r * caseCount + i]);
    out.push_back(samples.empty() ? 0.0 : median(std::move(samples)));
  }
  return out;
}

}  // namespace adsd::bench
