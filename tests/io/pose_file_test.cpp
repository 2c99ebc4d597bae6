// adsd::io::readPoseFile: the format of `adsd distance --poses`, and its bad-input cases.

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "adsd/error.h"
#include "adsd/io/pose_file.h"

namespace adsd::io {
namespace {

const char* const kIdentityPair = "0 0 0 1 0 0 0   0 0 0 1 0 0 0";

std::vector<PosePair> read(const std::string& text) {
  std::istringstream in(text);
  return readPoseFile(in, "poses.txt");
}

/// Reads \p text expecting InputError; returns its message after checking it is one line that
/// starts with "poses.txt:LINE: ".
std::string readError(const std::string& text, int expectedLine) {
  try {
    read(text);
  } catch (const InputError& e) {
    const std::string message = e.what();
    const std::string prefix = "poses.txt:" + std::to_string(expectedLine) + ": ";
    EXPECT_EQ(message.rfind(prefix, 0), 0u) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    return message;
  }
  ADD_FAILURE() << "expected adsd::InputError for:\n" << text;
  return "";
}

TEST(PoseFile, ReadsPosesThatMapMeshToWorld) {
  // A: translate (1,2,3), no rotation. B: rotate 90 degrees about z (qw = qz = sqrt(1/2)), then
  // translate (0,0,-4).
  const double h = std::sqrt(0.5);
  std::ostringstream text;
  text.precision(17);
  text << "1 2 3 1 0 0 0  0 0 -4 " << h << " 0 0 " << h << "\n";
  const std::vector<PosePair> poses = read(text.str());
  ASSERT_EQ(poses.size(), 1u);
  EXPECT_EQ(poses[0].line, 1);
  EXPECT_LT((poses[0].a * Vec3(1, 0, 0) - Vec3(2, 2, 3)).norm(), 1e-15);
  EXPECT_LT((poses[0].b * Vec3(1, 0, 0) - Vec3(0, 1, -4)).norm(), 1e-15);
}

TEST(PoseFile, CommentsBlankLinesAndCrLfAreSkippedAndLinesCounted) {
  const std::string text = std::string("# header comment\n\n   \t\n") + kIdentityPair + "  # trailing comment\r\n" +
                           "\r\n" + "+1 -2 3.5e0 1 0 0 0 4 5 6 1 0 0 0\n";
  const std::vector<PosePair> poses = read(text);
  ASSERT_EQ(poses.size(), 2u);
  EXPECT_EQ(poses[0].line, 4);
  EXPECT_EQ(poses[1].line, 6);
  EXPECT_EQ(poses[1].a.translation(), Vec3(1, -2, 3.5));
  EXPECT_EQ(poses[1].b.translation(), Vec3(4, 5, 6));
}

TEST(PoseFile, LoneCarriageReturnsEndLines) {
  // Classic Mac OS text: before, its lines ran together into one line of 28 numbers.
  const std::string text = std::string("# header\r") + kIdentityPair + "\r\r" + kIdentityPair + "\r";
  const std::vector<PosePair> poses = read(text);
  ASSERT_EQ(poses.size(), 2u);
  EXPECT_EQ(poses[0].line, 2);
  EXPECT_EQ(poses[1].line, 4);
  const std::string bad = readError(std::string(kIdentityPair) + "\r0 0 0 1 0 0 0\r", 2);
  EXPECT_NE(bad.find("got 7"), std::string::npos) << bad;
}

TEST(PoseFile, Utf8ByteOrderMarkBeforeTheFirstLineIsSkipped) {
  const std::vector<PosePair> poses = read("\xEF\xBB\xBF" + std::string(kIdentityPair) + "\n");
  ASSERT_EQ(poses.size(), 1u);
  EXPECT_EQ(poses[0].line, 1);
}

// A UTF-16 file (Windows Notepad may save one) had its first number quoted as '??0?'.
TEST(PoseFile, WideTextIsRefusedNamingItsEncoding) {
  std::string utf16 = "\xFF\xFE";
  for (const char c : std::string(kIdentityPair) + "\n") utf16 += std::string{c, '\0'};
  try {
    read(utf16);
    ADD_FAILURE() << "no error for a UTF-16 pose file";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "poses.txt: the file is UTF-16LE text; save it as UTF-8 (iconv -f UTF-16LE -t UTF-8)");
  }
}

TEST(PoseFile, EmptyInputHasNoPoses) { EXPECT_TRUE(read("# nothing\n\n").empty()); }

TEST(PoseFile, QuaternionWithinToleranceIsNormalized) {
  const std::vector<PosePair> poses = read("0 0 0 1.0000005 0 0 0  0 0 0 0 0.9999995 0 0\n");
  ASSERT_EQ(poses.size(), 1u);
  EXPECT_LT((poses[0].a.linear() - Eigen::Matrix3d::Identity()).norm(), 1e-15);
  const Eigen::Matrix3d r = poses[0].b.linear();
  EXPECT_LT((r * r.transpose() - Eigen::Matrix3d::Identity()).norm(), 1e-15);
}

TEST(PoseFileBadInput, ThirteenNumbers) {
  const std::string message = readError(std::string(kIdentityPair) + "\n" + "0 0 0 1 0 0 0 0 0 0 1 0 0\n", 2);
  EXPECT_NE(message.find("expected 14 numbers"), std::string::npos) << message;
  EXPECT_NE(message.find("got 13"), std::string::npos) << message;
}

TEST(PoseFileBadInput, FifteenNumbers) {
  EXPECT_NE(readError(std::string(kIdentityPair) + " 0\n", 1).find("got 15"), std::string::npos);
}

TEST(PoseFileBadInput, NonUnitQuaternionNamesTheMesh) {
  const std::string b = readError("0 0 0 1 0 0 0  0 0 0 1.2 0 0 0\n", 1);
  EXPECT_NE(b.find("quaternion of mesh B has norm 1.2"), std::string::npos) << b;
  const std::string a = readError("# ok\n0 0 0 0 0 0 0  0 0 0 1 0 0 0\n", 2);
  EXPECT_NE(a.find("quaternion of mesh A has norm 0"), std::string::npos) << a;
  // Just beyond the tolerance of 1e-6.
  readError("0 0 0 1.000002 0 0 0  0 0 0 1 0 0 0\n", 1);
  // Components whose squares overflow: the norm is said as it is, not "inf".
  const std::string huge = readError("0 0 0 1e300 1e300 0 0  0 0 0 1 0 0 0\n", 1);
  EXPECT_NE(huge.find("quaternion of mesh A has norm 1.41421356237e+300"), std::string::npos) << huge;
}

TEST(PoseFileBadInput, NanAndInfinityNameTheField) {
  const std::string nan = readError("0 nan 0 1 0 0 0  0 0 0 1 0 0 0\n", 1);
  EXPECT_NE(nan.find("field 2 (ty of mesh A) is not finite"), std::string::npos) << nan;
  const std::string inf = readError("0 0 0 1 0 0 0  0 0 0 1 0 0 -inf\n", 1);
  EXPECT_NE(inf.find("field 14 (qz of mesh B) is not finite"), std::string::npos) << inf;
  const std::string overflow = readError("0 0 1e999 1 0 0 0  0 0 0 1 0 0 0\n", 1);
  EXPECT_NE(overflow.find("field 3 (tz of mesh A)"), std::string::npos) << overflow;
}

TEST(PoseFileBadInput, NotANumber) {
  const std::string word = readError("0 0 0 1 0 0 0  0 0 x 1 0 0 0\n", 1);
  EXPECT_NE(word.find("field 10 (tz of mesh B) is not a number: 'x'"), std::string::npos) << word;
  const std::string comma = readError("0, 0 0 1 0 0 0  0 0 0 1 0 0 0\n", 1);
  EXPECT_NE(comma.find("field 1 (tx of mesh A) is not a number: '0,'"), std::string::npos) << comma;
  const std::string binary = readError(std::string("0 0 0 1 0 0 0  0 0 0 1 0 0 ") + "\x01\x02\n", 1);
  EXPECT_NE(binary.find("'?" "?'"), std::string::npos) << binary;  // two control bytes
}

TEST(PoseFileBadInput, LineWithoutEndIsRefusedAtItsLengthLimit) {
  // A stream without line ends (/dev/zero on stdin) was read into one string until memory ran out.
  const std::string endless(std::size_t{3} << 20, '0');
  const std::string message = readError(std::string(kIdentityPair) + "\n" + endless, 2);
  EXPECT_NE(message.find("line longer than 1048576 bytes"), std::string::npos) << message;
  // A long comment under the limit is still a comment.
  EXPECT_EQ(read(std::string(kIdentityPair) + " #" + std::string(100000, 'x') + "\n").size(), 1u);
}

TEST(PoseFileBadInput, PosesBeyondTheLimitAreRefusedAtTheFirstOneOver) {
  // An endless stream of good poses (`yes POSE | adsd distance --poses -`) took all the memory.
  std::string text;
  for (int i = 0; i < 5; ++i) text += std::string(kIdentityPair) + "\n# comment\n";
  std::istringstream in(text);
  try {
    readPoseFile(in, "poses.txt", 4);
    ADD_FAILURE() << "five poses read under a limit of four";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "poses.txt:9: more than 4 poses: split the file");
  }
  std::istringstream exactly(text);
  EXPECT_EQ(readPoseFile(exactly, "poses.txt", 5).size(), 5u);
}

TEST(PoseFileBadInput, BadLastLineMeansNothingIsReturned) {
  std::string text;
  for (int i = 0; i < 50; ++i) text += std::string(kIdentityPair) + "\n";
  text += "0 0 0 1 0 0 0\n";
  EXPECT_THROW(read(text), InputError);
  readError(text, 51);
}

}  // namespace
}  // namespace adsd::io
