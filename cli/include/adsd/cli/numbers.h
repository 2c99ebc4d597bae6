#pragma once
/// \file
/// \brief Numbers on a command line, read the same way in every locale.
///
/// Why not strtod, strtoul or std::stod: they read the decimal point of the C locale the process
/// runs in (a program, or a library it loads, that calls setlocale(LC_ALL, "") under a German
/// locale reads "0.5" as 0), take a sign, leading spaces and "inf", and strtoul turns "-1" into
/// 2^64 - 1. std::from_chars reads one fixed grammar in every locale; these functions add the
/// checks every option needs (the whole text used, finite, in range).

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>

namespace adsd::cli {

/// \brief A whole decimal number: digits only (no sign, space, point or exponent), at most
/// 2^64 - 1. Nullopt for anything else.
std::optional<std::uint64_t> toWhole(std::string_view text);

/// \brief A finite decimal number: an optional sign, digits with an optional '.' (the decimal
/// point in every locale), an optional exponent ("2.5e-3"). Nullopt for anything else, for
/// "inf" and "nan", and for magnitudes beyond the largest double.
std::optional<double> toReal(std::string_view text);

/// \brief The shortest decimal text that reads back (toReal, strtod) as exactly \p x: a value one
/// ulp beyond a limit prints apart from the limit, where a stream's 6 digits print both alike
/// ("inf", "-inf" and "nan" for those).
std::string shortestText(double x);

/// \brief The reals an option takes: an interval, each end open or closed (infinite ends are open).
struct RealInterval {
  double low = -std::numeric_limits<double>::infinity();
  bool lowIncluded = false;
  double high = std::numeric_limits<double>::infinity();
  bool highIncluded = false;

  /// (\p x, inf): "> x".
  static RealInterval above(double x) { return {x, false}; }
  /// [\p x, inf): ">= x".
  static RealInterval atLeast(double x) { return {x, true}; }
  /// This interval with its upper end open at \p x: "... and < x".
  RealInterval below(double x) const {
    RealInterval r = *this;
    r.high = x;
    r.highIncluded = false;
    return r;
  }

  /// This interval with its upper end closed at \p x: "... and <= x".
  RealInterval atMost(double x) const {
    RealInterval r = *this;
    r.high = x;
    r.highIncluded = true;
    return r;
  }

  bool contains(double x) const;
  /// For messages: "> 0", ">= 0 and <= 1", "any".
  std::string describe() const;
};

/// \brief \p text as a whole number in [\p min, \p max]; throws UsageError
/// "WHAT: expected a whole number from MIN to MAX, got 'TEXT'" (">= MIN" without a maximum).
std::uint64_t parseWhole(std::string_view text, const std::string& what, std::uint64_t min = 0,
                         std::uint64_t max = std::numeric_limits<std::uint64_t>::max());

/// \brief \p text as a finite number in \p range; throws UsageError
/// "WHAT: expected a finite number RANGE, got 'TEXT'".
double parseReal(std::string_view text, const std::string& what, const RealInterval& range = {});

}  // namespace adsd::cli
