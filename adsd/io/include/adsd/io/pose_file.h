#pragma once
/// \file
/// \brief The pose-file format of `adsd distance --poses`: one query per line.
///
/// A line holds 14 numbers, `tx ty tz qw qx qy qz` for mesh A, then the same for mesh B; each
/// pose maps mesh coordinates to the world. `#` starts a comment; blank lines are skipped. Lines
/// end in '\n', "\r\n" or a lone '\r', and are at most 1 MiB long.

#include <cstddef>
#include <istream>
#include <limits>
#include <string>
#include <vector>

#include "adsd/mesh.h"

namespace adsd::io {

struct PosePair {
  Pose a = Pose::Identity();
  Pose b = Pose::Identity();
  int line = 0;  ///< 1-based line number in the source, for messages
};

/// Quaternions must have unit norm within this, as the format promises (dimensionless).
inline constexpr double kQuaternionNormTolerance = 1e-6;

/// \brief Reads all pose pairs; throws adsd::InputError "NAME:LINE: what is wrong" for a line
/// without exactly 14 finite numbers or with a quaternion whose norm is off by more than
/// kQuaternionNormTolerance, or a line longer than 1 MiB (a stream without line ends is refused
/// there, not read into memory whole). Nothing is returned unless every line is good.
/// A file of more than \p maxPoses poses is refused at the line of the first pose beyond them (an
/// endless stream of poses on stdin otherwise takes all the memory), and so is one that exhausts
/// the memory before that.
std::vector<PosePair> readPoseFile(std::istream& in, const std::string& sourceName,
                                   std::size_t maxPoses = std::numeric_limits<std::size_t>::max());

}  // namespace adsd::io
