#include <array>
#include <cstdint>

#include "adsd/problem_scenes.h"
#include "scene_parts.h"

namespace adsd::shapes {

namespace {

/// A fixed linear congruential generator (Knuth's MMIX constants): the maze must be the same on
/// every machine, which std::uniform_int_distribution does not promise.
class MazeRandom {
 public:
  explicit MazeRandom(std::uint64_t seed) : state_(seed) {}
  std::uint32_t below(std::uint32_t n) {
    state_ = state_ * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<std::uint32_t>((state_ >> 33) % n);
  }

 private:
  std::uint64_t state_;
};

}  // namespace

// An 8 × 8 perfect maze of 1.2 m cells (walls 0.1 m thick), carved by a depth-first search from
// cell (0, 0) with a fixed seed; the robot (0.6 × 0.3) goes from cell (0, 0) to cell (7, 7).
ProblemScene mazeScene() {
  constexpr int n = 8;
  constexpr double cell = 1.2, wall = 0.1, halfHeight = 1.0, origin = -0.5 * n * cell;
  // openEast[i][j]: passage between (i, j) and (i + 1, j); openNorth: between (i, j) and (i, j + 1).
  std::array<std::array<bool, n>, n> openEast{}, openNorth{}, visited{};
  MazeRandom random(20240611);
  std::vector<std::array<int, 2>> stack = {{0, 0}};
  visited[0][0] = true;
  while (!stack.empty()) {
    const auto [i, j] = stack.back();
    std::vector<std::array<int, 2>> next;
    const int di[] = {1, -1, 0, 0}, dj[] = {0, 0, 1, -1};
    for (int k = 0; k < 4; ++k) {
      const int a = i + di[k], b = j + dj[k];
      if (a >= 0 && a < n && b >= 0 && b < n && !visited[a][b]) next.push_back({a, b});
    }
    if (next.empty()) {
      stack.pop_back();
      continue;
    }
    const auto [a, b] = next[random.below(static_cast<std::uint32_t>(next.size()))];
    if (a != i) openEast[std::min(a, i)][j] = true;
    if (b != j) openNorth[i][std::min(b, j)] = true;
    visited[a][b] = true;
    stack.push_back({a, b});
  }

  SceneParts parts;
  const auto slab = [&](double x0, double y0, double x1, double y1) {
    parts.addBox(Vec3(origin + x0 - wall / 2, origin + y0 - wall / 2, -halfHeight),
                 Vec3(origin + x1 + wall / 2, origin + y1 + wall / 2, halfHeight));
  };
  slab(0, 0, n * cell, 0);
  slab(0, n * cell, n * cell, n * cell);
  slab(0, 0, 0, n * cell);
  slab(n * cell, 0, n * cell, n * cell);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      if (i + 1 < n && !openEast[i][j]) slab((i + 1) * cell, j * cell, (i + 1) * cell, (j + 1) * cell);
      if (j + 1 < n && !openNorth[i][j]) slab(i * cell, (j + 1) * cell, (i + 1) * cell, (j + 1) * cell);
    }
  }
  return {"maze", {centredOnVertexMean(box(Vec3(0.3, 0.15, 0.25)))}, parts.merged()};
}

}  // namespace adsd::shapes
