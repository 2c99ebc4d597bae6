// Ends the program when an OMPL planner runs far past its time limit.
#pragma once

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>

namespace adsd::app {

/// \brief While alive, ends the program with exit status 1 and one line on standard error
/// ("PROGRAM: error: planner PLANNER did not stop at its time limit ...; LOST") if it is not
/// destroyed within \p limitSeconds plus a grace (as long again, at least 10 s).
///
/// Why: OMPL planners stop at their time limit only where they test it, and some loops never do.
/// OMPL 1.5.2's BIT* asks its informed sampler for samples until it has them; in an SE(2) problem a
/// few centimetres wide whose goal turns the robot half round, the yaw's share of the distance
/// puts almost every informed sample outside the bounds, and `adsd plan --planner bitstar --time 2`
/// never returned (an outside review; OMPL's Benchmark waits on such a run for ever too). A thread
/// cannot be stopped from outside, so the program is: nothing has been written by then (outputs
/// are written after planning, through temporary files), and the line names the planner.
class PlannerWatchdog {
 public:
  /// Tells every watchdog that the program made \p directory for its outputs: a watchdog that ends
  /// the program removes it if it is still empty, so that a stopped `adsd benchmark --out NEW`
  /// leaves nothing behind (it makes the directory before the runs: their spools live there).
  static void outputDirectoryMade(const std::filesystem::path& directory) {
    std::lock_guard<std::mutex> lock(madeMutex());
    madeDirectory() = directory;
  }

  /// \p program names the command; \p lost says what is not written; \p freshLine starts the line
  /// afresh (after a progress bar's).
  PlannerWatchdog(const std::string& program, const std::string& planner, double limitSeconds,
                  const std::string& lost, bool freshLine = false) {
    std::ostringstream message;
    message << (freshLine ? "\n" : "") << program << ": error: planner " << planner
            << " did not stop at its time limit of " << limitSeconds
            << " s (an OMPL planner stops only where it tests the limit, and this one did not); " << lost;
    message_ = message.str();
    const double grace = std::max(10.0, limitSeconds);
    const auto deadline = std::chrono::steady_clock::now() +
                          std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                              std::chrono::duration<double>(limitSeconds + grace));
    watcher_ = std::thread([this, deadline, total = limitSeconds + grace] {
      std::unique_lock<std::mutex> lock(mutex_);
      if (stopped_.wait_until(lock, deadline, [this] { return disarmed_; })) return;
      std::fflush(stdout);
      {
        std::lock_guard<std::mutex> made(madeMutex());
        std::error_code ignored;  // not empty, or gone: left as it is
        if (!madeDirectory().empty()) std::filesystem::remove(madeDirectory(), ignored);
      }
      std::fprintf(stderr, "%s (stopped after %.0f s)\n", message_.c_str(), total);
      std::fflush(stderr);
      std::_Exit(1);
    });
  }
  ~PlannerWatchdog() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      disarmed_ = true;
    }
    stopped_.notify_all();
    watcher_.join();
  }
  PlannerWatchdog(const PlannerWatchdog&) = delete;
  PlannerWatchdog& operator=(const PlannerWatchdog&) = delete;

 private:
  static std::mutex& madeMutex() {
    static std::mutex mutex;
    return mutex;
  }
  static std::filesystem::path& madeDirectory() {
    static std::filesystem::path directory;
    return directory;
  }

  std::string message_;
  std::mutex mutex_;
  std::condition_variable stopped_;
  bool disarmed_ = false;
  std::thread watcher_;
};

}  // namespace adsd::app
