// Issue 16: the stress suite's numerics families written to files in every format adsd::io reads
// without assimp, read back through adsd::io::loadMesh and through the `adsd distance` program,
// and checked against the binary128 oracle.
//
// Formats in double (ASCII with 17 significant digits: OBJ, OFF, ASCII PLY, ASCII STL; binary PLY
// with double properties, both byte orders): every corner must come back bit for bit, and the
// distance must be within the stress suite's tolerance (1e-10 x diagonal + the working
// magnitude's roundoff, properties.h) of the oracle on the meshes as generated.
// Formats in float (binary STL, binary PLY with float properties): every corner must come back as
// the float nearest the generated one, the distance within the same tolerance of the oracle on
// those float meshes, and that oracle within the float rounding of the geometry, 4 x 2^-24 x the
// largest coordinate, of the oracle on the generated meshes (each coordinate moves by at most
// 2^-24 of itself, a point by sqrt(3) x that, a distance by twice a point).

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "adsd/distance.h"
#include "adsd/io/load_mesh.h"
#include "families.h"
#include "properties.h"

namespace adsd::stress {
namespace {

// ---- writers -------------------------------------------------------------------------------

std::string exact17(double x) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

std::string obj(const Mesh& m) {
  std::string s = "# written by file_formats_test\n";
  for (const Vec3& v : m.vertices()) s += "v " + exact17(v.x()) + " " + exact17(v.y()) + " " + exact17(v.z()) + "\n";
  for (const TriangleIndices& t : m.triangles()) {
    s += "f " + std::to_string(t[0] + 1) + " " + std::to_string(t[1] + 1) + " " + std::to_string(t[2] + 1) + "\n";
  }
  return s;
}

std::string off(const Mesh& m) {
  std::string s = "OFF\n" + std::to_string(m.vertices().size()) + " " + std::to_string(m.triangleCount()) + " 0\n";
  for (const Vec3& v : m.vertices()) s += exact17(v.x()) + " " + exact17(v.y()) + " " + exact17(v.z()) + "\n";
  for (const TriangleIndices& t : m.triangles()) {
    s += "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) + "\n";
  }
  return s;
}

std::string plyHeader(const Mesh& m, const char* format, const char* type) {
  const std::string t(type);
  return std::string("ply\nformat ") + format + " 1.0\nelement vertex " + std::to_string(m.vertices().size()) +
         "\nproperty " + t + " x\nproperty " + t + " y\nproperty " + t + " z\nelement face " +
         std::to_string(m.triangleCount()) + "\nproperty list uchar int vertex_indices\nend_header\n";
}

std::string plyAscii(const Mesh& m) {
  std::string s = plyHeader(m, "ascii", "double");
  for (const Vec3& v : m.vertices()) s += exact17(v.x()) + " " + exact17(v.y()) + " " + exact17(v.z()) + "\n";
  for (const TriangleIndices& t : m.triangles()) {
    s += "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) + "\n";
  }
  return s;
}

template <typename Scalar>
void putScalar(std::string& s, Scalar value, bool little) {
  unsigned char bytes[sizeof(Scalar)];
  std::memcpy(bytes, &value, sizeof bytes);  // the host is little-endian (x86-64, as CI)
  for (std::size_t i = 0; i < sizeof bytes; ++i) s.push_back(static_cast<char>(bytes[little ? i : sizeof bytes - 1 - i]));
}

template <typename Scalar>
std::string plyBinary(const Mesh& m, bool little) {
  std::string s = plyHeader(m, little ? "binary_little_endian" : "binary_big_endian",
                            sizeof(Scalar) == 8 ? "double" : "float");
  for (const Vec3& v : m.vertices()) {
    for (int k = 0; k < 3; ++k) putScalar(s, static_cast<Scalar>(v(k)), little);
  }
  for (const TriangleIndices& t : m.triangles()) {
    s.push_back(3);
    for (const std::uint32_t i : t) putScalar(s, static_cast<std::int32_t>(i), little);
  }
  return s;
}

std::string stlAscii(const Mesh& m) {
  std::string s = "solid stress\n";
  for (std::size_t t = 0; t < m.triangleCount(); ++t) {
    s += "facet normal 0 0 0\n outer loop\n";
    for (int k = 0; k < 3; ++k) {
      const Vec3& v = m.corner(t, k);
      s += "  vertex " + exact17(v.x()) + " " + exact17(v.y()) + " " + exact17(v.z()) + "\n";
    }
    s += " endloop\nendfacet\n";
  }
  return s + "endsolid stress\n";
}

std::string stlBinary(const Mesh& m) {
  std::string s(80, ' ');
  putScalar(s, static_cast<std::uint32_t>(m.triangleCount()), true);
  for (std::size_t t = 0; t < m.triangleCount(); ++t) {
    for (int k = 0; k < 3; ++k) putScalar(s, 0.0f, true);
    for (int k = 0; k < 3; ++k) {
      for (int axis = 0; axis < 3; ++axis) putScalar(s, static_cast<float>(m.corner(t, k)(axis)), true);
    }
    s.append(2, '\0');
  }
  return s;
}

struct Format {
  const char* name;
  const char* extension;
  bool isFloat;  ///< stores float32: the file's own precision
  std::string (*write)(const Mesh&);
};

const std::vector<Format>& formats() {
  static const std::vector<Format> all = {
      {"obj", ".obj", false, obj},
      {"off", ".off", false, off},
      {"ply-ascii", ".ply", false, plyAscii},
      {"ply-binary-le-double", ".ply", false, [](const Mesh& m) { return plyBinary<double>(m, true); }},
      {"ply-binary-be-double", ".ply", false, [](const Mesh& m) { return plyBinary<double>(m, false); }},
      {"stl-ascii", ".stl", false, stlAscii},
      {"ply-binary-le-float", ".ply", true, [](const Mesh& m) { return plyBinary<float>(m, true); }},
      {"stl-binary", ".stl", true, stlBinary},
  };
  return all;
}

// The numerics families of the stress suite: tiny scales (small-triangles, tiny-next-to-large,
// tiny-features), offsets up to 1e8 (near-contact-far, coplanar-touching-far, offset-vertices,
// offset-poses), parallel and coplanar (cad-parallel-edges, coplanar-touching-far, tilted-faces,
// boxes-near), slivers, degenerate triangles (degenerate-near, mesh/degenerate).
const std::vector<std::string> kFamilies = {
    "tri/cad-parallel-edges", "tri/small-triangles",        "tri/tiny-next-to-large", "tri/near-contact-far",
    "tri/coplanar-touching-far", "tri/degenerate-near",     "tri/slivers",            "tri/tilted-faces",
    "mesh/boxes-near",        "mesh/offset-vertices",       "mesh/offset-poses",      "mesh/degenerate",
    "mesh/tiny-features"};
constexpr std::uint64_t kSeed = 16;
constexpr std::uint64_t kCasesPerFamily = 24;     // through loadMesh, every format
constexpr std::uint64_t kProgramCasesPerFamily = 3;  // through `adsd distance`, every format

/// A fresh directory of the test's own, removed afterwards.
class Scratch {
 public:
  Scratch() {
    std::random_device entropy;
    root_ = std::filesystem::temp_directory_path() /
            ("adsd-formats-" + std::to_string(entropy()) + "-" + std::to_string(entropy()));
    std::filesystem::create_directories(root_);
  }
  ~Scratch() {
    std::error_code ignored;
    std::filesystem::remove_all(root_, ignored);
  }
  std::string write(const std::string& name, const std::string& bytes) const {
    const std::string path = (root_ / name).string();
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
  }

 private:
  std::filesystem::path root_;
};

/// The mesh with every coordinate rounded to float, as a float format stores it.
Mesh roundedToFloat(const Mesh& m) {
  std::vector<Vec3> vertices = m.vertices();
  for (Vec3& v : vertices) {
    for (int k = 0; k < 3; ++k) {
      // Through a volatile: GCC 12.2's SLP vectorizer at -O2/-O3 drops the double -> float ->
      // double round trip of a loop like this one (seen here: -31566943.199 came back unrounded).
      volatile float stored = static_cast<float>(v(k));
      v(k) = stored;
    }
  }
  return Mesh(std::move(vertices), m.triangles(), m.name());
}

/// \p m less the triangles a loader drops as adding no point (load_mesh.h): a repeat of an
/// earlier triangle's three corners in any order, and a triangle on a single point that is a
/// corner of a triangle on more than one. Corners compare by their coordinates' bits, as the
/// loader shares vertices (float formats round distinct vertices of the generated mesh to one).
Mesh withoutRepeatedTriangles(const Mesh& m) {
  using Bits = std::array<std::uint64_t, 3>;
  auto bits = [&](std::size_t t, int k) {
    Bits b;
    std::memcpy(b.data(), m.corner(t, k).data(), sizeof b);
    return b;
  };
  std::set<std::array<Bits, 3>> seen;
  std::set<Bits> cornersOfProperTriangles;
  std::vector<std::size_t> kept;
  for (std::size_t t = 0; t < m.triangleCount(); ++t) {
    std::array<Bits, 3> corners = {bits(t, 0), bits(t, 1), bits(t, 2)};
    std::sort(corners.begin(), corners.end());
    if (!seen.insert(corners).second) continue;
    kept.push_back(t);
    if (corners[0] != corners[2]) cornersOfProperTriangles.insert(corners.begin(), corners.end());
  }
  std::vector<TriangleIndices> triangles;
  for (const std::size_t t : kept) {
    const Bits first = bits(t, 0);
    const bool onePoint = first == bits(t, 1) && first == bits(t, 2);
    if (!(onePoint && cornersOfProperTriangles.count(first))) triangles.push_back(m.triangles()[t]);
  }
  return Mesh(m.vertices(), triangles, m.name());
}

/// Corners of every triangle equal bit for bit (the loader may share or drop vertices, never move
/// one or reorder triangles). Returns how many corners differ.
int cornerMismatches(const Mesh& want, const Mesh& got) {
  if (want.triangleCount() != got.triangleCount()) return 3 * static_cast<int>(want.triangleCount()) + 1;
  int mismatches = 0;
  for (std::size_t t = 0; t < want.triangleCount(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const bool differs = std::memcmp(want.corner(t, k).data(), got.corner(t, k).data(), 24) != 0;
      if (differs && mismatches == 0) {
        ADD_FAILURE() << "triangle " << t << " corner " << k << ": wrote " << exact17(want.corner(t, k).x()) << " "
                      << exact17(want.corner(t, k).y()) << " " << exact17(want.corner(t, k).z()) << ", read "
                      << exact17(got.corner(t, k).x()) << " " << exact17(got.corner(t, k).y()) << " "
                      << exact17(got.corner(t, k).z());
      }
      mismatches += differs;
    }
  }
  return mismatches;
}

/// `adsd distance A B --csv`: the distance of its one result line.
double programDistance(const std::string& a, const std::string& b) {
  const std::string command = std::string(ADSD_PROGRAM) + " distance '" + a + "' '" + b + "' --csv 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return std::nan("");
  std::string output;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) output += buffer;
  const int status = pclose(pipe);
  const std::size_t row = output.find('\n');
  if (status != 0 || row == std::string::npos) {
    ADD_FAILURE() << command << " failed (" << status << "): " << output;
    return std::nan("");
  }
  double value = std::nan("");
  const char* begin = output.data() + row + 1;
  std::from_chars(begin, output.data() + output.size(), value);
  return value;
}

struct Tally {
  int cases = 0, failures = 0;
};

TEST(FileFormats, NumericsFamiliesThroughEveryFormatAgreeWithTheOracle) {
  Scratch dir;
  std::map<std::string, Tally> library, program;
  for (const std::string& name : kFamilies) {
    const Family* family = findFamily(name);
    ASSERT_NE(family, nullptr) << name;
    for (std::uint64_t i = 0; i < kCasesPerFamily; ++i) {
      const StressCase c = generateCase(*family, kSeed, i);
      const Truth truth = consultOracle(c);
      StressCase rounded{c.family, c.seed, c.index, c.scale, c.variant, c.penetrating,
                         roundedToFloat(c.a), roundedToFloat(c.b), c.poseA, c.poseB};
      const Truth floatTruth = consultOracle(rounded);
      // The float geometry's own distance is within float rounding of the generated one.
      const double floatRounding = 4.0 * std::ldexp(1.0, -24) * worldMagnitude(c);
      EXPECT_LE(std::abs(floatTruth.distance - truth.distance), floatRounding) << caseHeadline(c);

      const bool identityPoses = c.poseA.matrix() == Pose::Identity().matrix() &&
                                 c.poseB.matrix() == Pose::Identity().matrix();
      for (const Format& format : formats()) {
        const StressCase& stored = format.isFloat ? rounded : c;
        const Truth& want = format.isFloat ? floatTruth : truth;
        const std::string label = std::string(format.name) + " " + caseHeadline(c);
        const std::string a = dir.write(std::string("a") + format.extension, format.write(c.a));
        const std::string b = dir.write(std::string("b") + format.extension, format.write(c.b));
        Tally& tally = library[format.name];
        ++tally.cases;
        const Mesh loadedA = io::loadMesh(a), loadedB = io::loadMesh(b);
        const int mismatches = cornerMismatches(withoutRepeatedTriangles(stored.a), loadedA) +
                               cornerMismatches(withoutRepeatedTriangles(stored.b), loadedB);
        EXPECT_EQ(mismatches, 0) << label << ": corners not read back bit for bit";
        const DistanceResult r = distance(loadedA, c.poseA, loadedB, c.poseB);
        std::vector<Failure> failures;
        checkExact(want, r, c.penetrating, "loadMesh exact", failures);
        for (const Failure& f : failures) ADD_FAILURE() << label << ": " << f.check << ": " << f.detail;
        tally.failures += mismatches > 0 || !failures.empty();

        if (i < kProgramCasesPerFamily && identityPoses) {
          Tally& run = program[format.name];
          ++run.cases;
          const double d = programDistance(a, b);
          const bool ok = std::abs(d - want.distance) <= want.tolerance && (d == 0.0) == (r.distance == 0.0);
          EXPECT_TRUE(ok) << label << ": adsd distance printed " << d << ", oracle " << want.distance << " +- "
                          << want.tolerance;
          run.failures += !ok;
        }
      }
    }
  }
  for (const Format& format : formats()) {
    std::printf("%-22s loadMesh: %3d cases, %d failing; adsd distance: %3d cases, %d failing\n", format.name,
                library[format.name].cases, library[format.name].failures, program[format.name].cases,
                program[format.name].failures);
  }
}

}  // namespace
}  // namespace adsd::stress
