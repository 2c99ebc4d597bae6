/// \file
/// \brief The families themselves: deterministic from (seed, index), different across seeds,
/// valid finite geometry at both ends of their scale range, unique names covering both levels.

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "families.h"

namespace adsd::stress {
namespace {

bool sameGeometry(const StressCase& x, const StressCase& y) {
  return x.a.vertices() == y.a.vertices() && x.b.vertices() == y.b.vertices() && x.a.triangles() == y.a.triangles() &&
         x.b.triangles() == y.b.triangles() && x.poseA.matrix() == y.poseA.matrix() && x.poseB.matrix() == y.poseB.matrix() &&
         x.scale == y.scale && x.penetrating == y.penetrating;
}

TEST(StressFamilies, NamesAreUniqueAndBothLevelsArePresent) {
  std::set<std::string> names;
  int triangleLevel = 0, meshLevel = 0;
  for (const Family& f : families()) {
    EXPECT_TRUE(names.insert(f.name).second) << f.name;
    triangleLevel += f.name.rfind("tri/", 0) == 0;
    meshLevel += f.name.rfind("mesh/", 0) == 0;
    EXPECT_EQ(findFamily(f.name), &f);
  }
  EXPECT_GE(triangleLevel, 5);
  EXPECT_GE(meshLevel, 12);
  EXPECT_EQ(findFamily("no such family"), nullptr);
}

TEST(StressFamilies, CasesAreDeterministicAndDependOnTheSeed) {
  for (const Family& f : families()) {
    for (std::uint64_t index : {0, 7, 123456}) {
      const StressCase first = generateCase(f, 42, index), again = generateCase(f, 42, index);
      EXPECT_TRUE(sameGeometry(first, again)) << f.name << " case " << index;
      EXPECT_FALSE(sameGeometry(first, generateCase(f, 43, index))) << f.name << " case " << index;
    }
  }
}

TEST(StressFamilies, GeometryIsFiniteAtBothEndsOfTheScaleRange) {
  for (const Family& f : families()) {
    for (double log10Scale : {f.log10ScaleLo, f.log10ScaleHi}) {
      for (std::uint64_t index = 0; index < 40; ++index) {
        const StressCase c = generateCase(f, 5, index, std::pow(10.0, log10Scale));
        ASSERT_GE(c.a.triangleCount(), 1u);
        ASSERT_GE(c.b.triangleCount(), 1u);
        ASSERT_TRUE(c.poseA.matrix().allFinite() && c.poseB.matrix().allFinite()) << f.name;
        // Rotations stay rotations (to rounding): the oracle applies them as given.
        EXPECT_NEAR((c.poseA.linear().transpose() * c.poseA.linear() - Eigen::Matrix3d::Identity()).norm(), 0, 1e-14) << f.name;
        EXPECT_NEAR((c.poseB.linear().transpose() * c.poseB.linear() - Eigen::Matrix3d::Identity()).norm(), 0, 1e-14) << f.name;
        EXPECT_GT(c.poseA.linear().determinant(), 0) << f.name;
        EXPECT_GT(c.poseB.linear().determinant(), 0) << f.name;
      }
    }
  }
}

}  // namespace
}  // namespace adsd::stress
