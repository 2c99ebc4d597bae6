#include "polygon_soup.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cstring>
#include <unordered_map>
#include <utility>

#include "adsd/error.h"
#include "adsd/tolerances.h"
#include "polygon_triangulation.h"

namespace adsd::io::detail {

namespace {

/// Coordinates compared by their bits: +0 and -0 stay apart (harmless: both are kept), and no two
/// points that differ in any bit are ever merged, which an epsilon would do.
struct PointBits {
  std::uint64_t x, y, z;
  bool operator==(const PointBits& o) const { return x == o.x && y == o.y && z == o.z; }
};
struct PointBitsHash {
  std::size_t operator()(const PointBits& p) const {
    std::uint64_t h = p.x * 0x9E3779B97F4A7C15ull;
    h ^= (p.y + 0x7F4A7C159E3779B9ull + (h << 6) + (h >> 2)) * 0xBF58476D1CE4E5B9ull;
    h ^= (p.z + 0x94D049BB133111EBull + (h << 6) + (h >> 2)) * 0x94D049BB133111EBull;
    return static_cast<std::size_t>(h ^ (h >> 31));
  }
};

PointBits bitsOf(const Vec3& p) {
  PointBits b;
  std::memcpy(&b.x, &p.x(), 8);
  std::memcpy(&b.y, &p.y(), 8);
  std::memcpy(&b.z, &p.z(), 8);
  return b;
}

/// A triangle's vertex indices in increasing order: the same three vertices in any order give the
/// same key.
struct SortedCorners {
  std::uint32_t low, middle, high;
  bool operator==(const SortedCorners& o) const { return low == o.low && middle == o.middle && high == o.high; }
  bool operator<(const SortedCorners& o) const {
    return low != o.low ? low < o.low : middle != o.middle ? middle < o.middle : high < o.high;
  }
};

SortedCorners sortedCorners(const TriangleIndices& t) {
  std::uint32_t a = t[0], b = t[1], c = t[2];
  if (a > b) std::swap(a, b);
  if (b > c) std::swap(b, c);
  if (a > b) std::swap(a, b);
  return {a, b, c};
}

std::string shortest(double x) {
  char text[32];
  return std::string(text, std::to_chars(text, text + sizeof text, x).ptr);
}

}  // namespace

void requireRepresentablePoints(const PolygonSoup& soup, const std::string& path) {
  for (std::size_t i = 0; i < soup.points.size(); ++i) {
    const Vec3& p = soup.points[i];
    if (!p.allFinite()) {
      throw InputError(path + ": vertex " + std::to_string(i) + " has a non-finite coordinate (" + shortest(p.x()) +
                       ", " + shortest(p.y()) + ", " + shortest(p.z()) + ")");
    }
    Eigen::Index axis = 0;
    if (p.cwiseAbs().maxCoeff(&axis) > tolerance::kMaxCoordinate) {
      throw InputError(path + ": vertex " + std::to_string(i) + " has coordinate " + "xyz"[axis] + " = " +
                       shortest(p(axis)) + ", beyond +-1e75, where the distance computation's squared lengths " +
                       "would overflow");
    }
  }
}

void dropRepeatedTriangles(std::vector<TriangleIndices>& triangles, std::size_t vertexCount) {
  // Repeats found by sorting (corners, file position): 16 bytes a triangle, where a hash set's
  // nodes took about 50, more than the mesh itself.
  struct Keyed {
    SortedCorners corners;
    std::uint32_t position;
  };
  std::vector<Keyed> keyed(triangles.size());
  for (std::size_t i = 0; i < triangles.size(); ++i) keyed[i] = {sortedCorners(triangles[i]), static_cast<std::uint32_t>(i)};
  std::sort(keyed.begin(), keyed.end(), [](const Keyed& x, const Keyed& y) {
    return x.corners < y.corners || (x.corners == y.corners && x.position < y.position);
  });
  std::vector<bool> repeat(triangles.size(), false);
  for (std::size_t i = 1; i < keyed.size(); ++i) {
    if (keyed[i].corners == keyed[i - 1].corners) repeat[keyed[i].position] = true;
  }
  keyed = std::vector<Keyed>();
  std::vector<bool> cornerOfProperTriangle(vertexCount, false);
  std::size_t kept = 0;
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    if (repeat[i]) continue;
    const TriangleIndices t = triangles[i];
    triangles[kept++] = t;
    if (t[0] != t[1] || t[1] != t[2]) {
      for (const std::uint32_t v : t) cornerOfProperTriangle[v] = true;
    }
  }
  triangles.resize(kept);
  // A triangle on a single vertex adds no point when that vertex is a corner of another triangle.
  // One at a vertex of its own is a point of the surface, kept (a lone point is a valid mesh).
  triangles.erase(std::remove_if(triangles.begin(), triangles.end(),
                                 [&](const TriangleIndices& t) {
                                   return t[0] == t[1] && t[1] == t[2] && cornerOfProperTriangle[t[0]];
                                 }),
                  triangles.end());
}

Mesh meshFromSoup(PolygonSoup soup, const std::string& path) {
  std::uint64_t lines = 0, points = 0;
  std::vector<TriangleIndices> triangles;
  triangles.reserve(soup.corners.size() / 3);
  constexpr std::uint32_t kUnused = UINT32_MAX;
  std::vector<std::uint32_t> newIndex(soup.points.size(), kUnused);
  std::vector<Vec3> vertices;
  vertices.reserve(soup.points.size());
  std::unordered_map<PointBits, std::uint32_t, PointBitsHash> shared;
  shared.reserve(soup.points.size());
  auto vertexFor = [&](std::uint32_t point, std::size_t polygon) {
    if (point >= soup.points.size()) {
      throw InputError(path + ": face " + std::to_string(polygon) + " refers to vertex " + std::to_string(point) +
                       " but the file has " + std::to_string(soup.points.size()) + " vertices");
    }
    std::uint32_t& index = newIndex[point];
    if (index == kUnused) {
      const auto [it, inserted] = shared.emplace(bitsOf(soup.points[point]), static_cast<std::uint32_t>(vertices.size()));
      if (inserted) vertices.push_back(soup.points[point]);
      index = it->second;
    }
    return index;
  };
  std::vector<Vec3> polygon;  // a polygon's corners, and its triangles, for triangulatePolygon
  std::vector<std::array<std::uint32_t, 3>> pieces;
  std::uint64_t clippingTestsLeft = kClippingTestsPerFile;
  for (std::size_t p = 0; p < soup.polygonCount(); ++p) {
    const std::uint64_t begin = soup.starts[p], end = soup.starts[p + 1];
    const std::uint64_t n = end - begin;
    if (n == 1) ++points;
    if (n == 2) ++lines;
    if (n < 3) continue;
    if (n == 3) {
      triangles.push_back({vertexFor(soup.corners[begin], p), vertexFor(soup.corners[begin + 1], p),
                           vertexFor(soup.corners[begin + 2], p)});
      continue;
    }
    polygon.clear();
    for (std::uint64_t k = begin; k < end; ++k) {
      if (soup.corners[k] >= soup.points.size()) vertexFor(soup.corners[k], p);  // throws, naming the face
      polygon.push_back(soup.points[soup.corners[k]]);
    }
    pieces.clear();
    const PolygonKind kind = triangulatePolygon(polygon, pieces, clippingTestsLeft);
    if (kind == PolygonKind::tooLarge) {
      throw InputError(path + ": face " + std::to_string(p) + " is a non-convex polygon of " + std::to_string(n) +
                       " corners, more than the " + std::to_string(kMaxClippedCorners) +
                       " this reader triangulates: split it into triangles first");
    }
    if (kind == PolygonKind::outOfTests) {
      throw InputError(path + ": face " + std::to_string(p) + " (" + std::to_string(n) +
                       " corners): the file's non-convex polygons need more than the " +
                       std::to_string(kClippingTestsPerFile) +
                       " corner tests this reader spends clipping ears in one file: split them into triangles first");
    }
    for (const std::array<std::uint32_t, 3>& t : pieces) {
      triangles.push_back({vertexFor(soup.corners[begin + t[0]], p), vertexFor(soup.corners[begin + t[1]], p),
                           vertexFor(soup.corners[begin + t[2]], p)});
    }
  }
  if (triangles.empty()) {
    std::string what = path + ": the file holds no triangles";
    if (lines + points > 0) {
      what += " (only " + std::to_string(lines) + " lines and " + std::to_string(points) +
              " points, which are not surfaces)";
    }
    throw InputError(what);
  }
  // Repeats cost the distance queries (100,000 copies of one triangle: every tree query visits
  // each copy) and change no distance. No vertex is left unused: a dropped repeat's are its
  // original's, a dropped single-vertex triangle's belongs to another triangle.
  dropRepeatedTriangles(triangles, vertices.size());
  soup = PolygonSoup();  // the file's copy is no longer needed before the Mesh takes its own
  return Mesh(std::move(vertices), std::move(triangles), path);
}

}  // namespace adsd::io::detail
