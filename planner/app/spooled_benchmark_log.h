// An OMPL benchmark log whose runs wait on disk, not in memory, until the log is written.
#pragma once

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <ompl/tools/benchmark/Benchmark.h>

namespace adsd::app {

/// \brief Writes one OMPL benchmark log (the format of ompl::tools::Benchmark::saveResultsToStream,
/// which ompl_benchmark_statistics reads) from runs recorded one call of Benchmark::benchmark at a
/// time, holding in memory only what does not grow with the run count.
///
/// Why: `adsd benchmark` calls Benchmark::benchmark once per run (the checker combinations take
/// turns run by run), and a log lists each planner's runs together, so the runs must wait
/// somewhere until the last one is done. In memory that grows by a few KB per run without bound (a
/// soak of a million runs); here each planner's runs are appended to a spool file next to the log
/// as they finish. What stays in memory per planner is its name, its common properties, the names
/// of its run properties seen so far (a log's run table has a column for every name any run had)
/// and two counts. write() assembles the log from the spools through a temporary file renamed on
/// success, so a failure leaves no log rather than half of one.
///
/// A spool is created in the log's directory (on disk: /tmp may be memory) and unlinked at once,
/// kept open for writing and reading back: it takes no name in the directory, and the system
/// frees it however the program ends (an error, Ctrl-C, a kill), so no spool is ever left behind.
class SpooledBenchmarkLog {
 public:
  /// \p logPath is the log write() will produce; each spool is created as `LOG.PID-K.runs` or
  /// `LOG.PID-K.progress` beside it and unlinked as soon as it is open.
  explicit SpooledBenchmarkLog(std::filesystem::path logPath);
  ~SpooledBenchmarkLog();
  SpooledBenchmarkLog(const SpooledBenchmarkLog&) = delete;
  SpooledBenchmarkLog& operator=(const SpooledBenchmarkLog&) = delete;

  /// \brief Appends the runs one call of Benchmark::benchmark recorded: the call's planner i is the
  /// log's planner firstPlanner + i. The first call that reaches a planner also gives its name,
  /// common properties and progress property names (they are the same in every call).
  /// Throws adsd::InputError when a spool cannot be written.
  void append(std::size_t firstPlanner, const ompl::tools::Benchmark::CompleteExperiment& call);

  /// Runs appended so far, over all planners.
  std::size_t runCount() const { return runs_; }

  /// \brief Writes the log: \p header's experiment fields (name, properties, host, start time,
  /// set-up text, CPU, seed, limits, run count, duration; its planners are ignored), then every
  /// planner in order with its runs read back from its spool. Throws adsd::InputError when the log
  /// cannot be written; nothing is left at the log's path then.
  void write(const ompl::tools::Benchmark::CompleteExperiment& header);

 private:
  /// One planner of the log: what it holds in memory, and its two spools.
  struct Planner {
    std::string name;
    ompl::tools::Benchmark::RunProperties common;
    std::vector<std::string> progressPropertyNames;
    std::set<std::string> runPropertyNames;  ///< every name any of its runs had
    std::size_t runs = 0;
    std::size_t progressRuns = 0;
    std::unique_ptr<std::fstream> runSpool;       ///< open, unlinked
    std::unique_ptr<std::fstream> progressSpool;  ///< open, unlinked
  };

  Planner& planner(std::size_t index);
  void writePlanner(std::ostream& out, Planner& p);

  std::filesystem::path logPath_;
  std::filesystem::path temporaryPath_;
  std::vector<Planner> planners_;
  std::size_t runs_ = 0;
};

}  // namespace adsd::app
