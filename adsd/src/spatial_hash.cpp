// Stage two (sec. 5): spatial hashing in the frame of the separating plane, sized by the GJK
// bounds, culling triangle pairs twice (Fig. 2).

#include <algorithm>
#include <cmath>

#include "adsd/triangle_distance.h"
#include "query.h"

namespace adsd::detail {

namespace {

/// Cell hash of [THM+03]: large primes mixed by xor, folded into the table size (a power of two).
/// Distinct cells may share a bucket; the box test behind it removes such false candidates.
inline std::uint32_t cellHash(std::int64_t ix, std::int64_t iy, std::uint32_t mask) {
  return static_cast<std::uint32_t>((ix * 73856093) ^ (iy * 19349663)) & mask;
}

/// Lower bound of the distance of two triangles from their boxes in the grid frame.
inline double boxDistance(const SlabTriangle& s, const SlabTriangle& t) {
  const double gx = std::max({0.0, s.minX - t.maxX, t.minX - s.maxX});
  const double gy = std::max({0.0, s.minY - t.maxY, t.minY - s.maxY});
  const double gz = std::max({0.0, s.minZ - t.maxZ, t.minZ - s.maxZ});
  return std::sqrt(gx * gx + gy * gy + gz * gz);
}

/// A slab triangle's extent in the separating plane: the larger side of its grid-frame box.
inline double planeSize(const SlabTriangle& s) { return std::max(s.maxX - s.minX, s.maxY - s.minY); }

/// Fills the grid-frame box of a slab triangle from its corners (A frame).
void frameBox(SlabTriangle& s, const Vec3& ex, const Vec3& ey, const Vec3& ez) {
  double x[3], y[3], z[3];
  for (int k = 0; k < 3; ++k) {
    x[k] = ex.dot(s.corner[k]);
    y[k] = ey.dot(s.corner[k]);
    z[k] = ez.dot(s.corner[k]);
  }
  s.minX = std::min({x[0], x[1], x[2]});
  s.maxX = std::max({x[0], x[1], x[2]});
  s.minY = std::min({y[0], y[1], y[2]});
  s.maxY = std::max({y[0], y[1], y[2]});
  s.minZ = std::min({z[0], z[1], z[2]});
  s.maxZ = std::max({z[0], z[1], z[2]});
}

}  // namespace

void Query::testSlabPair(const SlabTriangle& ta, const SlabTriangle& tb) {
  // Box bound first: pairs that cannot beat the global upper bound are dropped without the exact
  // test (the dropped bound is recorded by skip() for the interval).
  charge(tolerance::kWorkBoxTest);
  if (skip(boxDistance(ta, tb) - roundoff_)) return;
  charge(tolerance::kWorkTrianglePair);
  const double limit = pruneBound();
  const double ceiling = triangleCeiling(limit);
  const TrianglePairResult t =
      triangleDistanceBelow(ta.corner[0], ta.corner[1], ta.corner[2], tb.corner[0], tb.corner[1], tb.corner[2],
                            enoughDistance(), ceiling);
  ++counters_.trianglePairsTested;
  leftOutAbove(t.distance, ceiling, limit);
  offer(t.pointOnA, t.pointOnB, t.distance, ta.triangle, false, tb.triangle, false);
}

void Query::gatherSlabA(const SubMesh& a, const Vec3& ex, const Vec3& ey, const Vec3& ez, double slabLow) {
  auto admit = [&](std::uint32_t t, double highest) {
    if (highest < slabLow) return;
    SlabTriangle s;
    for (int k = 0; k < 3; ++k) s.corner[k] = a_.corner(t, k);
    s.triangle = t;
    frameBox(s, ex, ey, ez);
    buf_.slabA.push_back(s);
  };
  projectA(a, ez);
  for (std::uint32_t i = a.t0; i < a.t1; ++i) {
    const std::uint32_t t = orderA_[i];
    const TriangleIndices& tri = a_.triangles()[t];
    admit(t, std::max({buf_.projectionA[tri[0]], buf_.projectionA[tri[1]], buf_.projectionA[tri[2]]}));
  }
}

void Query::gatherSlabB(const SubMesh& b, const Vec3& ex, const Vec3& ey, const Vec3& ez, double slabHigh) {
  auto admit = [&](std::uint32_t t, double lowest) {
    if (lowest > slabHigh) return;
    SlabTriangle s;
    for (int k = 0; k < 3; ++k) s.corner[k] = toA(b_.corner(t, k));
    s.triangle = t;
    frameBox(s, ex, ey, ez);
    buf_.slabB.push_back(s);
  };
  projectB(b, ez);
  for (std::uint32_t i = b.t0; i < b.t1; ++i) {
    const std::uint32_t t = orderB_[i];
    const TriangleIndices& tri = b_.triangles()[t];
    admit(t, std::min({buf_.projectionB[tri[0]], buf_.projectionB[tri[1]], buf_.projectionB[tri[2]]}));
  }
}

bool Query::hashStage(const SubMesh& a, const SubMesh& b, const GjkResult& g) {
  // Sec. 5.1: the grid frame. z along the separating direction n (A towards B), x and y span
  // the separating plane.
  const Vec3 ez = g.direction;
  const Vec3 ex = ez.unitOrthogonal();
  const Vec3 ey = ez.cross(ex);
  const double lower = g.minB - g.maxA;
  const double upper = geometricBound();
  if (!std::isfinite(upper)) {
    testAllPairs(a, b);
    return true;
  }

  // Sec. 5.2, eq. (1): a point of A below maxA - (U - L), or of B above minB + (U - L), is farther
  // than U from the other mesh (the other mesh lies wholly beyond its support plane). The slab
  // spans c_z = 2U - L. Widened by the roundoff allowance so that rounding never culls a pair.
  const double reach = upper - lower + roundoff_;
  const double slabLowA = g.maxA - reach;
  const double slabHighB = g.minB + reach;

  // First culling (Fig. 2, 1.): only triangles reaching into the slab are kept.
  std::vector<SlabTriangle>& slabA = buf_.slabA;
  std::vector<SlabTriangle>& slabB = buf_.slabB;
  slabA.clear();
  slabB.clear();
  charge(tolerance::kWorkTrianglePass * (a.triangles() + b.triangles()));
  gatherSlabA(a, ex, ey, ez, slabLowA);
  gatherSlabB(b, ex, ey, ez, slabHighB);
  const std::size_t pairs = slabA.size() * slabB.size();

  // Eq. (3), taken over every pair rather than the support pair: points closer than U whose z
  // differ by at least L differ in the plane by at most sqrt(U^2 - L^2). Any larger cell is also
  // correct; the cell grows to the mean triangle size (so that a triangle covers few cells) and to
  // the span / kMaxCellsPerAxis (so that indices stay small).
  double cell = 0.0, minX = 0.0, minY = 0.0;
  if (pairs > static_cast<std::size_t>(tolerance::kHashMinPairs)) {
    const double lowerSafe = std::max(0.0, lower - roundoff_);
    cell = std::sqrt(std::max(0.0, upper * upper - lowerSafe * lowerSafe)) + roundoff_;
    minX = slabA[0].minX, minY = slabA[0].minY;
    double maxX = slabA[0].maxX, maxY = slabA[0].maxY;
    double meanSize = 0.0;
    for (const SlabTriangle& s : slabA) {
      minX = std::min(minX, s.minX);
      maxX = std::max(maxX, s.maxX);
      minY = std::min(minY, s.minY);
      maxY = std::max(maxY, s.maxY);
      meanSize += planeSize(s);
    }
    meanSize /= static_cast<double>(slabA.size());
    // The mean again without the triangles far larger than it: one triangle 2e4 across added to a
    // cow (an outside review's mesh) raised the mean, and with it the cell, to about the cow's
    // size, so that near its copy every B triangle met nearly every A triangle (the copy turned
    // and 0.18 away: 59 ms, and 7.8 ms with the giant left out). Left out of the mean, such
    // triangles cover many cells and meet the B triangles directly instead (bigA).
    double keptSize = 0.0;
    std::size_t kept = 0;
    for (const SlabTriangle& s : slabA) {
      const double size = planeSize(s);
      if (size > tolerance::kOutlierTriangleSize * meanSize) continue;
      keptSize += size;
      ++kept;
    }
    if (kept > 0) meanSize = keptSize / static_cast<double>(kept);
    cell = std::max({cell, meanSize, (maxX - minX) / tolerance::kMaxCellsPerAxis,
                     (maxY - minY) / tolerance::kMaxCellsPerAxis});
    if (!(cell > 0.0)) cell = std::max(1.0, magnitude_);  // every slab triangle is a point at one spot
    // A B triangle meets the A triangles of about 3 x 3 cells: with the slab's A triangles spread
    // over the grid's cells, that many of them each. When the bounds lie far apart for the pair's
    // size, the cells are as large as the slab and the grid culls next to nothing (blade and
    // turbine, 10 apart: 34 682 triangles in the slab, 1.7 s): splitting the pair lets its halves'
    // GJK bounds drop most of it instead (tolerance::kHashCandidatesPerTriangle).
    const double cells =
        std::max(1.0, std::ceil((maxX - minX) / cell)) * std::max(1.0, std::ceil((maxY - minY) / cell));
    const double candidates = static_cast<double>(pairs) * std::min(1.0, 9.0 / cells);
    if ((a.triangles() > 1 || b.triangles() > 1) &&
        candidates > tolerance::kHashCandidatesPerTriangle * static_cast<double>(slabA.size() + slabB.size())) {
      return false;
    }
  }
  counters_.trianglesHashed += slabA.size() + slabB.size();
  if (upper < best_) minSkippedLower_ = std::min(minSkippedLower_, upper);  // what the slab culled is beyond it
  if (slabA.empty() || slabB.empty()) return true;

  // Nearest to the separating plane first: the global upper bound falls fastest that way, and
  // with it the box bound prunes more of what follows.
  std::sort(slabB.begin(), slabB.end(), [](const SlabTriangle& s, const SlabTriangle& t) { return s.minZ < t.minZ; });

  if (pairs <= static_cast<std::size_t>(tolerance::kHashMinPairs)) {
    for (const SlabTriangle& tb : slabB) {
      for (const SlabTriangle& ta : slabA) {
        if (done_) return true;
        testSlabPair(ta, tb);
      }
    }
    return true;
  }
  const double inv = 1.0 / cell;
  auto cellX = [&](double x) { return static_cast<std::int64_t>(std::floor((x - minX) * inv)); };
  auto cellY = [&](double y) { return static_cast<std::int64_t>(std::floor((y - minY) * inv)); };

  // Build the table (counting sort into buckets, no allocation once warm). Oversized triangles
  // stay out of it and meet every B triangle directly.
  std::uint32_t entries = 0;
  buf_.bigA.clear();
  for (std::uint32_t i = 0; i < slabA.size(); ++i) {
    const SlabTriangle& s = slabA[i];
    const std::int64_t cells = (cellX(s.maxX) - cellX(s.minX) + 1) * (cellY(s.maxY) - cellY(s.minY) + 1);
    if (cells > tolerance::kMaxCellsPerTriangle) {
      buf_.bigA.push_back(i);
    } else {
      entries += static_cast<std::uint32_t>(cells);
    }
  }
  std::uint32_t tableSize = 16;
  while (tableSize < 2 * entries) tableSize <<= 1;
  const std::uint32_t mask = tableSize - 1;
  buf_.bucketStart.assign(tableSize + 1, 0);
  buf_.entryBucket.resize(entries);
  buf_.bucketEntries.resize(entries);
  std::uint32_t e = 0;
  std::size_t nextBig = 0;
  for (std::uint32_t i = 0; i < slabA.size(); ++i) {
    if (nextBig < buf_.bigA.size() && buf_.bigA[nextBig] == i) {
      ++nextBig;
      continue;
    }
    const SlabTriangle& s = slabA[i];
    for (std::int64_t ix = cellX(s.minX); ix <= cellX(s.maxX); ++ix) {
      for (std::int64_t iy = cellY(s.minY); iy <= cellY(s.maxY); ++iy) {
        const std::uint32_t h = cellHash(ix, iy, mask);
        buf_.entryBucket[e++] = h;
        ++buf_.bucketStart[h + 1];
      }
    }
  }
  for (std::uint32_t h = 0; h < tableSize; ++h) buf_.bucketStart[h + 1] += buf_.bucketStart[h];
  {
    // Scatter: walk the entries again in the same order, placing each slab index in its bucket.
    std::vector<std::uint32_t>& cursor = buf_.lastVisitor;  // reused as the fill cursor
    cursor.assign(buf_.bucketStart.begin(), buf_.bucketStart.end() - 1);
    e = 0;
    nextBig = 0;
    for (std::uint32_t i = 0; i < slabA.size(); ++i) {
      if (nextBig < buf_.bigA.size() && buf_.bigA[nextBig] == i) {
        ++nextBig;
        continue;
      }
      const SlabTriangle& s = slabA[i];
      const std::int64_t cells = (cellX(s.maxX) - cellX(s.minX) + 1) * (cellY(s.maxY) - cellY(s.minY) + 1);
      for (std::int64_t k = 0; k < cells; ++k) buf_.bucketEntries[cursor[buf_.entryBucket[e++]]++] = i;
    }
  }

  // Second culling (Fig. 2, 2.): a B triangle meets only the A triangles of the cells its box
  // covers and their one-ring; each pair once (lastVisitor stamps).
  // The slab and the cells were sized by the upper bound at the start (eq. 1 and 3), which the
  // first B triangles tested may lower by orders of magnitude: GJK's support points are corners,
  // far from the nearest point inside a large triangle (a triangle 2e4 across beside a cow, its
  // bound 292 against the answer 28: both cows in one cell, about 5 800 x 5 800 box tests, 0.4 s;
  // 7 ms with the restart).
  // Once the reach has fallen to a quarter, the stage starts again with the bound found: a
  // narrower slab and smaller cells for the B triangles left (each restart linear, and each needs
  // a reach a quarter of the last: a threshold query's reach may start at or below 0, and then
  // never restarts).
  const bool mayRestart = upper - lower > 0.0;
  const double restartBelow = lower + 0.25 * (upper - lower);
  buf_.lastVisitor.assign(slabA.size(), 0);
  for (std::uint32_t j = 0; j < slabB.size(); ++j) {
    if (mayRestart && geometricBound() < restartBelow && slabB.size() - j >= tolerance::kHashRestartTriangles) {
      ++counters_.hashRestarts;
      return hashStage(a, b, g);
    }
    const SlabTriangle& tb = slabB[j];
    const std::uint32_t stamp = j + 1;
    for (std::uint32_t i : buf_.bigA) {
      if (done_) return true;
      testSlabPair(slabA[i], tb);
    }
    const std::int64_t x0 = cellX(tb.minX) - 1, x1 = cellX(tb.maxX) + 1;
    const std::int64_t y0 = cellY(tb.minY) - 1, y1 = cellY(tb.maxY) + 1;
    if ((x1 - x0 + 1) * (y1 - y0 + 1) > tolerance::kMaxCellsPerTriangle + 8) {
      // A large B triangle: cheaper to meet every hashed A triangle once than to walk its cells.
      for (std::uint32_t i = 0; i < slabA.size(); ++i) {
        if (buf_.lastVisitor[i] == stamp || std::binary_search(buf_.bigA.begin(), buf_.bigA.end(), i)) continue;
        buf_.lastVisitor[i] = stamp;
        if (done_) return true;
        testSlabPair(slabA[i], tb);
      }
      continue;
    }
    for (std::int64_t ix = x0; ix <= x1; ++ix) {
      for (std::int64_t iy = y0; iy <= y1; ++iy) {
        const std::uint32_t h = cellHash(ix, iy, mask);
        for (std::uint32_t k = buf_.bucketStart[h]; k < buf_.bucketStart[h + 1]; ++k) {
          const std::uint32_t i = buf_.bucketEntries[k];
          if (buf_.lastVisitor[i] == stamp) continue;
          buf_.lastVisitor[i] = stamp;
          if (done_) return true;
          testSlabPair(slabA[i], tb);
        }
      }
    }
  }
  return true;
}

}  // namespace adsd::detail
