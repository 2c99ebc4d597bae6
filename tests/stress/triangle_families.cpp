// Triangle-level families: two one-triangle meshes at identity poses, so the case is exactly the
// six corners. They complement, and do not repeat, the random families of
// tests/core/test_triangle_distance.cpp (generic, separated, near-parallel edges, parallel faces,
// coplanar on a grid, large offset, scaled, degenerate, near contact): each family here combines
// two of those hazards, or generalizes one of the two documented PQP/FCL/Coal failures of issue 3.

#include <array>
#include <cmath>

#include "families.h"
#include "shape_kit.h"

namespace adsd::stress {

namespace {

using Triangle = std::array<Vec3, 3>;

Generated pairOf(const Triangle& a, const Triangle& b, std::string variant, SeededRandom& random) {
  // Which triangle is A is itself random: the checks also swap them, but the first query's order
  // should not always be the generator's.
  const bool swap = random.below(2) == 1;
  const Triangle& first = swap ? b : a;
  const Triangle& second = swap ? a : b;
  return Generated{triangleMesh(first[0], first[1], first[2], "A"), triangleMesh(second[0], second[1], second[2], "B"),
                   Pose::Identity(), Pose::Identity(), std::move(variant)};
}

Triangle randomTriangle(SeededRandom& random, double halfSide, const Vec3& centre = Vec3::Zero()) {
  return {centre + random.inCube(halfSide), centre + random.inCube(halfSide), centre + random.inCube(halfSide)};
}

/// A triangle whose smallest angle is not tiny (so "the triangle's plane" means something).
Triangle wellShapedTriangle(SeededRandom& random, double halfSide, const Vec3& centre = Vec3::Zero()) {
  for (;;) {
    const Triangle t = randomTriangle(random, halfSide, centre);
    const double area2 = (t[1] - t[0]).cross(t[2] - t[0]).norm();
    const double longest2 = std::max({(t[1] - t[0]).squaredNorm(), (t[2] - t[1]).squaredNorm(), (t[0] - t[2]).squaredNorm()});
    if (area2 > 0.2 * longest2) return t;
  }
}

Vec3 unitNormal(const Triangle& t) { return (t[1] - t[0]).cross(t[2] - t[0]).normalized(); }

/// Exact axis permutation and sign flips of all six points (keeps exact parallelism, coplanarity
/// and touching).
void shuffleAxes(Triangle& a, Triangle& b, SeededRandom& random) {
  const Eigen::Matrix3d r = axisRotation(random);
  for (Triangle* t : {&a, &b}) {
    for (Vec3& v : *t) v = r * v;
  }
}

/// Point of triangle t at barycentric (u, v) measured from corner 0, u, v >= margin, u + v <= 1 - margin.
Vec3 interiorPoint(const Triangle& t, SeededRandom& random, double margin = 0.05) {
  double u = random.uniform(), v = random.uniform();
  if (u + v > 1) {
    u = 1 - u;
    v = 1 - v;
  }
  u = margin + (1 - 3 * margin) * u;
  v = margin + (1 - 3 * margin) * v;
  return t[0] + u * (t[1] - t[0]) + v * (t[2] - t[0]);
}

/// The gap of a near-contact case: exactly 0 now and then, otherwise 1e-14 ... 1e-6 of `size`.
double nearGap(SeededRandom& random, double size) { return random.below(8) == 0 ? 0.0 : size * random.logUniform(-14, -6); }

/// B placed so that the two triangles are exactly `gap` apart in real arithmetic (before the
/// rounding of the corners): B lies in the half space w.(x - m) >= gap and A in w.(x - m) <= 0,
/// and m, m + gap w are points of A and B. `kind` 0: B's corner over A's interior point m
/// (vertex-face, w = A's normal); 1: B's edge over A's edge (edge-edge, w between A's outward
/// in-plane edge normal and its face normal).
Triangle facingAtGap(const Triangle& a, double gap, int kind, double size, SeededRandom& random) {
  const Vec3 n = unitNormal(a);
  if (kind == 0) {
    const Vec3 m = interiorPoint(a, random);
    const Vec3 tip = m + gap * n;
    return {tip, tip + size * (random.uniform(0.2, 1) * n + 0.5 * random.inCube(1)),
            tip + size * (random.uniform(0.2, 1) * n + 0.5 * random.inCube(1))};
  }
  const int k = int(random.below(3));
  const Vec3 p = a[k], q = a[(k + 1) % 3], third = a[(k + 2) % 3];
  const Vec3 e = (q - p).normalized();
  Vec3 outward = n.cross(e);
  if (outward.dot(third - p) > 0) outward = -outward;
  const double phi = random.uniform(-1.4, 1.4);
  const Vec3 w = std::cos(phi) * outward + std::sin(phi) * n;
  const Vec3 m = p + random.uniform(0.1, 0.9) * (q - p);
  const Vec3 f = perpendicularTo(w, random);
  const Vec3 c = m + gap * w;
  return {c - size * random.uniform(0.1, 0.8) * f, c + size * random.uniform(0.1, 0.8) * f,
          c + size * (random.uniform(0.2, 1) * w + 0.3 * random.inCube(1).cross(w))};
}

// ---------------------------------------------------------------------------------------------

/// The first documented failure of issue 3 (PQP issue 4), generalized: CAD-like axis-aligned right
/// triangles at coordinates up to 1e8 x the scale, one horizontal, one vertical, with exactly
/// parallel edges, S's nearest corner 0, +-1..4 ulps, or 1e-14 ... 1 x the scale from T's plane,
/// over T's face, exactly on the line of T's edge, or with S's edge parallel to T's bottom edge.
Generated cadParallelEdges(SeededRandom& random, double s) {
  const double far = s * random.logUniform(0, 8);
  const Vec3 origin(far * random.uniform(-1, 1), far * random.uniform(-1, 1), far * random.uniform(-1, 1));
  // T: vertical, in the plane y = yT, right angle at (xT0, zLow).
  const double xT0 = origin.x(), xT1 = xT0 + s * random.uniform(0.2, 2);
  const double zLow = origin.z(), zHigh = zLow + s * random.uniform(0.2, 2);
  const double yT = origin.y();
  // S's nearest corner is delta from T's plane (negative: it crosses it).
  double yNear = yT;
  std::string variant;
  switch (random.below(4)) {
    case 0: variant = "touching"; break;
    case 1: {
      const int ulps = int(random.below(6)) - 2;  // -2 ... 3
      for (int i = 0; i < std::abs(ulps) + (ulps >= 0); ++i) yNear = std::nextafter(yNear, ulps >= 0 ? INFINITY : -INFINITY);
      variant = "ulps";
      break;
    }
    case 2: yNear = yT + s * random.logUniform(-14, -6); variant = "near"; break;
    default: yNear = yT + s * random.logUniform(-6, 0); variant = "apart"; break;
  }
  const double yFar = yNear + s * random.uniform(0.2, 2);
  Triangle sTri, tTri{Vec3(xT1, yT, zLow), Vec3(xT0, yT, zLow), Vec3(xT0, yT, zHigh)};
  switch (random.below(4)) {
    case 0: {  // S horizontal, its corner (xS0, yNear) over T's face
      const double a = random.uniform(0.05, 0.6), b = random.uniform(0.05, 0.9 - a);
      const double xS0 = xT0 + a * (xT1 - xT0), zS = zLow + b * (zHigh - zLow);
      const double xS1 = xS0 + s * random.uniform(0.2, 2);
      sTri = {Vec3(xS1, yFar, zS), Vec3(xS0, yFar, zS), Vec3(xS0, yNear, zS)};
      variant += ", corner over face";
      break;
    }
    case 1: {  // the same with S's corner exactly on the line of T's vertical edge x = xT0
      const double zS = zLow + random.uniform(0.05, 0.9) * (zHigh - zLow);
      sTri = {Vec3(xT0 - s * random.uniform(0.2, 2), yFar, zS), Vec3(xT0, yFar, zS), Vec3(xT0, yNear, zS)};
      variant += ", corner on edge line";
      break;
    }
    case 2: {  // S horizontal at z = zLow: its x edge parallel to T's bottom edge, overlapping in x
      const double x0 = xT0 + random.uniform(-0.5, 0.5) * (xT1 - xT0), x1 = x0 + s * random.uniform(0.2, 2);
      sTri = {Vec3(x1, yNear, zLow), Vec3(x0, yNear, zLow), Vec3(x0, yFar, zLow)};
      variant += ", parallel edges";
      break;
    }
    default: {  // S vertical too, in the plane y = yNear: parallel faces, overlapping in x and z
      const double x0 = xT0 + random.uniform(-0.5, 0.5) * (xT1 - xT0), z0 = zLow + random.uniform(-0.5, 0.5) * (zHigh - zLow);
      sTri = {Vec3(x0, yNear, z0), Vec3(x0 + s * random.uniform(0.2, 2), yNear, z0), Vec3(x0, yNear, z0 + s * random.uniform(0.2, 2))};
      variant += ", parallel faces";
      break;
    }
  }
  shuffleAxes(sTri, tTri, random);
  return pairOf(sTri, tTri, variant, random);
}

/// The second documented failure of issue 3, generalized: triangles whose edges are 1e-9 ... 1e-3
/// length units (absolute: PQP/FCL/Coal skip a test below a fixed 1e-15 on |n|^2, i.e. edges below
/// ~2e-4, and report contact), a corner, an edge or a whole face hovering over the other at
/// 1e-3 ... 1 of their size, near the origin or shifted by up to 1e3 sizes.
Generated smallTriangles(SeededRandom& random, double s) {
  const Vec3 centre = random.below(2) ? Vec3::Zero() : Vec3(s * random.logUniform(0, 3) * random.unitVector());
  const Triangle a = wellShapedTriangle(random, s, centre);
  const double gap = s * random.logUniform(-3, 0);
  switch (random.below(3)) {
    case 0: return pairOf(a, facingAtGap(a, gap, 0, s, random), "vertex-face", random);
    case 1: return pairOf(a, facingAtGap(a, gap, 1, s, random), "edge-edge", random);
    default: {
      const Vec3 n = unitNormal(a), shift = gap * n + 0.3 * s * perpendicularTo(n, random);
      return pairOf(a, {a[0] + shift, a[1] + shift, a[2] + shift}, "parallel faces", random);
    }
  }
}

/// Issue 3: tiny features (edges of 1e-8 ... 1e-6 x the scene) next to large ones: a tiny triangle
/// over the large one's interior, beside its edge, at its corner, piercing it, or lying in its plane.
Generated tinyNextToLarge(SeededRandom& random, double s) {
  const Triangle big = wellShapedTriangle(random, s);
  const double tiny = s * random.logUniform(-8, -6);
  const double gap = random.below(6) == 0 ? 0.0 : s * random.logUniform(-14, -4);
  const Vec3 n = unitNormal(big);
  switch (random.below(5)) {
    case 0: return pairOf(big, facingAtGap(big, gap, 0, tiny, random), "over face", random);
    case 1: return pairOf(big, facingAtGap(big, gap, 1, tiny, random), "beside edge", random);
    case 2: {
      const Vec3 corner = big[random.below(3)];
      const Vec3 away = (corner - (big[0] + big[1] + big[2]) / 3.0).normalized();
      const Vec3 w = (away + 0.5 * random.unitVector()).normalized();
      const Vec3 tip = corner + gap * w;
      return pairOf(big, {tip, tip + tiny * (w + 0.7 * random.unitVector()), tip + tiny * (w + 0.7 * random.unitVector())},
                    "at corner", random);
    }
    case 3: {
      const Vec3 m = interiorPoint(big, random);
      return pairOf(big, {m + tiny * n, m - tiny * n + 0.5 * tiny * random.unitVector(), m + tiny * random.unitVector()},
                    "piercing", random);
    }
    default: {
      const Vec3 m = interiorPoint(big, random, 0.0);
      const Vec3 e = perpendicularTo(n, random), f = n.cross(e);
      return pairOf(big, {m, m + tiny * e, m + tiny * (0.3 * e + f)}, "in plane", random);
    }
  }
}

/// Issue 3 items 2 and 6: near contact (1e-14 ... 1e-6 x the scene, or exactly 0 before rounding)
/// combined with a large offset (the pair translated by 1e3 ... 1e8 x the scene): a vertex over a
/// face or an edge over an edge.
Generated nearContactFar(SeededRandom& random, double s) {
  const Triangle a = wellShapedTriangle(random, s);
  const int kind = int(random.below(2));
  const Triangle b = facingAtGap(a, nearGap(random, s), kind, s, random);
  const Vec3 offset = s * random.logUniform(3, 8) * random.unitVector();
  Triangle fa, fb;
  for (int k = 0; k < 3; ++k) {
    fa[k] = a[k] + offset;
    fb[k] = b[k] + offset;
  }
  return pairOf(fa, fb, kind == 0 ? "vertex-face" : "edge-edge", random);
}

/// Issue 3: coplanar touching (shared corner, corner on an edge, collinear overlapping edges, a
/// shared edge), coplanar disjoint and coplanar overlapping, on a dyadic grid scaled by a power of
/// two and translated by an integer offset of 1e3 ... 1e8 units, so that touching stays exact.
Generated coplanarTouchingFar(SeededRandom& random, double s) {
  const double unit = powerOfTwoNear(s);
  const double z = dyadic(random, 8);
  Triangle a;
  for (;;) {
    for (Vec3& v : a) v = Vec3(dyadic(random, 8), dyadic(random, 8), z);
    if ((a[1] - a[0]).cross(a[2] - a[0]).norm() > 0.1) break;
  }
  const int k = int(random.below(3));
  const Vec3 p = a[k], q = a[(k + 1) % 3], third = a[(k + 2) % 3];
  // In-plane outward normal of edge pq (exact: a rotation by 90 degrees of dyadic numbers).
  Vec3 out(-(q - p).y(), (q - p).x(), 0.0);
  if (out.dot(third - p) > 0) out = -out;
  const double t1 = std::ldexp(double(1 + random.below(7)), -3);  // 1/8 ... 7/8: on the edge
  std::string variant;
  Triangle b;
  switch (random.below(6)) {
    case 0: b = {p, p + 0.5 * out + 0.25 * (p - q), p + 0.25 * out + 0.5 * (p - third)}; variant = "shared corner"; break;
    case 1: {
      const Vec3 c = p + t1 * (q - p);
      b = {c, c + 0.5 * out + 0.25 * (q - p), c + 0.5 * out - 0.25 * (q - p)};
      variant = "corner on edge";
      break;
    }
    case 2: {
      const double t0 = t1 + std::ldexp(double(1 + random.below(8)), -3);  // B's edge on A's, overlapping part of it
      b = {p + t1 * (q - p), p + t0 * (q - p), p + 0.5 * (t0 + t1) * (q - p) + 0.5 * out};
      variant = "collinear overlapping edges";
      break;
    }
    case 3: b = {p, q, 0.5 * (p + q) + out}; variant = "shared edge"; break;
    case 4: {
      const Vec3 c = p + t1 * (q - p) + std::ldexp(double(1 + random.below(64)), -10) * out;
      b = {c, c + 0.5 * out + 0.25 * (q - p), c + 0.5 * out - 0.25 * (q - p)};
      variant = "disjoint";
      break;
    }
    default:
      b = {third, third + std::ldexp(1.0, -2) * (p + q - 2.0 * third), p + std::ldexp(1.0, -3) * out};
      variant = "overlapping";
      break;
  }
  const Vec3 offset(std::round(random.logUniform(3, 8)) * (random.below(2) ? 1 : -1),
                    std::round(random.logUniform(3, 8)) * (random.below(2) ? 1 : -1),
                    std::round(random.logUniform(3, 8)) * (random.below(2) ? 1 : -1));
  for (Triangle* t : {&a, &b}) {
    for (Vec3& v : *t) v = unit * (v + offset);
  }
  shuffleAxes(a, b, random);
  return pairOf(a, b, variant, random);
}

/// A segment through `centre` along the unit `direction`, about `s` long, given as a zero-area
/// triangle: three collinear corners or a repeated corner.
Triangle segmentTriangle(const Vec3& centre, const Vec3& direction, double s, SeededRandom& random) {
  const Vec3 p = centre - s * random.uniform(0.1, 1) * direction, q = centre + s * random.uniform(0.1, 1) * direction;
  switch (random.below(3)) {
    case 0: return {p, q, q};
    case 1: return {p, p, q};
    default: return {p, q, p + random.uniform() * (q - p)};
  }
}

/// Issue 3: zero-area triangles (segments given as three collinear corners or a repeated corner,
/// points) close to each other or to a proper triangle: skew segments, a point over a face, a
/// point beside a segment, parallel segments, collinear segments, a segment through a face, at
/// gaps of 0 or 1e-14 ... 1 x the scene (negative along a line: overlapping).
Generated degenerateNear(SeededRandom& random, double s) {
  const double gap = random.below(6) == 0 ? 0.0 : s * random.logUniform(-14, 0);
  const Vec3 m = s * random.inCube(1);
  const Vec3 e = random.unitVector();
  const Vec3 w = perpendicularTo(e, random);
  switch (random.below(6)) {
    case 0:
      return pairOf(segmentTriangle(m, e, s, random), segmentTriangle(m + gap * w, perpendicularTo(w, random), s, random),
                    "skew segments", random);
    case 1: {
      const Triangle face = wellShapedTriangle(random, s);
      const Vec3 point = interiorPoint(face, random) + gap * unitNormal(face);
      return pairOf(face, {point, point, point}, "point over face", random);
    }
    case 2: {
      const Vec3 point = m + gap * w;
      return pairOf(segmentTriangle(m, e, s, random), {point, point, point}, "point beside segment", random);
    }
    case 3:
      return pairOf(segmentTriangle(m, e, s, random),
                    segmentTriangle(m + gap * w + 0.5 * s * random.uniform(-1, 1) * e, e, s, random), "parallel segments",
                    random);
    case 4: {
      // On one line: B starts `gap` beyond A's end (or overlaps A by up to half its length).
      const Vec3 end = m + s * e;
      const double along = random.below(3) == 0 ? -0.5 * s * random.uniform() : gap;
      const Vec3 start = end + along * e;
      return pairOf({m, end, end}, {start, start + s * random.uniform(0.2, 1) * e, start}, "collinear segments", random);
    }
    default: {
      const Triangle face = wellShapedTriangle(random, s);
      const Vec3 n = unitNormal(face), through = interiorPoint(face, random);
      return pairOf(face, segmentTriangle(through, (n + 0.8 * random.unitVector()).normalized(), s, random),
                    "segment through face", random);
    }
  }
}

/// Issue 3: slivers, triangles whose third corner is 1e-16 ... 1e-6 x the scene off the line of the
/// other two (smallest angle 1e-16 ... 1e-6 rad: between the core's "no interior" cut of ~1e-15
/// and well-shaped), crossed by a segment, a sliver or a triangle through an interior point, or
/// with a point, a segment or a face 0 or 1e-14 ... 1 x the scene beside it.
Generated slivers(SeededRandom& random, double s) {
  const Vec3 p = s * random.inCube(1), e = random.unitVector();
  const double length = s * random.uniform(0.3, 2);
  const Vec3 up = perpendicularTo(e, random);
  const double height = s * random.logUniform(-16, -6);
  const Triangle sliver{p, p + length * e, p + random.uniform(-0.5, 1.5) * length * e + height * up};
  // A point of the sliver: on its long edge, or inside it (barycentric, so within `height` of it).
  const Vec3 on = random.below(2) ? Vec3(p + random.uniform(0.1, 0.9) * length * e) : interiorPoint(sliver, random);
  const double gap = random.below(4) == 0 ? 0.0 : s * random.logUniform(-14, 0);
  // Directions away from the sliver's line: its (ill-conditioned) plane normal is never needed.
  const Vec3 away = perpendicularTo(e, random);
  switch (random.below(5)) {
    case 0: return pairOf(sliver, segmentTriangle(on + gap * away, (away + random.unitVector()).normalized(), s, random), "segment through or beside", random);
    case 1: {
      const Vec3 point = on + gap * away;
      return pairOf(sliver, {point, point, point}, "point beside", random);
    }
    case 2: {
      // Another sliver crossing this one.
      const Vec3 f = perpendicularTo(away, random);
      const Vec3 q = on + gap * away - 0.5 * length * f;
      return pairOf(sliver, {q, q + length * f, q + 0.5 * length * f + s * random.logUniform(-16, -6) * perpendicularTo(f, random)},
                    "two slivers", random);
    }
    case 3: {
      // A proper triangle whose corner touches or nears the sliver.
      const Vec3 tip = on + gap * away;
      return pairOf(sliver, {tip, tip + s * (away + 0.5 * random.unitVector()), tip + s * (away + 0.5 * random.unitVector())},
                    "triangle corner beside", random);
    }
    default: {
      // A proper triangle the sliver pierces (the sliver's long edge through its interior).
      const Vec3 n = perpendicularTo(e, random), f = n.cross(e).normalized();
      const Vec3 c = on + gap * n;
      return pairOf(sliver, {c + s * (f - 0.5 * e), c + s * (-f - 0.5 * e), c + s * (0.3 * f + e)}, "triangle across", random);
    }
  }
}

/// Faces that are nearly but not exactly parallel (tilt 1e-16 ... 1e-3 rad), one over the other at
/// 1e-14 ... 1e-1 x the scene: the vertex-face minimum moves between nearly tied corners, and where
/// tilt x size exceeds the gap the triangles cross.
Generated tiltedFaces(SeededRandom& random, double s) {
  const Triangle a = wellShapedTriangle(random, s);
  const Vec3 n = unitNormal(a), centroid = (a[0] + a[1] + a[2]) / 3.0;
  Triangle b = a;
  if (random.below(2)) {  // another triangle in A's plane
    const Vec3 e = perpendicularTo(n, random), f = n.cross(e);
    for (Vec3& v : b) v = centroid + s * (random.uniform(-1, 1) * e + random.uniform(-1, 1) * f);
  }
  const Eigen::AngleAxisd tilt(random.logUniform(-16, -3), perpendicularTo(n, random));
  const Vec3 shift = s * random.logUniform(-14, -1) * n + 0.5 * s * random.uniform(-1, 1) * perpendicularTo(n, random);
  for (Vec3& v : b) v = centroid + tilt * (v - centroid) + shift;
  return pairOf(a, b, "tilted", random);
}

}  // namespace

std::vector<Family> triangleFamilies() {
  std::vector<Family> f;
  f.push_back({"tri/cad-parallel-edges",
               "axis-aligned right triangles at 1..1e8 x scale, exactly parallel edges/faces, 0/ulps/1e-14..1 apart (PQP issue 4)",
               -6, 6, {0.15, 0.15, 0.2}, cadParallelEdges});
  f.push_back({"tri/small-triangles", "edges of 1e-9..1e-3 units hovering at 1e-3..1 of their size (the 2e-4 normal test)",
               -9, -3, {0.0, 0.0, 0.95}, smallTriangles});
  f.push_back({"tri/tiny-next-to-large", "a 1e-8..1e-6 x scene triangle over/beside/at/through/in a large one",
               -6, 6, {0.2, 0.3, 0.05}, tinyNextToLarge});
  f.push_back({"tri/near-contact-far", "vertex-face and edge-edge at 0 or 1e-14..1e-6 x scene, translated 1e3..1e8 x scene",
               -6, 6, {0.05, 0.3, 0.0}, nearContactFar});
  f.push_back({"tri/coplanar-touching-far",
               "coplanar touching/disjoint/overlapping on a dyadic grid, integer offsets 1e3..1e8, exact", -6, 6,
               {0.6, 0.0, 0.1}, coplanarTouchingFar});
  f.push_back({"tri/degenerate-near", "segments and points (zero-area triangles) near each other and near faces, 0 or 1e-14..1 apart",
               -6, 6, {0.1, 0.2, 0.15}, degenerateNear});
  // Apart: about 30 % of the sample (30.4 % of 20 000 cases, seed 7), so the floor sits below it.
  f.push_back({"tri/slivers", "slivers (smallest angle 1e-16..1e-6 rad) crossed by or 0..1 x scene beside segments, points, slivers, faces",
               -6, 6, {0.1, 0.1, 0.2}, slivers});
  f.push_back({"tri/tilted-faces", "nearly parallel faces (tilt 1e-16..1e-3 rad) 1e-14..1e-1 x scene apart or crossing",
               -6, 6, {0.1, 0.1, 0.1}, tiltedFaces});
  return f;
}

}  // namespace adsd::stress
