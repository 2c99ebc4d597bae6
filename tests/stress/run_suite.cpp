#include "run_suite.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <set>
#include <thread>

#include "adsd/tolerances.h"
#include "minimize.h"
#include "properties.h"

namespace adsd::stress {

/// A case counts as "near" up to this x the diagonal (issue 3: near contact is 1e-14 ... 1e-6 x
/// the scene).
constexpr double kNearContact = 1e-6;
/// Sample mixes are judged only on at least this many cases of a family (below it a fraction is
/// too noisy to hold a generator to).
constexpr std::uint64_t kMixMinimumCases = 200;

void FamilyStats::merge(const FamilyStats& o) {
  cases += o.cases;
  contact += o.contact;
  near += o.near;
  apart += o.apart;
  split += o.split;
  failedCases += o.failedCases;
  pendingCases += o.pendingCases;
  if (o.worstError > worstError || (o.worstError == worstError && o.worstCase < worstCase)) {
    worstError = o.worstError;
    worstCase = o.worstCase;
  }
  gjkMaxIterations = std::max(gjkMaxIterations, o.gjkMaxIterations);
  gjkCapHits += o.gjkCapHits;
  maxDepthScratch = std::max(maxDepthScratch, o.maxDepthScratch);
  maxDepthTree = std::max(maxDepthTree, o.maxDepthTree);
  for (const auto& [check, n] : o.failuresByCheck) failuresByCheck[check] += n;
  for (const auto& [check, n] : o.pendingByCheck) pendingByCheck[check] += n;
}

bool SuiteResult::passed() const {
  if (!mixProblems.empty()) return false;
  return std::all_of(rows.begin(), rows.end(), [](const FamilyStats& r) { return r.failedCases == 0; });
}

namespace {

void printFailingCase(const StressCase& c, const CaseReport& report, const std::vector<std::string>& checksToShow,
                      bool minimize, DistanceScratch& scratch, std::FILE* out, std::mutex* printing,
                      const char* verdict = "FAIL") {
  std::string text = std::string(verdict) + " " + caseHeadline(c) + "\n";
  for (const Failure& f : report.failures) text += "  " + describeFailure(f, report.truth) + "\n";
  char reproduce[256];
  std::snprintf(reproduce, sizeof reproduce, "  reproduce: adsd_stress --family %s --seed %llu --case %llu%s\n",
                c.family.c_str(), (unsigned long long)c.seed, (unsigned long long)c.index,
                c.family == "pinned" ? " (pinned)" : "");
  text += reproduce;
  if (c.scale != 0) {
    char pin[96];
    std::snprintf(pin, sizeof pin, "  (case scale %a)\n", c.scale);
    text += pin;
  }
  for (const std::string& check : checksToShow) {
    const StressCase small = minimize ? minimizeFailure(c, check, scratch) : c;
    text += "  case for \"" + check + "\"" + (minimize ? " (minimized)" : "") + ":\n" + caseAsCode(small);
    if (minimize) {
      const CaseReport again = checkCase(small, scratch);
      for (const Failure& f : again.failures) {
        if (f.check == check) text += "  minimized: " + describeFailure(f, again.truth) + "\n";
      }
    }
  }
  if (printing) {
    std::lock_guard<std::mutex> lock(*printing);
    std::fputs(text.c_str(), out);
    std::fflush(out);
  } else {
    std::fputs(text.c_str(), out);
  }
}

}  // namespace

SuiteResult runSuite(const SuiteOptions& options) {
  std::vector<const Family*> selected = options.families;
  if (selected.empty()) {
    for (const Family& f : families()) selected.push_back(&f);
  }
  const std::uint64_t total = options.casesPerFamily * selected.size();
  const int threads = std::max(1, options.threads);
  std::vector<std::vector<FamilyStats>> perThread(threads, std::vector<FamilyStats>(selected.size()));
  std::atomic<std::uint64_t> next{0}, done{0}, failing{0};
  std::mutex printing;
  std::map<std::pair<std::size_t, std::string>, int> printed;  // (family, check) -> cases printed
  const auto start = std::chrono::steady_clock::now();

  auto work = [&](int thread) {
    DistanceScratch scratch;
    for (;;) {
      // Interleaved: task k is case k / F of family k % F, so every family progresses together.
      const std::uint64_t k = next.fetch_add(1);
      if (k >= total) return;
      const std::size_t familyIndex = k % selected.size();
      const std::uint64_t index = k / selected.size();
      const StressCase c = generateCase(*selected[familyIndex], options.seed, index, options.scale);
      const CaseReport report = checkCase(c, scratch);

      FamilyStats& s = perThread[thread][familyIndex];
      ++s.cases;
      const Truth& t = report.truth;
      if (t.distance == 0.0 || t.intersecting) {
        ++s.contact;
      } else if (t.distance <= kNearContact * t.diagonal) {
        ++s.near;
      } else {
        ++s.apart;
      }
      s.split += report.rootSplit;
      if (report.worstError > s.worstError) {
        s.worstError = report.worstError;
        s.worstCase = index;
      }
      s.gjkMaxIterations = std::max(s.gjkMaxIterations, report.gjkMaxIterations);
      s.gjkCapHits += report.gjkMaxIterations >= tolerance::kGjkMaxIterations;
      s.maxDepthScratch = std::max(s.maxDepthScratch, report.maxDepthScratch);
      s.maxDepthTree = std::max(s.maxDepthTree, report.maxDepthTree);
      if (!report.failures.empty()) {
        auto isPending = [&](const std::string& check) {
          return std::any_of(options.pending.begin(), options.pending.end(),
                             [&](const std::string& p) { return check.find(p) != std::string::npos; });
        };
        std::set<std::string> checks;
        for (const Failure& f : report.failures) checks.insert(f.check);
        const bool onlyPending = std::all_of(checks.begin(), checks.end(), isPending);
        ++(onlyPending ? s.pendingCases : s.failedCases);
        if (!onlyPending) failing.fetch_add(1);
        std::vector<std::string> show;
        {
          std::lock_guard<std::mutex> lock(printing);
          for (const std::string& check : checks) {
            ++(isPending(check) ? s.pendingByCheck : s.failuresByCheck)[check];
            if (printed[{familyIndex, check}]++ < options.reportsPerCheck) show.push_back(check);
          }
        }
        if (!show.empty()) {
          // A pending bug was pinned when it was reported: its cases are listed, not minimized.
          if (onlyPending) show.resize(1);
          printFailingCase(c, report, show, options.minimize && !onlyPending, scratch, options.out, &printing,
                           onlyPending ? "PENDING" : "FAIL");
        }
      }
      const std::uint64_t finished = done.fetch_add(1) + 1;
      if (options.progressSeconds > 0 && thread == 0) {
        static thread_local auto lastReport = std::chrono::steady_clock::now();
        const auto now = std::chrono::steady_clock::now();
        if (std::chrono::duration<double>(now - lastReport).count() >= options.progressSeconds) {
          lastReport = now;
          std::fprintf(stderr, "progress: %llu of %llu cases, %llu failing, %.0f s\n", (unsigned long long)finished,
                       (unsigned long long)total, (unsigned long long)failing.load(),
                       std::chrono::duration<double>(now - start).count());
        }
      }
    }
  };
  std::vector<std::thread> pool;
  for (int i = 1; i < threads; ++i) pool.emplace_back(work, i);
  work(0);
  for (std::thread& t : pool) t.join();

  SuiteResult result;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (std::size_t f = 0; f < selected.size(); ++f) {
    FamilyStats row;
    row.name = selected[f]->name;
    for (int t = 0; t < threads; ++t) row.merge(perThread[t][f]);
    const ExpectedMix& mix = selected[f]->mix;
    if (row.cases >= kMixMinimumCases) {
      auto missed = [&](const char* what, std::uint64_t count, double expected) {
        if (double(count) < expected * double(row.cases)) {
          char line[256];
          std::snprintf(line, sizeof line, "%s: %llu of %llu cases %s, expected at least %.0f%%", row.name.c_str(),
                        (unsigned long long)count, (unsigned long long)row.cases, what, 100 * expected);
          result.mixProblems.push_back(line);
        }
      };
      missed("in contact", row.contact, mix.contact);
      missed("near contact", row.near, mix.near);
      missed("apart", row.apart, mix.apart);
    }
    result.rows.push_back(std::move(row));
  }
  return result;
}

void printTable(const SuiteResult& result, const SuiteOptions& options) {
  std::FILE* out = options.out;
  std::fprintf(out, "\n%-28s %9s %8s %8s %8s %8s %13s %8s %9s %9s %8s\n", "family", "cases", "contact", "near", "apart",
               "split", "max err/diag", "max GJK", "depth s/t", "failures", "pending");
  FamilyStats all;
  all.name = "total";
  for (const FamilyStats& r : result.rows) {
    char depth[32];
    std::snprintf(depth, sizeof depth, "%d/%d", r.maxDepthScratch, r.maxDepthTree);
    std::fprintf(out, "%-28s %9llu %8llu %8llu %8llu %8llu %13.3g %8d %9s %9llu %8llu\n", r.name.c_str(),
                 (unsigned long long)r.cases, (unsigned long long)r.contact, (unsigned long long)r.near,
                 (unsigned long long)r.apart, (unsigned long long)r.split, r.worstError, r.gjkMaxIterations, depth,
                 (unsigned long long)r.failedCases, (unsigned long long)r.pendingCases);
    all.merge(r);
  }
  char depth[32];
  std::snprintf(depth, sizeof depth, "%d/%d", all.maxDepthScratch, all.maxDepthTree);
  std::fprintf(out, "%-28s %9llu %8llu %8llu %8llu %8llu %13.3g %8d %9s %9llu %8llu\n", "total", (unsigned long long)all.cases,
               (unsigned long long)all.contact, (unsigned long long)all.near, (unsigned long long)all.apart,
               (unsigned long long)all.split, all.worstError, all.gjkMaxIterations, depth,
               (unsigned long long)all.failedCases, (unsigned long long)all.pendingCases);
  std::fprintf(out, "GJK iteration cap %d reached in %llu cases; seed %llu, %llu cases per family, %d threads, %.1f s\n",
               tolerance::kGjkMaxIterations, (unsigned long long)all.gjkCapHits, (unsigned long long)options.seed,
               (unsigned long long)options.casesPerFamily, options.threads, result.seconds);
  for (const FamilyStats& r : result.rows) {
    if (r.worstError > 0) {
      std::fprintf(out, "  %-28s max error/diagonal %.3g at --case %llu\n", r.name.c_str(), r.worstError,
                   (unsigned long long)r.worstCase);
    }
  }
  for (const FamilyStats& r : result.rows) {
    for (const auto& [check, n] : r.failuresByCheck) {
      std::fprintf(out, "  %-28s failed %-58s in %llu cases\n", r.name.c_str(), ("\"" + check + "\"").c_str(),
                   (unsigned long long)n);
    }
  }
  for (const FamilyStats& r : result.rows) {
    for (const auto& [check, n] : r.pendingByCheck) {
      std::fprintf(out, "  %-28s pending %-57s in %llu cases\n", r.name.c_str(), ("\"" + check + "\"").c_str(),
                   (unsigned long long)n);
    }
  }
  for (const std::string& p : options.pending) std::fprintf(out, "  pending (reported core bug, not failing this run): \"%s\"\n", p.c_str());
  for (const std::string& problem : result.mixProblems) std::fprintf(out, "  sample mix missed: %s\n", problem.c_str());
  std::fprintf(out, "%s\n", result.passed() ? "PASSED" : "FAILED");
}

bool runOneCase(const Family& family, std::uint64_t seed, std::uint64_t index, double scale, bool minimize, std::FILE* out) {
  const StressCase c = generateCase(family, seed, index, scale);
  DistanceScratch scratch;
  const CaseReport report = checkCase(c, scratch);
  std::fprintf(out, "%s\n  oracle distance %s, diagonal %s, intersecting %s, oracle pairs %llu\n", caseHeadline(c).c_str(),
               exactNumber(report.truth.distance).c_str(), exactNumber(report.truth.diagonal).c_str(),
               report.truth.intersecting ? "yes" : "no", (unsigned long long)report.truth.oraclePairs);
  std::fprintf(out, "  max error/diagonal %.3g, max GJK iterations %d, depth %d/%d, root split %s\n", report.worstError,
               report.gjkMaxIterations, report.maxDepthScratch, report.maxDepthTree, report.rootSplit ? "yes" : "no");
  if (report.failures.empty()) {
    std::fprintf(out, "%s", caseAsCode(c).c_str());
    std::fprintf(out, "PASSED\n");
    return true;
  }
  std::set<std::string> checks;
  for (const Failure& f : report.failures) checks.insert(f.check);
  printFailingCase(c, report, std::vector<std::string>(checks.begin(), checks.end()), minimize, scratch, out, nullptr);
  std::fprintf(out, "FAILED\n");
  return false;
}

}  // namespace adsd::stress
