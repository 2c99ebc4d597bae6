#pragma once
/// \file
/// \brief Small locale-independent text scanning shared by the pose-file reader and the mesh-file
/// structure checks: lines with their numbers, whitespace tokens, whole-token numbers.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace adsd::io::detail {

/// \brief The UTF-8 byte-order mark, which some editors put at the start of a text file.
inline constexpr std::string_view kUtf8ByteOrderMark = "\xEF\xBB\xBF";

/// \brief Walks a buffer line by line, after a UTF-8 byte-order mark at its start if any ('\n' ends
/// a line; a '\r' before it is dropped; in a buffer with no '\n' at all, '\r' ends a line, as in
/// classic Mac OS text), counting lines from 1 and remembering where the next line starts (binary
/// PLY data follows its header).
class LineScanner {
 public:
  explicit LineScanner(std::string_view text);

  /// \brief The next line without its terminator; false at the end of the buffer.
  bool next(std::string_view& line);
  /// \brief 1-based number of the line last returned by next().
  int lineNumber() const { return lineNumber_; }
  /// \brief Offset of the first byte after the line last returned (after its '\n').
  std::size_t offset() const { return offset_; }

 private:
  std::string_view text_;
  char lineEnd_ = '\n';
  std::size_t offset_ = 0;
  int lineNumber_ = 0;
};

/// \brief The longest line of a text mesh file split into words: a face of a million corners fits
/// (about 8 MB). Each word takes 16 bytes, so a 100 MB face line took 38 times the file in
/// memory before this bound (adversarial review).
inline constexpr std::size_t kMaxWordLineBytes = std::size_t{16} << 20;

/// \brief Splits at spaces, tabs, '\r', '\v' and '\f'.
std::vector<std::string_view> splitWhitespace(std::string_view text);

/// \brief True if \p text holds nothing but whitespace.
bool isBlank(std::string_view text);

/// \brief Parses a whole token as a double (std::from_chars, so independent of the C locale); a
/// leading '+' is accepted. Accepts "nan" and "inf": finiteness is the caller's check.
bool parseDouble(std::string_view token, double& value);

/// \brief Parses a whole token as a decimal integer; a leading '+' is accepted.
bool parseInteger(std::string_view token, long long& value);

/// \brief A token fit for a one-line message: quoted, at most 40 characters, control and non-ASCII
/// bytes shown as '?'.
std::string quoteToken(std::string_view token);

}  // namespace adsd::io::detail
