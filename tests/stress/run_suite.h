#pragma once
/// \file
/// \brief Runs N cases of each selected family on T threads and gathers the table of issue 3
/// item 4 (family, cases, max error / diagonal, max GJK iterations, max recursion depth, failures),
/// printing every failing case's exact numbers as it goes.

#include <cstdint>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "families.h"

namespace adsd::stress {

struct SuiteOptions {
  std::uint64_t casesPerFamily = 1000;
  std::uint64_t seed = 1;
  std::vector<const Family*> families;  ///< empty: all
  int threads = 1;
  double scale = 0.0;          ///< > 0 pins every case's scale
  int reportsPerCheck = 3;     ///< failing cases printed in full per family and failure label
  bool minimize = true;        ///< shrink each printed failing case before printing it
  double progressSeconds = 0;  ///< > 0: a progress line on stderr this often
  /// Failures whose check label contains one of these are counted as pending (a reported core bug
  /// whose fix has not landed), printed and tabled apart, and do not fail the run.
  std::vector<std::string> pending;
  std::FILE* out = stdout;
};

/// \brief One row of the table.
struct FamilyStats {
  std::string name;
  std::uint64_t cases = 0;
  std::uint64_t contact = 0;  ///< oracle distance 0, or the exact predicate says they intersect
  std::uint64_t near = 0;     ///< 0 < oracle distance <= 1e-6 x diagonal
  std::uint64_t apart = 0;    ///< oracle distance > 1e-6 x diagonal
  std::uint64_t split = 0;    ///< the root pair's hulls overlapped (recursion ran)
  std::uint64_t failedCases = 0;   ///< cases with at least one failure that is not pending
  std::uint64_t pendingCases = 0;  ///< cases whose only failures are pending ones
  double worstError = 0.0;    ///< max |exact answer - oracle| / diagonal
  std::uint64_t worstCase = 0;  ///< the case index where it occurred
  int gjkMaxIterations = 0;
  std::uint64_t gjkCapHits = 0;  ///< cases where some GJK run reached tolerance::kGjkMaxIterations
  int maxDepthScratch = 0, maxDepthTree = 0;
  std::map<std::string, std::uint64_t> failuresByCheck;
  std::map<std::string, std::uint64_t> pendingByCheck;
  void merge(const FamilyStats& other);
};

struct SuiteResult {
  std::vector<FamilyStats> rows;
  std::vector<std::string> mixProblems;  ///< families whose sample missed their ExpectedMix
  double seconds = 0.0;
  bool passed() const;
};

/// \brief Runs the suite; failing cases are printed to options.out as they are found.
SuiteResult runSuite(const SuiteOptions& options);

/// \brief The table, the failure labels per family, and the mix problems.
void printTable(const SuiteResult& result, const SuiteOptions& options);

/// \brief One case in full: what the oracle says, every failure, the case as code. True if it passed.
bool runOneCase(const Family& family, std::uint64_t seed, std::uint64_t index, double scale, bool minimize, std::FILE* out);

}  // namespace adsd::stress
