// The distance query alone, from a project that linked adsd::core and nothing else: two unit
// tetrahedra, the second 2 along x, whose nearest features are a face at x = 1 and a corner at
// x = 2. Exit 0 only when the installed library answers 1.
#include <cmath>
#include <cstdio>
#include <vector>

#include <adsd/distance.h>

int main() {
  const std::vector<adsd::Vec3> vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const std::vector<adsd::TriangleIndices> triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  const adsd::Mesh a(vertices, triangles, "a"), b(vertices, triangles, "b");
  adsd::Pose poseB = adsd::Pose::Identity();
  poseB.translation() = adsd::Vec3(2, 0, 0);
  const adsd::DistanceResult r = adsd::distance(a, adsd::Pose::Identity(), b, poseB);
  std::printf("distance %.17g\n", r.distance);
  return std::abs(r.distance - 1.0) < 1e-12 ? 0 : 1;
}
