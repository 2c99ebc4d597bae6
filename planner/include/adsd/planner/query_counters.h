#pragma once
/// \file
/// \brief Counters a benchmark reads off a checker: queries and the time they took, thread-safe.

#include <atomic>
#include <chrono>
#include <cstdint>

namespace adsd::planner {

/// \brief A snapshot of the counters.
struct QueryCounts {
  std::uint64_t validityChecks = 0;    ///< isValid(state) calls (threshold queries)
  std::uint64_t clearanceQueries = 0;  ///< distance queries: clearance(), isValid(state, dist), motion steps
  double validitySeconds = 0.0;        ///< wall time inside validity checks, summed over threads
  double clearanceSeconds = 0.0;       ///< wall time inside clearance queries, summed over threads

  double meanValiditySeconds() const {
    return validityChecks ? validitySeconds / static_cast<double>(validityChecks) : 0.0;
  }
  double meanClearanceSeconds() const {
    return clearanceQueries ? clearanceSeconds / static_cast<double>(clearanceQueries) : 0.0;
  }
};

/// \brief Relaxed atomic counters: each query adds to them once, from any thread; a reader sees
/// every finished query (the counts are statistics, nothing is ordered by them).
class QueryCounters {
 public:
  void addValidity(std::chrono::nanoseconds spent) {
    validityChecks_.fetch_add(1, std::memory_order_relaxed);
    validityNanoseconds_.fetch_add(static_cast<std::uint64_t>(spent.count()), std::memory_order_relaxed);
  }
  void addClearance(std::chrono::nanoseconds spent) {
    clearanceQueries_.fetch_add(1, std::memory_order_relaxed);
    clearanceNanoseconds_.fetch_add(static_cast<std::uint64_t>(spent.count()), std::memory_order_relaxed);
  }
  QueryCounts snapshot() const {
    QueryCounts c;
    c.validityChecks = validityChecks_.load(std::memory_order_relaxed);
    c.clearanceQueries = clearanceQueries_.load(std::memory_order_relaxed);
    c.validitySeconds = 1e-9 * static_cast<double>(validityNanoseconds_.load(std::memory_order_relaxed));
    c.clearanceSeconds = 1e-9 * static_cast<double>(clearanceNanoseconds_.load(std::memory_order_relaxed));
    return c;
  }
  void reset() {
    validityChecks_ = 0;
    clearanceQueries_ = 0;
    validityNanoseconds_ = 0;
    clearanceNanoseconds_ = 0;
  }

 private:
  std::atomic<std::uint64_t> validityChecks_{0};
  std::atomic<std::uint64_t> clearanceQueries_{0};
  std::atomic<std::uint64_t> validityNanoseconds_{0};
  std::atomic<std::uint64_t> clearanceNanoseconds_{0};
};

/// \brief Times one query and adds it to the counters when it goes out of scope.
class ScopedQueryTimer {
 public:
  enum class Kind { validity, clearance };
  ScopedQueryTimer(QueryCounters& counters, Kind kind)
      : counters_(counters), kind_(kind), start_(std::chrono::steady_clock::now()) {}
  ~ScopedQueryTimer() {
    const auto spent = std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - start_);
    if (kind_ == Kind::validity) {
      counters_.addValidity(spent);
    } else {
      counters_.addClearance(spent);
    }
  }
  ScopedQueryTimer(const ScopedQueryTimer&) = delete;
  ScopedQueryTimer& operator=(const ScopedQueryTimer&) = delete;

 private:
  QueryCounters& counters_;
  Kind kind_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace adsd::planner
