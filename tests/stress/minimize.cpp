#include "minimize.h"

#include <algorithm>
#include <optional>
#include <vector>

#include "properties.h"

namespace adsd::stress {

namespace {

/// The mesh without triangles [begin, end), its vertices compacted in first-use order; none if
/// that would leave no triangle.
std::optional<Mesh> without(const Mesh& mesh, std::size_t begin, std::size_t end) {
  if (end - begin >= mesh.triangleCount()) return std::nullopt;
  std::vector<std::int64_t> newIndex(mesh.vertices().size(), -1);
  std::vector<Vec3> vertices;
  std::vector<TriangleIndices> triangles;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    if (t >= begin && t < end) continue;
    TriangleIndices kept;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = mesh.triangles()[t][k];
      if (newIndex[v] < 0) {
        newIndex[v] = static_cast<std::int64_t>(vertices.size());
        vertices.push_back(mesh.vertices()[v]);
      }
      kept[k] = static_cast<std::uint32_t>(newIndex[v]);
    }
    triangles.push_back(kept);
  }
  return Mesh(std::move(vertices), std::move(triangles), mesh.name());
}

}  // namespace

StressCase minimizeFailure(const StressCase& failing, const std::string& check, DistanceScratch& scratch, int maxChecks) {
  StressCase best = failing;
  int checks = 0;
  auto stillFails = [&](const StressCase& c) {
    ++checks;
    const CaseReport report = checkCase(c, scratch);
    auto has = [&](const std::string& label) {
      return std::any_of(report.failures.begin(), report.failures.end(), [&](const Failure& f) { return f.check == label; });
    };
    // A cut that removes the crossing triangles of a penetrating case makes the case a different
    // one (the claim no longer holds): not a reproduction.
    return has(check) && !has(kNotPenetrating);
  };
  bool progress = true;
  while (progress && checks < maxChecks) {
    progress = false;
    for (int side = 0; side < 2 && checks < maxChecks; ++side) {
      for (std::size_t chunk = std::max<std::size_t>(1, (side ? best.b : best.a).triangleCount() / 2); chunk >= 1 && checks < maxChecks;
           chunk /= 2) {
        for (std::size_t begin = 0; begin < (side ? best.b : best.a).triangleCount() && checks < maxChecks;) {
          const Mesh& mesh = side ? best.b : best.a;
          const std::optional<Mesh> smaller = without(mesh, begin, std::min(begin + chunk, mesh.triangleCount()));
          if (!smaller) {
            begin += chunk;
            continue;
          }
          StressCase candidate = best;
          (side ? candidate.b : candidate.a) = *smaller;
          if (stillFails(candidate)) {
            best = std::move(candidate);
            progress = true;
          } else {
            begin += chunk;
          }
        }
        if (chunk == 1) break;
      }
    }
  }
  return best;
}

}  // namespace adsd::stress
