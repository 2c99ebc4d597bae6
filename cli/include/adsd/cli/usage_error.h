#pragma once
/// \file
/// \brief The one error a command line can have: what() is the line to print, without the
/// program's name (command_line.h's reportUsageError adds it and returns exit status 2).

#include <stdexcept>

namespace adsd::cli {

/// \brief A bad command line: an unknown option, a missing or malformed value, a wrong count of
/// arguments. The message names the option and the text given.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// \brief The exit status of every program here on a bad command line (and on other bad input).
constexpr int kUsageExitStatus = 2;

}  // namespace adsd::cli
