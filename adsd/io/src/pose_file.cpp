#include "adsd/io/pose_file.h"

#include <array>
#include <cmath>
#include <sstream>
#include <string_view>

#include "adsd/error.h"
#include "text_scan.h"

namespace adsd::io {

namespace {

constexpr int kNumbersPerLine = 14;
constexpr int kNumbersPerPose = 7;
constexpr std::array<const char*, kNumbersPerPose> kPoseFieldNames = {"tx", "ty", "tz", "qw", "qx", "qy", "qz"};

std::string fieldName(int index) {
  return std::string(kPoseFieldNames[index % kNumbersPerPose]) + " of mesh " + (index < kNumbersPerPose ? "A" : "B");
}

std::string formatNorm(double norm) {
  std::ostringstream out;
  out.precision(12);
  out << norm;
  return out.str();
}

Pose poseFrom(const double* numbers, const std::string& where, const char* meshLabel) {
  const Eigen::Quaterniond q(numbers[3], numbers[4], numbers[5], numbers[6]);
  const double norm = q.norm();
  if (!(std::abs(norm - 1.0) <= kQuaternionNormTolerance)) {
    throw InputError(where + "quaternion of mesh " + meshLabel + " has norm " + formatNorm(norm) +
                     ", not 1 within " + formatNorm(kQuaternionNormTolerance));
  }
  Pose pose = Pose::Identity();
  // Normalized so that the rotation is orthonormal to rounding, whatever slack the file used.
  pose.linear() = q.normalized().toRotationMatrix();
  pose.translation() = Vec3(numbers[0], numbers[1], numbers[2]);
  return pose;
}

}  // namespace

std::vector<PosePair> readPoseFile(std::istream& in, const std::string& sourceName) {
  std::vector<PosePair> poses;
  std::string line;
  int lineNumber = 0;
  while (std::getline(in, line)) {
    ++lineNumber;
    std::string_view content(line);
    if (lineNumber == 1 && content.substr(0, detail::kUtf8ByteOrderMark.size()) == detail::kUtf8ByteOrderMark) {
      content.remove_prefix(detail::kUtf8ByteOrderMark.size());
    }
    if (const std::size_t hash = content.find('#'); hash != std::string_view::npos) content = content.substr(0, hash);
    const std::vector<std::string_view> tokens = detail::splitWhitespace(content);
    if (tokens.empty()) continue;

    const std::string where = sourceName + ":" + std::to_string(lineNumber) + ": ";
    if (tokens.size() != kNumbersPerLine) {
      throw InputError(where + "expected " + std::to_string(kNumbersPerLine) +
                       " numbers (tx ty tz qw qx qy qz of mesh A, then of mesh B), got " +
                       std::to_string(tokens.size()));
    }
    double numbers[kNumbersPerLine];
    for (int i = 0; i < kNumbersPerLine; ++i) {
      const std::string field = "field " + std::to_string(i + 1) + " (" + fieldName(i) + ")";
      if (!detail::parseDouble(tokens[i], numbers[i])) {
        throw InputError(where + field + " is not a number: " + detail::quoteToken(tokens[i]));
      }
      if (!std::isfinite(numbers[i])) {
        throw InputError(where + field + " is not finite: " + detail::quoteToken(tokens[i]));
      }
    }
    PosePair pair;
    pair.a = poseFrom(numbers, where, "A");
    pair.b = poseFrom(numbers + kNumbersPerPose, where, "B");
    pair.line = lineNumber;
    poses.push_back(pair);
  }
  if (in.bad()) throw InputError(sourceName + ":" + std::to_string(lineNumber + 1) + ": read error");
  return poses;
}

}  // namespace adsd::io
