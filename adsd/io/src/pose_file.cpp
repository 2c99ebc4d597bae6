#include "adsd/io/pose_file.h"

#include <array>
#include <climits>
#include <cmath>
#include <ios>
#include <new>
#include <sstream>
#include <string_view>

#include "adsd/error.h"
#include "adsd/io/text_encoding.h"
#include "text_scan.h"

namespace adsd::io {

namespace {

constexpr int kNumbersPerLine = 14;
/// The longest line read: 14 numbers of 17 digits and a comment fit thousands of times over. A
/// stream without line ends (a binary file, /dev/zero piped to stdin) is refused at this length
/// instead of filling the memory.
constexpr std::size_t kMaxLineBytes = std::size_t{1} << 20;
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
  // Scaled by the largest component: the sum of squares of components near 1e300 overflowed, and
  // the message said "norm inf" (an adversarial review).
  const double largest = q.coeffs().cwiseAbs().maxCoeff();
  const double norm = largest > 0.0 && std::isfinite(largest) ? largest * (q.coeffs() / largest).norm() : q.norm();
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

/// Reads line \p lineNumber of \p in into \p line without its end: '\n', "\r\n", or a lone '\r'
/// (classic Mac OS text, whose lines would otherwise run together into one). False at the end of
/// the input with nothing read.
bool nextLine(std::istream& in, std::string& line, const std::string& sourceName, long long lineNumber) {
  using Traits = std::istream::traits_type;
  line.clear();
  std::streambuf* const buffer = in.rdbuf();
  if (buffer == nullptr || !in.good()) return false;
  try {
    for (bool any = false;; any = true) {
      const Traits::int_type c = buffer->sbumpc();
      if (Traits::eq_int_type(c, Traits::eof())) {
        in.setstate(std::ios::eofbit);
        return any;
      }
      if (c == '\n') return true;
      if (c == '\r') {
        if (Traits::eq_int_type(buffer->sgetc(), Traits::to_int_type('\n'))) buffer->sbumpc();
        return true;
      }
      if (line.size() == kMaxLineBytes) {
        throw InputError(sourceName + ":" + std::to_string(lineNumber) + ": line longer than " +
                         std::to_string(kMaxLineBytes) + " bytes (not a pose file?)");
      }
      line.push_back(Traits::to_char_type(c));
    }
  } catch (const std::ios_base::failure&) {  // a file stream's read error
    in.setstate(std::ios::badbit);
    return false;
  }
}

}  // namespace

std::vector<PosePair> readPoseFile(std::istream& in, const std::string& sourceName, std::size_t maxPoses) {
  std::vector<PosePair> poses;
  std::string line;
  int lineNumber = 0;
  while (nextLine(in, line, sourceName, lineNumber + 1LL)) {
    if (lineNumber == INT_MAX) throw InputError(sourceName + ": more than " + std::to_string(INT_MAX) + " lines");
    ++lineNumber;
    std::string_view content(line);
    if (lineNumber == 1 && content.substr(0, detail::kUtf8ByteOrderMark.size()) == detail::kUtf8ByteOrderMark) {
      content.remove_prefix(detail::kUtf8ByteOrderMark.size());
    }
    // A wide encoding's mark (Windows Notepad may save UTF-16): its first number was quoted as
    // '??0?', not a number, leaving the user to guess why.
    if (const std::string encoding = lineNumber == 1 ? wideTextEncoding(content) : std::string();
        !encoding.empty()) {
      throw InputError(sourceName + ": the file is " + encoding + " text; save it as UTF-8 (iconv -f " + encoding +
                       " -t UTF-8)");
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
    if (poses.size() == maxPoses) {
      throw InputError(where + "more than " + std::to_string(maxPoses) + " poses: split the file");
    }
    try {
      poses.push_back(pair);
    } catch (const std::bad_alloc&) {
      throw InputError(where + "out of memory after " + std::to_string(poses.size()) + " poses: split the file");
    }
  }
  if (in.bad()) throw InputError(sourceName + ":" + std::to_string(lineNumber + 1) + ": read error");
  return poses;
}

}  // namespace adsd::io
