#include "adsd/cli/numbers.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <system_error>

#include "adsd/cli/usage_error.h"

namespace adsd::cli {

std::optional<std::uint64_t> toWhole(std::string_view text) {
  // from_chars takes no '+' or space but does take a '-' for signed types only; digits alone are
  // checked first so that the rule does not hang on the type.
  if (text.empty() || text.find_first_not_of("0123456789") != std::string_view::npos) return std::nullopt;
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;  // beyond 2^64 - 1
  return value;
}

std::optional<double> toReal(std::string_view text) {
  // from_chars takes a '-' but not a '+'; strtod took both, and "+1" is a plain number.
  std::string_view digits = text;
  if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
  if (digits.empty() || (digits.front() == '-' && text.front() == '+')) return std::nullopt;  // "+-1"
  // "inf" and "nan" (which from_chars reads) start with a letter; a number starts with a sign,
  // a digit or a point.
  const char first = digits.front() == '-' && digits.size() > 1 ? digits[1] : digits.front();
  if (!(first == '.' || (first >= '0' && first <= '9'))) return std::nullopt;
  double value = 0.0;
  const auto [end, error] =
      std::from_chars(digits.data(), digits.data() + digits.size(), value, std::chars_format::general);
  // result_out_of_range: beyond the largest double, or below the smallest subnormal.
  if (error != std::errc() || end != digits.data() + digits.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

bool RealInterval::contains(double x) const {
  const bool aboveLow = lowIncluded ? x >= low : x > low;
  const bool belowHigh = highIncluded ? x <= high : x < high;
  return aboveLow && belowHigh;
}

std::string shortestText(double x) {
  char text[32];
  const auto result = std::to_chars(text, text + sizeof text, x);
  return std::string(text, result.ptr);
}

std::string RealInterval::describe() const {
  std::string lowPart, highPart;
  if (std::isfinite(low)) lowPart = (lowIncluded ? ">= " : "> ") + shortestText(low);
  if (std::isfinite(high)) highPart = (highIncluded ? "<= " : "< ") + shortestText(high);
  if (lowPart.empty() && highPart.empty()) return "";
  if (lowPart.empty()) return highPart;
  if (highPart.empty()) return lowPart;
  return lowPart + " and " + highPart;
}

std::uint64_t parseWhole(std::string_view text, const std::string& what, std::uint64_t min, std::uint64_t max) {
  const std::optional<std::uint64_t> value = toWhole(text);
  if (!value || *value < min || *value > max) {
    const std::string range = max == std::numeric_limits<std::uint64_t>::max()
                                  ? (min == 0 ? "" : " >= " + std::to_string(min))
                                  : " from " + std::to_string(min) + " to " + std::to_string(max);
    throw UsageError(what + ": expected a whole number" + range + ", got '" + std::string(text) + "'");
  }
  return *value;
}

double parseReal(std::string_view text, const std::string& what, const RealInterval& range) {
  const std::optional<double> value = toReal(text);
  if (!value || !range.contains(*value)) {
    const std::string bounds = range.describe();
    throw UsageError(what + ": expected a finite number" + (bounds.empty() ? "" : " " + bounds) + ", got '" +
                     std::string(text) + "'");
  }
  return *value;
}

}  // namespace adsd::cli
