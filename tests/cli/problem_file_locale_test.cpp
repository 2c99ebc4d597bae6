// The problem-file reader in a program that switched to a decimal-comma locale: an OMPL program
// with a GUI often calls setlocale(LC_ALL, ""), and the reader must still take "0.5" as a half
// (the file format's numbers are the C locale's, whatever the process's).

#include <gtest/gtest.h>

#include <clocale>
#include <cstdlib>
#include <string>

#include "adsd/planner/problem_file.h"
#include "scratch_dir.h"

namespace adsd::planner {
namespace {

TEST(ProblemFileLocale, DecimalPointsReadTheSameUnderACommaLocale) {
  // Compiled by the cli_locale fixture into LOCPATH (localedef, Debian package locales).
  ASSERT_NE(std::setlocale(LC_ALL, "de_DE.UTF-8"), nullptr)
      << "no de_DE.UTF-8 locale (LOCPATH=" << (std::getenv("LOCPATH") ? std::getenv("LOCPATH") : "unset") << ")";
  // The locale is in force: the C library itself now reads "0,5" as a half and stops at a point.
  ASSERT_EQ(std::strtod("0,5", nullptr), 0.5);
  ASSERT_EQ(std::strtod("0.5", nullptr), 0.0);
  test::ScratchDir dir;
  const ProblemFile p = readProblemFile(dir.write("p.cfg", "[problem]\nrobot = r.obj\nworld = w.obj\n"
                                                            "start.x = 0.5\nstart.y = -2.25e1\nstart.theta = 1.5\n"
                                                            "goal.x = 3\ngoal.y = 4\ngoal.theta = 0.125\n"));
  std::setlocale(LC_ALL, "C");
  EXPECT_EQ(p.start.position.x(), 0.5);
  EXPECT_EQ(p.start.position.y(), -22.5);
  EXPECT_EQ(p.start.theta, 1.5);
  EXPECT_EQ(p.goal.theta, 0.125);
}

}  // namespace
}  // namespace adsd::planner
