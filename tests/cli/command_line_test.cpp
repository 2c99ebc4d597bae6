// adsd::cli: numbers read alike in every locale, and the command line every program shares
// (cli/include/adsd/cli/command_line.h).
#include <clocale>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "adsd/cli/command_line.h"
#include "adsd/cli/numbers.h"

namespace {

using adsd::cli::Arguments;
using adsd::cli::CommandLine;
using adsd::cli::RealInterval;
using adsd::cli::UsageError;

TEST(Numbers, WholeNumbersAreDigitsOnly) {
  EXPECT_EQ(adsd::cli::toWhole("0"), 0u);
  EXPECT_EQ(adsd::cli::toWhole("42"), 42u);
  EXPECT_EQ(adsd::cli::toWhole("18446744073709551615"), 18446744073709551615ull);
  for (const char* bad : {"", "-1", "+1", " 1", "1 ", "1.0", "1e3", "0x10", "18446744073709551616", "abc", "1e3x"}) {
    EXPECT_FALSE(adsd::cli::toWhole(bad)) << "'" << bad << "'";
  }
}

TEST(Numbers, RealsAreFiniteDecimals) {
  EXPECT_EQ(adsd::cli::toReal("0.5"), 0.5);
  EXPECT_EQ(adsd::cli::toReal("+2.5e-3"), 2.5e-3);
  EXPECT_EQ(adsd::cli::toReal("-.25"), -0.25);
  EXPECT_EQ(adsd::cli::toReal("1e3"), 1000.0);
  EXPECT_EQ(adsd::cli::toReal("7"), 7.0);
  for (const char* bad : {"", "+", "-", ".", "abc", "1e3x", "0,5", " 1", "1 ", "inf", "-inf", "nan", "+-1", "1e999",
                          "0x1p3", "1e"}) {
    EXPECT_FALSE(adsd::cli::toReal(bad)) << "'" << bad << "'";
  }
}

/// The decimal point is '.' whatever the C locale says. The test's locale is German (decimal
/// comma), compiled by the test's fixture into LOCPATH (localedef, Debian package locales); the
/// first expectations show that it really changes how strtod reads, so the last ones mean something.
TEST(Numbers, ReadAlikeInACommaLocale) {
  ASSERT_NE(std::setlocale(LC_NUMERIC, "de_DE.UTF-8"), nullptr)
      << "no de_DE.UTF-8 locale (LOCPATH=" << (std::getenv("LOCPATH") ? std::getenv("LOCPATH") : "unset")
      << "): the ctest fixture cli_locale compiles one with localedef";
  EXPECT_STREQ(std::localeconv()->decimal_point, ",");
  EXPECT_EQ(std::strtod("0,5", nullptr), 0.5);
  EXPECT_EQ(std::strtod("0.5", nullptr), 0.0);  // strtod stops at the '.'
  EXPECT_EQ(adsd::cli::toReal("0.5"), 0.5);
  EXPECT_EQ(adsd::cli::toReal("2.5e-3"), 2.5e-3);
  EXPECT_FALSE(adsd::cli::toReal("0,5"));
  EXPECT_EQ(adsd::cli::parseReal("1.5", "--time", RealInterval::above(0.0)), 1.5);
  std::setlocale(LC_NUMERIC, "C");
}

TEST(Numbers, ErrorsNameTheOptionTheRangeAndTheText) {
  try {
    adsd::cli::parseWhole("-1", "--runs", 1, 10);
    FAIL() << "no error";
  } catch (const UsageError& e) {
    EXPECT_STREQ(e.what(), "--runs: expected a whole number from 1 to 10, got '-1'");
  }
  try {
    adsd::cli::parseReal("abc", "--time", RealInterval::above(0.0).below(1e7));
    FAIL() << "no error";
  } catch (const UsageError& e) {
    EXPECT_STREQ(e.what(), "--time: expected a finite number > 0 and < 1e+07, got 'abc'");
  }
  EXPECT_THROW(adsd::cli::parseReal("0", "--cap", RealInterval::above(0.0)), UsageError);
  EXPECT_EQ(adsd::cli::parseReal("0", "--threshold", RealInterval::atLeast(0.0)), 0.0);
  EXPECT_THROW(adsd::cli::parseWhole("11", "--runs", 1, 10), UsageError);
  try {
    adsd::cli::parseWhole("1e3", "--cases");
    FAIL() << "no error";
  } catch (const UsageError& e) {
    EXPECT_STREQ(e.what(), "--cases: expected a whole number, got '1e3'");
  }
}

CommandLine example() {
  CommandLine line("example", "example [--time SECONDS] [--mode a|b] [--quick] [FILE...]", "An example.",
                   "Exit status: 0.");
  line.options()("time", adsd::cli::value("SECONDS"), "time limit")("mode", adsd::cli::value("M"), "a or b")(
      "tag", adsd::cli::values("T"), "repeatable")("quick", "a short run");
  line.positional("file");
  return line;
}

std::string usageError(const std::vector<std::string>& args) {
  try {
    const auto given = example().parse(args);
    if (given) {
      given->real("time");
      given->choice("mode", {"a", "b"});
    }
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(CommandLine, ReadsOptionsAndArguments) {
  const auto given = example().parse({"x.cfg", "--time", "2.5", "--quick", "--mode=b", "y.cfg", "--tag", "1", "--tag", "2"});
  ASSERT_TRUE(given);
  EXPECT_EQ(given->real("time", RealInterval::above(0)), 2.5);
  EXPECT_EQ(given->choice("mode", {"a", "b"}), "b");
  EXPECT_TRUE(given->has("quick"));
  EXPECT_EQ(given->texts("file"), (std::vector<std::string>{"x.cfg", "y.cfg"}));
  EXPECT_EQ(given->texts("tag"), (std::vector<std::string>{"1", "2"}));
  EXPECT_FALSE(given->text("missing-value"));
}

TEST(CommandLine, BadLinesAreOneLineErrors) {
  EXPECT_EQ(usageError({"--bogus"}), "unrecognised option '--bogus'");
  EXPECT_EQ(usageError({"--tim", "1"}), "unrecognised option '--tim'");  // no guessing from a prefix
  EXPECT_EQ(usageError({"--time"}), "the required argument for option '--time' is missing");
  EXPECT_EQ(usageError({"--time", "1", "--time", "2"}), "option '--time' cannot be specified more than once");
  EXPECT_EQ(usageError({"--time", "1e3x"}), "--time: expected a finite number, got '1e3x'");
  EXPECT_EQ(usageError({"--time", "-1"}), "");  // a negative number is a value, not an option
  EXPECT_EQ(usageError({"--mode", "c"}), "--mode: expected a or b, got 'c'");
}

TEST(CommandLine, HelpWinsAndListsEveryOption) {
  std::ostringstream help;
  example().printHelp(help);
  const std::string text = help.str();
  EXPECT_EQ(text.rfind("usage: example [--time SECONDS]", 0), 0u) << text;
  for (const char* part : {"An example.", "options:", "--time SECONDS", "--quick", "-h [ --help ]", "Exit status: 0."}) {
    EXPECT_NE(text.find(part), std::string::npos) << part << " not in:\n" << text;
  }
  testing::internal::CaptureStdout();
  EXPECT_FALSE(example().parse({"--bogus", "--help"}));
  EXPECT_FALSE(example().parse({"-h"}));
  EXPECT_NE(testing::internal::GetCapturedStdout().find("usage: example"), std::string::npos);
}

}  // namespace
