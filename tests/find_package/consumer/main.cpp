// Two unit cubes 3 apart (centre to centre): distance 1. Exit 0 only when the installed library
// answers that.
#include <cmath>
#include <cstdio>

#include <adsd/distance.h>
#include <adsd/io/pose_file.h>

int main() {
  std::vector<adsd::Vec3> v;
  for (int i = 0; i < 8; ++i) v.emplace_back((i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1);
  const std::vector<adsd::TriangleIndices> t = {{0, 1, 3}, {0, 3, 2}, {4, 6, 7}, {4, 7, 5}, {0, 4, 5}, {0, 5, 1},
                                                {2, 3, 7}, {2, 7, 6}, {0, 2, 6}, {0, 6, 4}, {1, 5, 7}, {1, 7, 3}};
  const adsd::Mesh cube(v, t, "cube");
  adsd::Pose apart = adsd::Pose::Identity();
  apart.translation() = adsd::Vec3(3, 0, 0);
  const adsd::DistanceResult r = adsd::distance(cube, adsd::Pose::Identity(), cube, apart);
  std::printf("distance %.17g\n", r.distance);
  return std::abs(r.distance - 1.0) < 1e-12 ? 0 : 1;
}
