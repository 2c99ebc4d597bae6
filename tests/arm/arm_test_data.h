#pragma once
/// \file
/// \brief Where tests/arm finds its robots: the small hand-written URDF in tests/arm/data, and the
/// real arms that problems/data/fetch_robots.sh caches (skipped, naming the script, without them).

#include <cstdlib>
#include <filesystem>
#include <string>

namespace adsd::planner::test {

inline std::string armTestData(const std::string& name) { return std::string(ADSD_ARM_TEST_DATA) + "/" + name; }

/// The robot cache: $ADSD_ROBOTS (as in an arm problem's .cfg), or ~/.cache/adsd/robots (fetch_robots.sh's default).
inline std::string robotCacheDir() {
  if (const char* dir = std::getenv("ADSD_ROBOTS"); dir && *dir) return dir;
  const char* home = std::getenv("HOME");
  return std::string(home ? home : ".") + "/.cache/adsd/robots";
}
inline std::string kr5Urdf() { return robotCacheDir() + "/KR5/KR5 sixx R650.urdf"; }
inline std::string wamUrdf() { return robotCacheDir() + "/wam/wam.urdf"; }
inline std::string wamSearchDir() { return robotCacheDir() + "/wam"; }
inline bool haveRobots() { return std::filesystem::exists(kr5Urdf()) && std::filesystem::exists(wamUrdf()); }

}  // namespace adsd::planner::test

/// Skips the test, naming the fetch script, when the real arms are not cached.
#define ADSD_REQUIRE_ROBOTS()                                                                          \
  do {                                                                                                 \
    if (!::adsd::planner::test::haveRobots())                                                          \
      GTEST_SKIP() << "no robots in " << ::adsd::planner::test::robotCacheDir()                        \
                   << ": run problems/data/fetch_robots.sh";                                           \
  } while (0)
