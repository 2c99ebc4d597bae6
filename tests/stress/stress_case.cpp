#include "stress_case.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "oracle.h"

namespace adsd::stress {

double sceneDiagonal(const StressCase& c) { return oracle::sceneDiagonal(c.a, c.poseA, c.b, c.poseB); }

double worldMagnitude(const StressCase& c) {
  double m = 0.0;
  for (const Vec3& v : c.a.vertices()) m = std::max({m, (c.poseA * v).cwiseAbs().maxCoeff(), v.cwiseAbs().maxCoeff()});
  for (const Vec3& v : c.b.vertices()) m = std::max({m, (c.poseB * v).cwiseAbs().maxCoeff(), v.cwiseAbs().maxCoeff()});
  return m;
}

std::string exactNumber(double x) {
  char buffer[80];
  std::snprintf(buffer, sizeof buffer, "%a (%.17g)", x, x);
  return buffer;
}

namespace {

std::string hex(double x) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%a", x);
  return buffer;
}

std::string decimal(double x) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

void meshAsCode(std::ostringstream& out, const char* name, const Mesh& mesh) {
  out << "  const Mesh " << name << "(\n      {\n";
  for (const Vec3& v : mesh.vertices()) {
    out << "          Vec3(" << hex(v.x()) << ", " << hex(v.y()) << ", " << hex(v.z()) << "),  // " << decimal(v.x())
        << ", " << decimal(v.y()) << ", " << decimal(v.z()) << "\n";
  }
  out << "      },\n      {";
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const TriangleIndices& i = mesh.triangles()[t];
    out << (t % 8 == 0 ? "\n          " : " ") << "{" << i[0] << ", " << i[1] << ", " << i[2] << "},";
  }
  out << "\n      });\n";
}

void poseAsCode(std::ostringstream& out, const char* name, const Pose& pose) {
  // The 3 x 4 matrix as it is stored: a quaternion would not reproduce the doubles exactly.
  out << "  const Pose " << name << " = poseFromRows({\n";
  for (int r = 0; r < 3; ++r) {
    out << "      " << hex(pose.matrix()(r, 0)) << ", " << hex(pose.matrix()(r, 1)) << ", " << hex(pose.matrix()(r, 2))
        << ", " << hex(pose.matrix()(r, 3)) << ",  // " << decimal(pose.matrix()(r, 0)) << " "
        << decimal(pose.matrix()(r, 1)) << " " << decimal(pose.matrix()(r, 2)) << " " << decimal(pose.matrix()(r, 3))
        << "\n";
  }
  out << "  });\n";
}

}  // namespace

Pose poseFromRows(const std::array<double, 12>& rows) {
  Pose pose = Pose::Identity();
  for (int r = 0; r < 3; ++r) {
    for (int k = 0; k < 4; ++k) pose.matrix()(r, k) = rows[4 * r + k];
  }
  return pose;
}

std::string caseHeadline(const StressCase& c) {
  std::ostringstream out;
  out << c.family << " seed " << c.seed << " case " << c.index;
  if (!c.variant.empty()) out << " (" << c.variant << ")";
  if (c.penetrating) out << ", penetrating";
  out << ", scale " << decimal(c.scale) << ", A " << c.a.triangleCount() << " triangles, B " << c.b.triangleCount()
      << " triangles";
  return out.str();
}

std::string caseAsCode(const StressCase& c) {
  std::ostringstream out;
  out << "  // " << caseHeadline(c) << "\n";
  meshAsCode(out, "a", c.a);
  meshAsCode(out, "b", c.b);
  poseAsCode(out, "poseA", c.poseA);
  poseAsCode(out, "poseB", c.poseB);
  return out.str();
}

}  // namespace adsd::stress
