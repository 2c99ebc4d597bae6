#include "spooled_benchmark_log.h"

#include <unistd.h>

#include <istream>
#include <map>
#include <string>
#include <ostream>
#include <system_error>
#include <utility>

#include <ompl/base/PlannerStatus.h>
#include <ompl/config.h>
#include <ompl/util/Time.h>

#include "adsd/error.h"

namespace adsd::app {

namespace {

namespace fs = std::filesystem;
namespace ot = ompl::tools;

/// The OMPL version for the log's first line. Debian's OMPL 1.5.2 defines OMPL_VERSION as "" (its
/// config.h was generated without it), so its own logs say "OMPL version " and Planner Arena, which
/// groups runs by version, shows none; the numeric macros beside it are right and spell it then.
std::string omplVersion() {
  const std::string declared = OMPL_VERSION;
  if (!declared.empty()) return declared;
  return std::to_string(OMPL_MAJOR_VERSION) + '.' + std::to_string(OMPL_MINOR_VERSION) + '.' +
         std::to_string(OMPL_PATCH_VERSION);
}

// A spool holds records; a record is its length(s) on one line, then its bytes and a newline. The
// lengths make a record safe whatever its text holds, and let the reader check every record is
// whole.

/// A run's properties: "N\n", then per property "KEY_LENGTH VALUE_LENGTH\nKEYVALUE\n".
void writeRun(std::ostream& out, const ot::Benchmark::RunProperties& run) {
  out << run.size() << '\n';
  for (const auto& [key, value] : run) out << key.size() << ' ' << value.size() << '\n' << key << value << '\n';
}

/// Reads \p length bytes and the newline after them; false when the spool ends early.
bool readBytes(std::istream& in, std::size_t length, std::string& into) {
  into.resize(length);
  if (length > 0 && !in.read(&into[0], static_cast<std::streamsize>(length))) return false;
  return in.get() == '\n';
}

bool readRun(std::istream& in, ot::Benchmark::RunProperties& run) {
  run.clear();
  std::size_t count = 0;
  if (!(in >> count) || in.get() != '\n') return false;
  std::string both;
  for (std::size_t i = 0; i < count; ++i) {
    std::size_t keyLength = 0, valueLength = 0;
    if (!(in >> keyLength >> valueLength) || in.get() != '\n') return false;
    if (!readBytes(in, keyLength + valueLength, both)) return false;
    run.emplace(both.substr(0, keyLength), both.substr(keyLength));
  }
  return true;
}

/// A run's progress data as the log's line for it (OMPL's layout: each time point's values in the
/// order of their names, each followed by ',', the time point closed by ';').
std::string progressLine(const ot::Benchmark::RunProgressData& run) {
  std::string line;
  for (const auto& point : run) {
    for (const auto& property : point) line += property.second + ",";
    line += ";";
  }
  return line;
}

/// A file at \p path opened for writing and reading, then unlinked (see the class comment).
std::unique_ptr<std::fstream> openSpool(const fs::path& path) {
  auto spool = std::make_unique<std::fstream>(path, std::ios::binary | std::ios::in | std::ios::out | std::ios::trunc);
  if (!*spool) throw InputError("cannot write the spool '" + path.string() + "' beside the log");
  std::error_code error;
  fs::remove(path, error);
  if (error) throw InputError("cannot remove the spool '" + path.string() + "': " + error.message());
  return spool;
}

}  // namespace

SpooledBenchmarkLog::SpooledBenchmarkLog(fs::path logPath)
    : logPath_(std::move(logPath)), temporaryPath_(logPath_.string() + ".tmp") {}

SpooledBenchmarkLog::~SpooledBenchmarkLog() {
  std::error_code ignored;
  fs::remove(temporaryPath_, ignored);  // there only when write() failed
}

SpooledBenchmarkLog::Planner& SpooledBenchmarkLog::planner(std::size_t index) {
  if (index >= planners_.size()) planners_.resize(index + 1);
  Planner& p = planners_[index];
  if (!p.runSpool) {
    const std::string spool = logPath_.string() + "." + std::to_string(::getpid()) + "-" + std::to_string(index);
    p.runSpool = openSpool(spool + ".runs");
    p.progressSpool = openSpool(spool + ".progress");
  }
  return p;
}

void SpooledBenchmarkLog::append(std::size_t firstPlanner, const ot::Benchmark::CompleteExperiment& call) {
  for (std::size_t i = 0; i < call.planners.size(); ++i) {
    const ot::Benchmark::PlannerExperiment& from = call.planners[i];
    Planner& p = planner(firstPlanner + i);
    if (p.name.empty()) {
      p.name = from.name;
      p.common = from.common;
      p.progressPropertyNames = from.progressPropertyNames;
    }
    for (const auto& run : from.runs) {
      for (const auto& property : run) p.runPropertyNames.insert(property.first);
      writeRun(*p.runSpool, run);
      ++p.runs;
      ++runs_;
    }
    for (const auto& progress : from.runsProgressData) {
      const std::string line = progressLine(progress);
      *p.progressSpool << line.size() << '\n' << line << '\n';
      ++p.progressRuns;
    }
    if (!*p.runSpool || !*p.progressSpool) {
      throw InputError("cannot write the spools beside '" + logPath_.string() + "' (disk full?)");
    }
  }
}

// The layout below is OMPL 1.5's Benchmark::saveResultsToStream, line for line (the log must read
// back through ompl_benchmark_statistics exactly as a log OMPL wrote), with the runs streamed from
// the spools instead of read from memory, and the version spelled out where OMPL's is empty.
void SpooledBenchmarkLog::write(const ot::Benchmark::CompleteExperiment& header) {
  std::ofstream out(temporaryPath_, std::ios::trunc);
  if (!out) throw InputError("cannot write '" + logPath_.string() + "'");
  out << "OMPL version " << omplVersion() << '\n';
  out << "Experiment " << (header.name.empty() ? "NO_NAME" : header.name) << '\n';
  out << header.parameters.size() << " experiment properties\n";
  for (const auto& [key, value] : header.parameters) out << key << " = " << value << '\n';
  out << "Running on " << (header.host.empty() ? "UNKNOWN" : header.host) << '\n';
  out << "Starting at " << ompl::time::as_string(header.startTime) << '\n';
  out << "<<<|\n" << header.setupInfo << "|>>>\n";
  out << "<<<|\n" << header.cpuInfo << "|>>>\n";
  out << header.seed << " is the random seed\n";
  out << header.maxTime << " seconds per run\n";
  out << header.maxMem << " MB per run\n";
  out << header.runCount << " runs per planner\n";
  out << header.totalDuration << " seconds spent to collect the data\n";
  out << "1 enum type\nstatus";
  for (int i = 0; i < ompl::base::PlannerStatus::TYPE_COUNT; ++i) {
    out << '|' << ompl::base::PlannerStatus(static_cast<ompl::base::PlannerStatus::StatusType>(i)).asString();
  }
  out << '\n' << planners_.size() << " planners\n";
  for (Planner& p : planners_) writePlanner(out, p);
  out.flush();
  const bool written = static_cast<bool>(out);
  out.close();
  if (!written || out.fail()) throw InputError("cannot write '" + logPath_.string() + "'");
  std::error_code error;
  fs::rename(temporaryPath_, logPath_, error);
  if (error) throw InputError("cannot write '" + logPath_.string() + "': " + error.message());
}

void SpooledBenchmarkLog::writePlanner(std::ostream& out, Planner& p) {
  out << p.name << '\n';
  out << p.common.size() << " common properties\n";
  for (const auto& [key, value] : p.common) out << key << " = " << value << '\n';

  // The run table: a column for every property any run had (sorted, as OMPL sorts them), empty
  // where a run lacks it (ompl_benchmark_statistics stores NULL there).
  out << p.runPropertyNames.size() << " properties for each run\n";
  for (const std::string& name : p.runPropertyNames) out << name << '\n';
  out << p.runs << " runs\n";
  const auto spoolBroken = [&p](const char* which) {
    return InputError("cannot read back the " + std::string(which) + " spool of " + p.name);
  };
  if (p.runs > 0) {
    std::iostream& runs = *p.runSpool;
    if (!runs.seekg(0)) throw spoolBroken("run");  // also flushes what is still buffered
    ot::Benchmark::RunProperties run;
    for (std::size_t r = 0; r < p.runs; ++r) {
      if (!readRun(runs, run)) throw spoolBroken("run");
      for (const std::string& name : p.runPropertyNames) {
        const auto it = run.find(name);
        if (it != run.end()) out << it->second;
        out << "; ";
      }
      out << '\n';
    }
  }

  if (p.progressRuns > 0) {
    out << p.progressPropertyNames.size() << " progress properties for each run\n";
    for (const std::string& name : p.progressPropertyNames) out << name << '\n';
    out << p.progressRuns << " runs\n";
    std::iostream& progress = *p.progressSpool;
    if (!progress.seekg(0)) throw spoolBroken("progress");
    std::string line;
    for (std::size_t r = 0; r < p.progressRuns; ++r) {
      std::size_t length = 0;
      if (!(progress >> length) || progress.get() != '\n' || !readBytes(progress, length, line)) {
        throw spoolBroken("progress");
      }
      out << line << '\n';
    }
  }
  out << ".\n";
}

}  // namespace adsd::app
