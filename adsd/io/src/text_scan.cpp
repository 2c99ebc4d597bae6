#include "text_scan.h"

#include <algorithm>
#include <charconv>
#include <limits>
#include <type_traits>

namespace adsd::io::detail {

namespace {

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

/// from_chars reports a decimal beyond double's range as an error; it is a number all the same:
/// an overflow becomes +-infinity (for the caller's finiteness check to name), an underflow +-0.
/// Overflow: a non-negative exponent, or no exponent and a non-zero integer part.
double outOfRangeValue(std::string_view token) {
  const bool negative = token.front() == '-';
  const std::size_t e = token.find_first_of("eE");
  bool overflow;
  if (e != std::string_view::npos) {
    overflow = e + 1 >= token.size() || token[e + 1] != '-';
  } else {
    const std::string_view integerPart = token.substr(0, token.find('.'));
    overflow = integerPart.find_first_of("123456789") != std::string_view::npos;
  }
  const double magnitude = overflow ? std::numeric_limits<double>::infinity() : 0.0;
  return negative ? -magnitude : magnitude;
}

template <typename Number>
bool parseWhole(std::string_view token, Number& value) {
  if (!token.empty() && token.front() == '+') {
    token.remove_prefix(1);
    if (!token.empty() && token.front() == '-') return false;  // "+-1"
  }
  if (token.empty()) return false;
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  if constexpr (std::is_floating_point_v<Number>) {
    if (ec == std::errc::result_out_of_range && ptr == end) {
      value = outOfRangeValue(token);
      return true;
    }
  }
  return ec == std::errc() && ptr == end;
}

}  // namespace

LineScanner::LineScanner(std::string_view text) : text_(text) {
  // A UTF-8 byte-order mark, which Windows editors write at the start of text files, is not part
  // of the first line: left in, it hid an OBJ's first vertex (an unknown statement, skipped).
  if (text_.substr(0, kUtf8ByteOrderMark.size()) == kUtf8ByteOrderMark) offset_ = kUtf8ByteOrderMark.size();
  // Only a buffer without any '\n' is taken for CR-only text: a stray CR in LF or CR LF text stays
  // inside its line (where whitespace splitting drops it), as before.
  if (text_.find('\n') == std::string_view::npos && text_.find('\r') != std::string_view::npos) lineEnd_ = '\r';
}

bool LineScanner::next(std::string_view& line) {
  if (offset_ >= text_.size()) return false;
  const std::size_t newline = text_.find(lineEnd_, offset_);
  const std::size_t end = newline == std::string_view::npos ? text_.size() : newline;
  line = text_.substr(offset_, end - offset_);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  offset_ = newline == std::string_view::npos ? text_.size() : newline + 1;
  ++lineNumber_;
  return true;
}

std::vector<std::string_view> splitWhitespace(std::string_view text) {
  std::vector<std::string_view> tokens;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && isSpace(text[i])) ++i;
    const std::size_t start = i;
    while (i < text.size() && !isSpace(text[i])) ++i;
    if (i > start) tokens.push_back(text.substr(start, i - start));
  }
  return tokens;
}

bool isBlank(std::string_view text) { return std::all_of(text.begin(), text.end(), isSpace); }

bool parseDouble(std::string_view token, double& value) { return parseWhole(token, value); }

bool parseInteger(std::string_view token, long long& value) { return parseWhole(token, value); }

std::string quoteToken(std::string_view token) {
  constexpr std::size_t kMaxQuotedChars = 40;
  std::string quoted = "'";
  for (std::size_t i = 0; i < token.size() && i < kMaxQuotedChars; ++i) {
    const unsigned char c = static_cast<unsigned char>(token[i]);
    quoted += (c >= 0x20 && c < 0x7f) ? static_cast<char>(c) : '?';
  }
  if (token.size() > kMaxQuotedChars) quoted += "...";
  return quoted + "'";
}

}  // namespace adsd::io::detail
