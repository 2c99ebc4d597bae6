#pragma once
// The one spelling of a number that the planner's text readers (problem_file.cpp for OMPL.app's
// .cfg, yaml_input.cpp for MotionBenchMaker's YAML) accept.

#include <cctype>
#include <cstddef>
#include <string>

namespace adsd::planner::detail {

/// Whether \p v is written as a decimal number: an optional sign, digits with an optional point (at
/// least one digit), an optional exponent; nothing else. This is the form both strtod and OMPL's
/// classic-locale conversion read the same way in every locale (strtod alone would also take
/// hexadecimal, "inf", "nan" and leading blanks, which OMPL refuses by throwing; YAML's .inf and
/// .nan are refused too).
inline bool isDecimalNumber(const std::string& v) {
  std::size_t i = 0;
  const auto digitsAt = [&](std::size_t& k) {
    const std::size_t from = k;
    while (k < v.size() && std::isdigit(static_cast<unsigned char>(v[k]))) ++k;
    return k - from;
  };
  if (i < v.size() && (v[i] == '+' || v[i] == '-')) ++i;
  std::size_t digits = digitsAt(i);
  if (i < v.size() && v[i] == '.') {
    ++i;
    digits += digitsAt(i);
  }
  if (digits == 0) return false;
  if (i < v.size() && (v[i] == 'e' || v[i] == 'E')) {
    ++i;
    if (i < v.size() && (v[i] == '+' || v[i] == '-')) ++i;
    if (digitsAt(i) == 0) return false;
  }
  return i == v.size();
}

}  // namespace adsd::planner::detail
