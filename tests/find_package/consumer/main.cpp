// The README's library example, built against the installed package: two unit cubes 3 apart
// (centre to centre). Exit 0 only when the installed library answers distance 1, witnesses on the
// facing faces, and "above the threshold" for 1 cm.
#include <cmath>
#include <cstdio>
#include <vector>

#include <adsd/distance.h>
#include <adsd/io/pose_file.h>

int main() {
  std::vector<adsd::Vec3> verticesA;
  for (int i = 0; i < 8; ++i) verticesA.emplace_back((i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1);
  const std::vector<adsd::TriangleIndices> trianglesA = {{0, 1, 3}, {0, 3, 2}, {4, 6, 7}, {4, 7, 5},
                                                         {0, 4, 5}, {0, 5, 1}, {2, 3, 7}, {2, 7, 6},
                                                         {0, 2, 6}, {0, 6, 4}, {1, 5, 7}, {1, 7, 3}};
  const std::vector<adsd::Vec3>& verticesB = verticesA;
  const std::vector<adsd::TriangleIndices>& trianglesB = trianglesA;
  const adsd::Pose poseA = adsd::Pose::Identity();
  adsd::Pose poseB = adsd::Pose::Identity();
  poseB.translation() = adsd::Vec3(3, 0, 0);

  // README: the library example (from here to "end of the README example").
  adsd::Mesh a(verticesA, trianglesA, "a"), b(verticesB, trianglesB, "b");
  a.buildHierarchy(), b.buildHierarchy();  // optional: rigid meshes queried many times keep a tree
  adsd::DistanceScratch scratch;           // working memory, one per thread
  const adsd::DistanceResult r = adsd::distance(a, poseA, b, poseB, adsd::DistanceOptions::exactDistance(), scratch);
  // r.distance, r.witnessA, r.witnessB (world frame), r.lower <= r.distance <= r.upper, r.counters

  // The validity question: is the distance above 1 cm? Stops at the first proof either way.
  const adsd::DistanceResult v = adsd::distance(a, poseA, b, poseB, adsd::DistanceOptions::aboveThreshold(0.01), scratch);
  const bool free = v.status == adsd::DistanceStatus::aboveThreshold;
  // Also: DistanceOptions::withTolerance(abs, rel) and DistanceOptions::cappedAt(D).
  // end of the README example

  std::printf("distance %.17g, witnesses x %.17g and %.17g, free %d\n", r.distance, r.witnessA.x(), r.witnessB.x(),
              free);
  const bool right = std::abs(r.distance - 1.0) < 1e-12 && std::abs(r.witnessA.x() - 1.0) < 1e-12 &&
                     std::abs(r.witnessB.x() - 2.0) < 1e-12 && free;
  return right ? 0 : 1;
}
