#pragma once
/// \file
/// \brief What every fuzz target shares: the libFuzzer entry point, how a broken property stops
/// the run, the one-exception-type rule for bad input, and a scratch directory for inputs that
/// the code under test reads from files.

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>

#include "adsd/error.h"

/// The entry point libFuzzer calls once per input (and replay_main.cpp calls once per file).
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace adsd::fuzz {

/// \brief A broken property: says which on stderr and traps, so that libFuzzer keeps the input
/// as a crash and a replay fails (SIGILL) in every build type, sanitizers or not.
[[noreturn]] inline void violation(const std::string& what) {
  std::fprintf(stderr, "adsd fuzz: property violated: %s\n", what.c_str());
  std::fflush(stderr);
  __builtin_trap();
}

/// \brief Bad input must be reported as one adsd::InputError whose message is one line starting
/// with \p source (the file or stream name), as the bad-input rule of the team brief says.
inline void requireOneLineNaming(const InputError& e, const std::string& source) {
  const std::string message = e.what();
  if (message.find('\n') != std::string::npos || message.find('\r') != std::string::npos) {
    violation("InputError message spans several lines: " + message);
  }
  if (message.rfind(source, 0) != 0) violation("InputError message does not start with '" + source + "': " + message);
}

/// \brief Runs \p body; an InputError is checked by requireOneLineNaming and accepted, any other
/// exception is a violation (the library documents InputError as its only exception for input).
template <typename Body>
void acceptingOnlyInputError(const std::string& source, Body&& body) {
  try {
    body();
  } catch (const InputError& e) {
    requireOneLineNaming(e, source);
  } catch (const std::exception& e) {
    violation(std::string("exception other than adsd::InputError: ") + e.what());
  } catch (...) {
    violation("exception of a non-std type");
  }
}

/// \brief A directory of this process's own (parallel fuzzing jobs must not share files), in
/// /dev/shm when there is one so that writing an input per execution stays in memory. Removed at
/// exit.
class ScratchDirectory {
 public:
  ScratchDirectory() {
    std::error_code ec;
    const std::filesystem::path base =
        std::filesystem::is_directory("/dev/shm", ec) ? std::filesystem::path("/dev/shm")
                                                      : std::filesystem::temp_directory_path();
    path_ = base / ("adsd-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(path_);
  }
  ~ScratchDirectory() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchDirectory(const ScratchDirectory&) = delete;
  ScratchDirectory& operator=(const ScratchDirectory&) = delete;

  /// \brief Writes \p size bytes to \p name in the directory (replacing it); returns the path.
  std::string write(const std::string& name, const std::uint8_t* data, std::size_t size) const {
    const std::string file = path(name);
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    out.close();
    if (!out) violation("cannot write the scratch file " + file);
    return file;
  }

  std::string path(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

}  // namespace adsd::fuzz
