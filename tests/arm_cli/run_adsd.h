#pragma once
// Running the built `adsd` program (ADSD_PROGRAM) as a user does, for the tests of tests/arm_cli:
// a fresh directory per test, and the exit status and output of one command.
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace adsd_test {

inline std::string readAll(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// A fresh directory per test, named after it.
inline std::filesystem::path workDirectory() {
  const auto* info = testing::UnitTest::GetInstance()->current_test_info();
  std::filesystem::path dir = std::filesystem::path(testing::TempDir()) /
                              (std::string("adsd_arm_cli_") + info->test_suite_name() + "_" + info->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

struct PlanRun {
  int status = -1;
  std::string out, err;
};

/// Runs `adsd COMMAND ARGS` with stdout and stderr into files of \p dir.
inline PlanRun runAdsd(const std::string& subcommand, const std::vector<std::string>& args,
                       const std::filesystem::path& dir) {
  std::string command = std::string("'") + ADSD_PROGRAM + "' " + subcommand;
  for (const std::string& a : args) command += " '" + a + "'";
  command += " > '" + (dir / "stdout").string() + "' 2> '" + (dir / "stderr").string() + "'";
  const int raw = std::system(command.c_str());
  PlanRun r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = readAll(dir / "stdout");
  r.err = readAll(dir / "stderr");
  return r;
}

}  // namespace adsd_test
