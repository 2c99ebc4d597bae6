/// \file
/// \brief adsd_stress: the numerical stress suite of issue 3 as a program.
///
///   adsd_stress [--cases N] [--seed S] [--family NAME]... [--exclude NAME]... [--threads T]
///               [--scale X] [--case I] [--report K] [--no-minimize] [--progress SECONDS]
///               [--pending LABEL]... [--list]
///
/// Runs N cases (default 1000) of every family (or of the named ones; NAME may also be a prefix
/// such as "mesh/"; --exclude removes one) against the binary128 oracle and prints the table.
/// --pending LABEL counts failures whose check label contains LABEL apart, as a reported core bug
/// whose fix has not landed: they are printed and tabled but do not fail the run. Exit status 0 when every
/// case passed and every family's sample hit its intended mix, 1 otherwise, 2 on bad usage.
/// Every failing case is printed with its exact numbers (hex floats) and, minimized, as C++
/// ready to pin in regressions_test.cpp. --case I runs case I of the named family alone.

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "adsd/cli/command_line.h"
#include "run_suite.h"

namespace {

using namespace adsd::stress;

adsd::cli::CommandLine commandLine() {
  adsd::cli::CommandLine line(
      "adsd_stress",
      "adsd_stress [--cases N] [--seed S] [--family NAME|PREFIX]... [--exclude NAME|PREFIX]... [--threads T]\n"
      "                   [--scale X] [--case I] [--report K] [--no-minimize] [--progress SECONDS]\n"
      "                   [--pending LABEL]... [--list]",
      "The numerical stress suite: N cases of every family (or of the named ones) against the binary128\n"
      "oracle, then the table.",
      "Exit status 0 when every case passed and every family's sample hit its intended mix, 1 otherwise,\n"
      "2 on bad usage.");
  line.options()
      ("cases", adsd::cli::value("N"), "cases per family (default 1000)")
      ("seed", adsd::cli::value("S"), "random seed (default 1)")
      ("family", adsd::cli::values("NAME|PREFIX"), "run this family, or every family starting with PREFIX (\"mesh/\")")
      ("exclude", adsd::cli::values("NAME|PREFIX"), "leave these families out")
      ("threads", adsd::cli::value("T"), "worker threads, from 1 (default: the machine's cores)")
      ("scale", adsd::cli::value("X"), "pin every case's scale to X > 0 (default: each family's range)")
      ("case", adsd::cli::value("I"), "run case I of the one --family alone")
      ("report", adsd::cli::value("K"), "failures printed per check")
      ("no-minimize", "print failing cases as found, not minimized")
      ("progress", adsd::cli::value("SECONDS"), "a progress line every SECONDS, > 0")
      ("pending", adsd::cli::values("LABEL"),
       "failures whose check label contains LABEL are counted apart (a reported bug), not failing the run")
      ("list", "list the families and exit");
  return line;
}

int run(const adsd::cli::Arguments& given, int argc, char** argv) {
  using adsd::cli::UsageError;
  SuiteOptions options;
  options.threads = int(std::max(1u, std::thread::hardware_concurrency()));
  const adsd::cli::RealInterval positive = adsd::cli::RealInterval::above(0.0).below(1e300);
  options.casesPerFamily = given.whole("cases").value_or(options.casesPerFamily);
  options.seed = given.whole("seed").value_or(options.seed);
  if (const auto threads = given.whole("threads", 1, 1024)) options.threads = int(*threads);
  const std::optional<std::uint64_t> caseIndex = given.whole("case");
  if (const auto report = given.whole("report", 0, 1000000)) options.reportsPerCheck = int(*report);
  options.scale = given.real("scale", positive).value_or(options.scale);
  options.progressSeconds = given.real("progress", positive).value_or(options.progressSeconds);
  for (const std::string& name : given.texts("family")) {
    bool found = false;
    for (const Family& f : families()) {
      if (f.name == name || f.name.rfind(name, 0) == 0) {
        options.families.push_back(&f);
        found = true;
      }
    }
    if (!found) throw UsageError("--family: no family called or starting with '" + name + "' (see --list)");
  }
  for (const std::string& label : given.texts("pending")) {
    if (label.empty()) throw UsageError("--pending needs a failure label (or part of one)");
    options.pending.push_back(label);
  }
  options.minimize = !given.has("no-minimize");
  if (given.has("list")) {
    for (const Family& f : families()) {
      std::printf("%-28s scale 1e%+g..1e%+g  %s\n", f.name.c_str(), f.log10ScaleLo, f.log10ScaleHi, f.covers.c_str());
    }
    return 0;
  }
  if (caseIndex) {
    if (options.families.size() != 1) throw UsageError("--case needs exactly one --family");
    return runOneCase(*options.families[0], options.seed, *caseIndex, options.scale, options.minimize, stdout) ? 0 : 1;
  }
  const std::vector<std::string> excluded = given.texts("exclude");
  if (!excluded.empty()) {
    if (options.families.empty()) {
      for (const Family& f : families()) options.families.push_back(&f);
    }
    for (const std::string& name : excluded) {
      const auto before = options.families.size();
      options.families.erase(std::remove_if(options.families.begin(), options.families.end(),
                                            [&](const Family* f) { return f->name == name || f->name.rfind(name, 0) == 0; }),
                             options.families.end());
      if (options.families.size() == before) throw UsageError("--exclude: no selected family matches '" + name + "'");
    }
    if (options.families.empty()) throw UsageError("every family is excluded");
  }
  std::printf("adsd_stress");
  for (int i = 1; i < argc; ++i) std::printf(" %s", argv[i]);
  std::printf("\n");
  std::fflush(stdout);
  const SuiteResult result = runSuite(options);
  printTable(result, options);
  return result.passed() ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  return adsd::cli::runProgram(commandLine(), argc, argv,
                               [&](const adsd::cli::Arguments& given) { return run(given, argc, argv); });
}
