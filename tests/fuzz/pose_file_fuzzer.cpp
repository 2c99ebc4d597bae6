// Fuzz target: adsd::io::readPoseFile on a stream. Properties: every pose it returns is a rigid
// motion with finite entries (rotation orthonormal within kOrthonormalTolerance) and a line number
// inside the input, in increasing order; or one adsd::InputError whose one-line message starts
// with the stream's name. Nothing else, no crash, no hang.
#include <algorithm>
#include <sstream>
#include <string>

#include "adsd/io/pose_file.h"
#include "fuzz_support.h"

namespace {

/// A unit quaternion (normalized by the reader, within 1e-6 before that) gives a rotation matrix
/// orthonormal to a few ulps; 1e-12 (dimensionless) leaves three orders of magnitude.
constexpr double kOrthonormalTolerance = 1e-12;

const std::string kSource = "fuzz.poses";

void requireRigid(const adsd::Pose& pose, int line) {
  if (!pose.matrix().allFinite()) adsd::fuzz::violation("line " + std::to_string(line) + ": non-finite pose");
  const Eigen::Matrix3d r = pose.linear();
  const double offOrthonormal = (r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (!(offOrthonormal <= kOrthonormalTolerance) || !(r.determinant() > 0)) {
    adsd::fuzz::violation("line " + std::to_string(line) + ": rotation is not a rotation");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  // Lines as the reader counts them: '\n', "\r\n" or a lone '\r' ends a line.
  int lineCount = 1;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n' || (text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n'))) ++lineCount;
  }
  adsd::fuzz::acceptingOnlyInputError(kSource, [&] {
    std::istringstream in(text);
    const std::vector<adsd::io::PosePair> poses = adsd::io::readPoseFile(in, kSource);
    int previous = 0;
    for (const adsd::io::PosePair& p : poses) {
      if (p.line <= previous || p.line > lineCount) {
        adsd::fuzz::violation("line number " + std::to_string(p.line) + " out of order or beyond the input");
      }
      previous = p.line;
      requireRigid(p.a, p.line);
      requireRigid(p.b, p.line);
    }
  });
  return 0;
}
