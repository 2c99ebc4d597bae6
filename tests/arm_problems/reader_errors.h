#pragma once
// What the arm-problem readers' error tests share: the message a reader raises on a text, and the
// text with one line replaced.

#include <gtest/gtest.h>

#include <string>

#include "adsd/error.h"

namespace adsd::planner::test {

/// The message of the adsd::InputError that \p read (called with \p text) raises, after the source
/// name \p name it must start with; checked to be one line. A test failure when nothing is raised.
template <class Read>
std::string errorAfterName(const Read& read, const std::string& text, const std::string& name) {
  try {
    read(text);
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(message.rfind(name, 0), 0u) << message;
    return message.substr(name.size());
  }
  ADD_FAILURE() << "no error for:\n" << text;
  return "";
}

/// \p text with line \p line (1-based) replaced by \p replacement.
inline std::string withLineReplaced(const std::string& text, int line, const std::string& replacement) {
  std::size_t begin = 0;
  for (int i = 1; i < line; ++i) begin = text.find('\n', begin) + 1;
  return text.substr(0, begin) + replacement + text.substr(text.find('\n', begin));
}

}  // namespace adsd::planner::test

/// The message errorOf(text) (each test file's reader, through errorAfterName) gives starts with
/// \p prefix (":LINE:") and contains \p part.
#define EXPECT_ERROR(text, prefix, part)             \
  do {                                               \
    const std::string m = errorOf(text);             \
    EXPECT_EQ(m.rfind(prefix, 0), 0u) << m;          \
    EXPECT_NE(m.find(part), std::string::npos) << m; \
  } while (0)
