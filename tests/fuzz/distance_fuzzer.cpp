// Fuzz target: adsd::distance on two small meshes and poses built from the input bytes
// (layout in decodeScene below). Properties, those of the numerics issue (3):
//  - termination (libFuzzer's -timeout; the counters stay within the documented GJK cap);
//  - no NaN or infinity in the exact result; status exact with lower == upper == distance;
//  - the witnesses realize the distance and lie on the triangles they name;
//  - symmetry: the query with A and B swapped agrees within kAgreement x scale;
//  - the exact distance agrees with the independent oracle (binary128 brute force) within the same;
//  - the other query modes (threshold, cap, tolerance; picked by the input) are consistent with it;
//  - no exception at all: every scene built here is valid input.
// A violation traps (fuzz_support.h).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "adsd/distance.h"
#include "adsd/tolerances.h"
#include "fuzz_support.h"
#include "oracle.h"

namespace {

using adsd::fuzz::violation;

/// Agreement required between two answers to the same question (symmetry, oracle, modes), relative
/// to the scene's coordinate scale: the accuracy the core promises (issue 3: 1e-10 of the scene).
constexpr double kAgreement = 1e-10;
/// Magnitudes the decoder keeps (length units): the range issue 3 asks the core to be accurate in
/// (scales 1e-6 ... 1e6, offsets up to 1e8) with a margin. Outside it products of coordinates
/// underflow or lose every digit of the scene, which no double algorithm can answer within
/// kAgreement; such numbers, like non-finite ones, are skipped.
constexpr double kMinMagnitude = 1e-9;
constexpr double kMaxMagnitude = 1e9;
/// A quaternion shorter than this (dimensionless) is taken as the identity rather than normalized.
constexpr double kMinQuaternionNorm = 1e-6;
/// Largest vertex and triangle counts per mesh: enough for the recursion and the hashing stage to
/// run (the core tests pairs of up to kDirectPairLimit triangle pairs directly), small enough for
/// the binary128 oracle to keep thousands of executions per second.
constexpr int kMaxVertices = 24;
constexpr int kMaxTriangles = 24;

/// Reads numbers and small integers from the input in order; past its end, zeros.
class ByteReader {
 public:
  ByteReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  std::uint8_t byte() { return pos_ < size_ ? data_[pos_++] : 0; }

  /// The next number in the input's encoding (see decodeScene), skipping values the core need
  /// not answer for (non-finite, or |x| outside [kMinMagnitude, kMaxMagnitude]).
  double number() {
    while (pos_ < size_) {
      const double x = raw();
      const double m = std::fabs(x);
      if (x == 0.0 || (std::isfinite(x) && m >= kMinMagnitude && m <= kMaxMagnitude)) return x;
    }
    return 0.0;
  }

  void setEncoding(int encoding, int exponent) {
    encoding_ = encoding;
    exponent_ = exponent;
  }

 private:
  double raw() {
    switch (encoding_) {
      case 0: {  // a float64, little-endian
        std::uint64_t bits = 0;
        for (int i = 0; i < 8; ++i) bits |= static_cast<std::uint64_t>(byte()) << (8 * i);
        double x;
        std::memcpy(&x, &bits, sizeof x);
        return x;
      }
      case 1:  // a small integer: coplanar, parallel and coincident features everywhere
        return static_cast<std::int8_t>(byte());
      case 2: {  // a fine grid: int16 / 256
        const auto lo = byte(), hi = byte();
        return static_cast<std::int16_t>(lo | hi << 8) / 256.0;
      }
      default:  // the small-integer grid scaled by 2^exponent: one scene at many scales
        return std::ldexp(static_cast<std::int8_t>(byte()), exponent_);
    }
  }

  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
  int encoding_ = 0;
  int exponent_ = 0;
};

adsd::Pose readPose(ByteReader& in) {
  adsd::Vec3 t;
  for (int i = 0; i < 3; ++i) t[i] = in.number();
  double q[4];
  for (double& c : q) c = in.number();
  Eigen::Quaterniond rotation(q[0], q[1], q[2], q[3]);
  const double n = rotation.norm();
  if (std::isfinite(n) && n >= kMinQuaternionNorm) {
    rotation.coeffs() /= n;
  } else {
    rotation = Eigen::Quaterniond::Identity();
  }
  adsd::Pose pose = adsd::Pose::Identity();
  pose.translate(t);
  pose.rotate(rotation.toRotationMatrix());
  return pose;
}

struct Scene {
  std::vector<adsd::Vec3> verticesA, verticesB;
  std::vector<adsd::TriangleIndices> trianglesA, trianglesB;
  adsd::Pose poseA, poseB;
  bool hierarchies = false;
  int modeCheck = 0;       ///< which other query mode is checked against the exact answer
  std::uint8_t modeParameter = 0;
};

/// Layout: byte 0 = flags (bits 0-1 number encoding: float64, int8, int16/256, int8 x 2^e;
/// bit 2 build hierarchies; bits 4-5 the mode check), byte 1 = the exponent e (signed, clamped to
/// +-20) and the mode check's parameter, bytes 2-5 = vertex and triangle counts of A and B, then
/// pose A and pose B (tx ty tz qw qx qy qz), the vertices of A and of B, and the triangles' vertex
/// indices as bytes (modulo the vertex count).
Scene decodeScene(const std::uint8_t* data, std::size_t size) {
  ByteReader in(data, size);
  Scene s;
  const std::uint8_t flags = in.byte();
  const std::uint8_t parameter = in.byte();
  in.setEncoding(flags & 3, std::clamp<int>(static_cast<std::int8_t>(parameter), -20, 20));
  s.hierarchies = (flags & 4) != 0;
  s.modeCheck = (flags >> 4) & 3;
  s.modeParameter = parameter;
  const int vertexCountA = 3 + in.byte() % (kMaxVertices - 2);
  const int triangleCountA = 1 + in.byte() % kMaxTriangles;
  const int vertexCountB = 3 + in.byte() % (kMaxVertices - 2);
  const int triangleCountB = 1 + in.byte() % kMaxTriangles;
  s.poseA = readPose(in);
  s.poseB = readPose(in);
  const auto readVertices = [&](int n, std::vector<adsd::Vec3>& out) {
    for (int i = 0; i < n; ++i) {
      const double x = in.number(), y = in.number(), z = in.number();
      out.emplace_back(x, y, z);
    }
  };
  readVertices(vertexCountA, s.verticesA);
  readVertices(vertexCountB, s.verticesB);
  const auto readTriangles = [&](int n, int vertices, std::vector<adsd::TriangleIndices>& out) {
    for (int i = 0; i < n; ++i) {
      adsd::TriangleIndices t;
      for (std::uint32_t& k : t) k = in.byte() % vertices;
      out.push_back(t);
    }
  };
  readTriangles(triangleCountA, vertexCountA, s.trianglesA);
  readTriangles(triangleCountB, vertexCountB, s.trianglesB);
  return s;
}

std::string describe(const adsd::DistanceResult& r) {
  std::ostringstream out;
  out.precision(17);
  out << "distance " << r.distance << " [" << r.lower << ", " << r.upper << "] status " << adsd::toString(r.status)
      << " witnesses (" << r.witnessA.transpose() << ") (" << r.witnessB.transpose() << ") triangles " << r.triangleA
      << ' ' << r.triangleB;
  return out.str();
}

std::string number(double x) {
  std::ostringstream out;
  out.precision(17);
  out << x;
  return out.str();
}

void requireNoNan(const adsd::DistanceResult& r, const char* which) {
  if (std::isnan(r.distance) || std::isnan(r.lower) || std::isnan(r.upper) || !r.witnessA.allFinite() ||
      !r.witnessB.allFinite()) {
    violation(std::string(which) + ": NaN or infinite witness in " + describe(r));
  }
}

/// The counters say the query ended the way it is documented to.
void requireTerminated(const adsd::DistanceResult& r, const char* which) {
  if (r.counters.gjkMaxIterations > adsd::tolerance::kGjkMaxIterations) {
    violation(std::string(which) + ": a GJK run took " + std::to_string(r.counters.gjkMaxIterations) +
              " iterations, beyond the cap");
  }
}

/// Distance from \p p (world frame) to triangle \p t of \p mesh placed by \p pose.
double distanceToTriangle(const adsd::Vec3& p, const adsd::Mesh& mesh, const adsd::Pose& pose, std::int64_t t) {
  const auto corners = adsd::oracle::posedTriangle(mesh, pose, static_cast<std::size_t>(t));
  return static_cast<double>(
      adsd::oracle::pointTriangleDistance(adsd::oracle::Quad3(p), corners[0], corners[1], corners[2]));
}

void checkExact(const adsd::DistanceResult& r, const adsd::Mesh& a, const adsd::Pose& pa, const adsd::Mesh& b,
                const adsd::Pose& pb, double tolerance, const char* which) {
  requireNoNan(r, which);
  requireTerminated(r, which);
  if (r.status != adsd::DistanceStatus::exact || !std::isfinite(r.distance) || !(r.distance >= 0) ||
      r.lower != r.distance || r.upper != r.distance) {
    violation(std::string(which) + ": exact query without an exact finite answer: " + describe(r));
  }
  if (std::fabs((r.witnessA - r.witnessB).norm() - r.distance) > tolerance) {
    violation(std::string(which) + ": witnesses do not realize the distance: " + describe(r));
  }
  if (r.triangleA < 0 || r.triangleA >= static_cast<std::int64_t>(a.triangleCount()) || r.triangleB < 0 ||
      r.triangleB >= static_cast<std::int64_t>(b.triangleCount())) {
    violation(std::string(which) + ": witness triangles out of range: " + describe(r));
  }
  if (distanceToTriangle(r.witnessA, a, pa, r.triangleA) > tolerance ||
      distanceToTriangle(r.witnessB, b, pb, r.triangleB) > tolerance) {
    violation(std::string(which) + ": a witness is off its triangle: " + describe(r));
  }
}

/// The query in another mode must agree with the exact distance \p d.
void checkOtherMode(const Scene& s, const adsd::Mesh& a, const adsd::Mesh& b, double d, double scale, double tolerance,
                    adsd::DistanceScratch& scratch) {
  // A factor in [0, 2] of the exact distance, or of the scale when the meshes touch.
  const double factor = (s.modeParameter % 9) / 4.0;
  const double reference = d > 0 ? d : scale;
  adsd::DistanceOptions options;
  switch (s.modeCheck) {
    case 1:
      options = adsd::DistanceOptions::aboveThreshold(factor * reference);
      break;
    case 2:
      options = adsd::DistanceOptions::cappedAt(std::max(factor, 0.25) * reference);
      break;
    case 3:
      options = adsd::DistanceOptions::withTolerance(factor * reference * 0.1, (s.modeParameter >> 4) / 32.0);
      break;
    default:
      return;
  }
  if (!(reference > 0)) return;  // a scene of one point: no positive threshold or cap to ask about
  const adsd::DistanceResult r = adsd::distance(a, s.poseA, b, s.poseB, options, scratch);
  requireNoNan(r, "other mode");
  requireTerminated(r, "other mode");
  const std::string context = " (exact distance " + number(d) + "): " + describe(r);
  switch (r.status) {
    case adsd::DistanceStatus::aboveThreshold:
      if (options.mode != adsd::QueryMode::threshold || !(d > options.threshold - tolerance) ||
          !(r.lower >= options.threshold)) {
        violation("aboveThreshold " + number(options.threshold) + " wrong" + context);
      }
      break;
    case adsd::DistanceStatus::withinThreshold:
      if (options.mode != adsd::QueryMode::threshold || !(d <= options.threshold + tolerance) ||
          !(r.distance <= options.threshold + tolerance) || !(r.distance >= d - tolerance)) {
        violation("withinThreshold " + number(options.threshold) + " wrong" + context);
      }
      break;
    case adsd::DistanceStatus::beyondCap:
      if (options.mode != adsd::QueryMode::cap || !(d >= options.cap - tolerance)) {
        violation("beyondCap " + number(options.cap) + " wrong" + context);
      }
      break;
    case adsd::DistanceStatus::withinTolerance:
      if (options.mode != adsd::QueryMode::tolerance || !(r.lower <= d + tolerance) || !(r.upper >= d - tolerance) ||
          !(r.upper - r.lower <= std::max(options.absTolerance, options.relTolerance * r.upper) + tolerance) ||
          !(r.distance >= d - tolerance)) {
        violation("tolerance interval wrong" + context);
      }
      break;
    case adsd::DistanceStatus::exact:
      if (std::fabs(r.distance - d) > tolerance) violation("exact status in another mode disagrees" + context);
      break;
  }
}

/// Largest |coordinate| any of the meshes has in the world frame or in the other mesh's frame
/// (where the core may compute): |t| of either pose twice, plus sqrt(3) times each mesh's largest
/// coordinate twice, bounds all of them.
double coordinateScale(const adsd::Mesh& a, const adsd::Pose& pa, const adsd::Mesh& b, const adsd::Pose& pb) {
  const double translations = std::max(pa.translation().norm(), pb.translation().norm());
  const double extents = std::max(a.maxAbsCoordinate(), b.maxAbsCoordinate()) * std::sqrt(3.0);
  return 2 * translations + 2 * extents;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static adsd::DistanceScratch warmScratch;  // reused across inputs, as a planner thread reuses it
  Scene s = decodeScene(data, size);
  try {
    adsd::Mesh a(std::move(s.verticesA), std::move(s.trianglesA), "A");
    adsd::Mesh b(std::move(s.verticesB), std::move(s.trianglesB), "B");
    if (s.hierarchies) {
      a.buildHierarchy();
      b.buildHierarchy();
    }
    const double scale = coordinateScale(a, s.poseA, b, s.poseB);
    const double tolerance = kAgreement * scale;

    const adsd::DistanceResult ab = adsd::distance(a, s.poseA, b, s.poseB, {}, warmScratch);
    checkExact(ab, a, s.poseA, b, s.poseB, tolerance, "A,B");
    adsd::DistanceScratch fresh;
    const adsd::DistanceResult ba = adsd::distance(b, s.poseB, a, s.poseA, {}, fresh);
    checkExact(ba, b, s.poseB, a, s.poseA, tolerance, "B,A");
    if (std::fabs(ab.distance - ba.distance) > tolerance) {
      violation("asymmetric: A,B gives " + number(ab.distance) + ", B,A gives " + number(ba.distance) +
                " (tolerance " + number(tolerance) + ")");
    }
    const adsd::oracle::MeshPairDistance oracle = adsd::oracle::meshDistance(a, s.poseA, b, s.poseB);
    if (std::fabs(ab.distance - oracle.value) > tolerance) {
      violation("disagrees with the oracle: " + number(ab.distance) + " vs " + number(oracle.value) +
                " (tolerance " + number(tolerance) + ", oracle pair " + std::to_string(oracle.triangleA) + ' ' +
                std::to_string(oracle.triangleB) + "): " + describe(ab));
    }
    checkOtherMode(s, a, b, ab.distance, scale, tolerance, warmScratch);
  } catch (const std::exception& e) {
    violation(std::string("exception on valid input: ") + e.what());
  }
  return 0;
}
