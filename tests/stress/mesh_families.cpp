// Mesh-level families: small meshes (up to a few hundred triangles, so that the brute-force
// oracle stays cheap) in the configurations of issue 3 item 2 that meshes add to triangles:
// hulls that overlap (recursion, sec. 6), many tied support points (GJK, sec. 4), near contact
// and large offsets (the pruning bounds of sec. 6.2, issue 3 item 6), given through the poses
// and through the vertex coordinates.

#include <cmath>

#include "adsd/shapes.h"
#include "families.h"
#include "shape_kit.h"

namespace adsd::stress {

namespace {

Generated meshPair(Mesh a, const Pose& poseA, Mesh b, const Pose& poseB, std::string variant, bool penetrating = false) {
  return Generated{std::move(a), std::move(b), poseA, poseB, std::move(variant), penetrating};
}

Pose rigid(const Eigen::Matrix3d& rotation, const Vec3& translation) {
  Pose p = Pose::Identity();
  p.linear() = rotation;
  p.translation() = translation;
  return p;
}

/// The gap of a near-contact placement, as a multiple of `size`, with its name: 0 (touching up to
/// rounding), 1e-14 ... 1e-6 (near contact), or 1e-6 ... 1e-1 (apart).
double contactGap(SeededRandom& random, double size, std::string& name) {
  switch (random.below(4)) {
    case 0: name = "touching"; return 0.0;
    case 1:
    case 2: name = "near"; return size * random.logUniform(-14, -6);
    default: name = "apart"; return size * random.logUniform(-6, -1);
  }
}

/// B (turned by rotationB) over a random surface point p of A (placed by poseA), its support
/// vertex towards A at p + gap n (n: A's outward normal there). Negative gap: the vertex is
/// -gap deep inside A.
Pose overSurface(const Mesh& a, const Pose& poseA, const Mesh& b, const Eigen::Matrix3d& rotationB, double gap,
                 SeededRandom& random) {
  SurfacePoint p = randomSurfacePoint(a, poseA, random, 0.1);
  for (int tries = 0; p.normal.squaredNorm() == 0.0 && tries < 16; ++tries) p = randomSurfacePoint(a, poseA, random, 0.1);
  const Vec3 n = p.normal.squaredNorm() > 0 ? p.normal : Vec3::UnitZ();
  return placeSupportAt(b, rotationB, n, p.point + gap * n);
}

Eigen::Matrix3d randomRotation(SeededRandom& random) { return random.rotation().toRotationMatrix(); }

/// Half extents that are multiples of 1/8 in [1/8, 2] (exact, and sums of them too).
Vec3 dyadicExtents(SeededRandom& random) {
  return Vec3(double(1 + random.below(16)) / 8, double(1 + random.below(16)) / 8, double(1 + random.below(16)) / 8);
}

int boxDivisions(SeededRandom& random) { return 1 << random.below(3); }  // 1, 2 or 4

// ---------------------------------------------------------------------------------------------

/// Two axis-aligned grid boxes face to face along an axis, `gap` apart along it (gap 0: exactly
/// touching), laterally overlapping, meeting edge to edge or corner to corner, or laterally apart.
/// Exact arithmetic throughout when gap is 0: dyadic extents times a power of two, rotations with
/// entries 0 and +-1, translations that are integers times that power of two.
Generated boxesFacing(SeededRandom& random, double s, bool touching) {
  const double unit = powerOfTwoNear(s);
  const Vec3 hA = dyadicExtents(random), hB = dyadicExtents(random);
  const int axis = int(random.below(3));
  const double side = random.below(2) ? 1.0 : -1.0;
  Vec3 centre = Vec3::Zero();
  const double gap = touching ? 0.0 : (hA + hB).norm() * random.logUniform(-14, -6);
  centre[axis] = side * (hA[axis] + hB[axis] + gap);
  std::string variant;
  const int lateral = int(random.below(8));
  for (int k = 1; k < 3; ++k) {
    const int other = (axis + k) % 3;
    const double reach = hA[other] + hB[other];
    const double sign = random.below(2) ? 1.0 : -1.0;
    if (lateral == 0 || (lateral == 1 && k == 1)) {
      centre[other] = sign * reach;  // edges (one axis) or corners (both) meet exactly
    } else if (lateral == 2 && k == 1) {
      centre[other] = sign * (reach + double(1 + random.below(8)) / 16);  // laterally apart
    } else {
      centre[other] = dyadic(random, 4) * reach;  // overlapping faces
    }
  }
  variant = lateral == 0 ? "corner on corner" : lateral == 1 ? "edge on edge" : lateral == 2 ? "laterally apart" : "face on face";
  const Eigen::Matrix3d rotation = axisRotation(random);
  // A common placement: small, or an integer offset of 1e3 ... 1e8 units (exact in double).
  Vec3 where(double(random.below(9)) - 4, double(random.below(9)) - 4, double(random.below(9)) - 4);
  if (random.below(3) == 0) {
    for (int k = 0; k < 3; ++k) where[k] = std::round(random.logUniform(3, 8)) * (random.below(2) ? 1 : -1);
  }
  const Mesh a = gridBox(-unit * hA, unit * hA, boxDivisions(random));
  if (random.below(2)) {
    const Mesh b = gridBox(-unit * hB, unit * hB, boxDivisions(random));
    return meshPair(a, rigid(rotation, unit * where), b, rigid(rotation, unit * where + rotation * (unit * centre)),
                    variant + ", through poses");
  }
  const Mesh b = gridBox(unit * (centre - hB), unit * (centre + hB), boxDivisions(random));
  return meshPair(a, rigid(rotation, unit * where), b, rigid(rotation, unit * where), variant + ", through vertices");
}

Generated boxesTouching(SeededRandom& random, double s) { return boxesFacing(random, s, true); }
Generated boxesNear(SeededRandom& random, double s) { return boxesFacing(random, s, false); }

/// Issue 3: interpenetration. A vertex of B 1e-3 ... 1e-1 x the scene deep inside A (closed
/// shapes, random rotations): the surfaces cross with a margin, the answer must be exactly 0.
Generated interpenetrating(SeededRandom& random, double s) {
  std::string nameA, nameB;
  const Mesh a = randomShape(random, s, false, &nameA);
  const Mesh b = randomShape(random, s * random.uniform(0.3, 1.5), false, &nameB);
  const Pose poseA = rigid(randomRotation(random), s * random.inCube(1));
  const double depth = s * random.logUniform(-3, -1);
  // Thin shapes (tube radius 0.05 x size) may let the vertex out through the far side; B's edges
  // from it still cross A's surface twice, with margin, so the meshes still intersect robustly.
  const Pose poseB = overSurface(a, poseA, b, randomRotation(random), -depth, random);
  return meshPair(a, poseA, b, poseB, nameA + " pierced by " + nameB, true);
}

/// Issue 3: one mesh nested in the other's hull: a shape inside a room's cavity, inside a larger
/// closed shape, or inside the ring of a C, at 0 or 1e-14 ... 1e-1 x the scene from the wall.
Generated nested(SeededRandom& random, double s) {
  std::string gapName, nameB;
  const double gap = contactGap(random, s, gapName);
  const Mesh inner = randomShape(random, 0.3 * s, false, &nameB);
  const Eigen::Matrix3d innerRotation = randomRotation(random);
  const Pose world = rigid(randomRotation(random), s * random.inCube(1));
  switch (random.below(3)) {
    case 0: {
      const Vec3 cavity(s, 0.75 * s, 0.5 * s);
      const Mesh room = shapes::room(cavity, 0.1 * s, 1 + int(random.below(3)));
      // Against the wall x = +cavity.x (or another wall by an exact axis rotation of the room).
      const Vec3 target(cavity.x() - gap, random.uniform(-0.5, 0.5) * cavity.y(), random.uniform(-0.3, 0.3) * cavity.z());
      const Pose local = placeSupportAt(inner, innerRotation, -Vec3::UnitX(), target);
      return meshPair(room, world, inner, world * local, nameB + " in a room, " + gapName);
    }
    case 1: {
      std::string nameA;
      const Mesh outer = randomShape(random, 2 * s, true, &nameA);
      SurfacePoint p = randomSurfacePoint(outer, Pose::Identity(), random, 0.2);
      const Pose local = placeSupportAt(inner, innerRotation, -p.normal, p.point - gap * p.normal);
      return meshPair(outer, world, inner, world * local, nameB + " inside a " + nameA + ", " + gapName);
    }
    default: {
      const double radius = s, thickness = 0.25 * s;
      const Mesh c = shapes::cShape(radius, thickness, random.uniform(0.5, 2.0), 32);
      const double angle = random.uniform(2.0, 2 * M_PI - 2.0);  // inside the arc, away from the opening
      const Vec3 radial(std::cos(angle), std::sin(angle), 0.0);
      const Vec3 target = (radius - 0.5 * thickness - gap) * radial + Vec3(0, 0, random.uniform(-0.1, 0.1) * thickness);
      const Pose local = placeSupportAt(inner, innerRotation, -radial, target);
      return meshPair(c, world, inner, world * local, nameB + " in the ring of a C, " + gapName);
    }
  }
}

/// Issue 3: identical coincident meshes: the same mesh twice at the same pose, a permuted copy, the
/// copy baked into its vertex coordinates, or nudged by 1e-16 ... 1e-8 (rotation or translation).
Generated coincident(SeededRandom& random, double s) {
  // Coincident surfaces make the oracle evaluate every touching pair (each triangle against its
  // copy and the copy's neighbours) in binary128; the knotted tube and the torus (256+ triangles)
  // would make this one family cost as much as all the others, so shapes stay below 210 triangles.
  std::string name;
  Mesh a = randomShape(random, s, false, &name);
  while (a.triangleCount() > 210) a = randomShape(random, s, false, &name);
  const Pose pose = rigid(randomRotation(random), s * random.inCube(1));
  switch (random.below(5)) {
    case 0: return meshPair(a, pose, a, pose, name + ", identical");
    case 1: return meshPair(a, pose, permutedMesh(a, random), pose, name + ", permuted copy");
    case 2: return meshPair(a, pose, transformedMesh(a, pose), Pose::Identity(), name + ", baked copy");
    case 3: {
      const Pose nudge(Eigen::AngleAxisd(random.logUniform(-16, -8), random.unitVector()));
      return meshPair(a, pose, a, pose * nudge, name + ", rotated 1e-16..1e-8");
    }
    default: {
      const Pose nudge(Eigen::Translation3d(s * random.logUniform(-16, -8) * random.unitVector()));
      return meshPair(a, pose, a, pose * nudge, name + ", shifted 1e-16..1e-8");
    }
  }
}

/// A close pair of random shapes at the origin: B over A's surface at a contact gap (or 1e-3 ...
/// 1e-1 deep), both turned at random. Shared by the offset families.
struct ClosePair {
  Mesh a, b;
  Pose poseA, poseB;
  std::string variant;
  bool penetrating;
};

ClosePair closePair(SeededRandom& random, double s) {
  std::string nameA, nameB, gapName;
  Mesh a = randomShape(random, s, false, &nameA);
  Mesh b = randomShape(random, s * random.uniform(0.3, 1.5), false, &nameB);
  double gap = contactGap(random, s, gapName);
  bool penetrating = false;
  if (random.below(5) == 0) {
    gap = -s * random.logUniform(-3, -1);
    gapName = "penetrating";
    penetrating = true;
  }
  const Pose poseA = rigid(randomRotation(random), Vec3::Zero());
  const Pose poseB = overSurface(a, poseA, b, randomRotation(random), gap, random);
  return {std::move(a), std::move(b), poseA, poseB, nameA + " and " + nameB + ", " + gapName, penetrating};
}

/// Issue 3: large offsets through the poses: the close pair moved by a common rigid motion whose
/// translation is 1e3 ... 1e8 x the scene.
Generated offsetPoses(SeededRandom& random, double s) {
  ClosePair c = closePair(random, s);
  const Pose motion = rigid(randomRotation(random), s * random.logUniform(3, 8) * random.unitVector());
  return meshPair(std::move(c.a), motion * c.poseA, std::move(c.b), motion * c.poseB, c.variant, c.penetrating);
}

/// Issue 3: large offsets through the vertex coordinates: the close pair baked into its vertices and
/// shifted by 1e3 ... 1e8 x the scene, the two mesh frames related exactly (equal poses that are
/// pure translations): identity poses, poses that translate both meshes back near the origin, or
/// one common translation anywhere.
Generated offsetVertices(SeededRandom& random, double s) {
  ClosePair c = closePair(random, s);
  const Vec3 offset = s * random.logUniform(3, 8) * random.unitVector();
  const Mesh a = offsetMesh(transformedMesh(c.a, c.poseA), offset);
  const Mesh b = offsetMesh(transformedMesh(c.b, c.poseB), offset);
  switch (random.below(3)) {
    case 0: return meshPair(a, Pose::Identity(), b, Pose::Identity(), c.variant + ", identity poses", c.penetrating);
    case 1: {
      const Pose back(Eigen::Translation3d(-offset));
      return meshPair(a, back, b, back, c.variant + ", translated back", c.penetrating);
    }
    default: {
      const Pose common(Eigen::Translation3d(s * random.logUniform(0, 8) * random.unitVector()));
      return meshPair(a, common, b, common, c.variant + ", common translation", c.penetrating);
    }
  }
}

/// Issue 3: large offsets through the vertex coordinates with mesh frames that are NOT related
/// exactly: the close pair baked into its vertices 1e3 ... 1e8 x the scene from the origin under
/// one common random rotation (R_A^T R_B is the identity only up to rounding), or each mesh
/// shifted by its own offset and translated back next to the other (in A's frame B's vertices are
/// as far out as the offsets).
Generated offsetFrames(SeededRandom& random, double s) {
  ClosePair c = closePair(random, s);
  const Vec3 offset = s * random.logUniform(3, 8) * random.unitVector();
  const Mesh a = offsetMesh(transformedMesh(c.a, c.poseA), offset);
  if (random.below(2)) {
    const Mesh b = offsetMesh(transformedMesh(c.b, c.poseB), offset);
    const Pose common = rigid(randomRotation(random), s * random.inCube(1));
    return meshPair(a, common, b, common, c.variant + ", common rotation", c.penetrating);
  }
  const Vec3 otherOffset = s * random.logUniform(3, 8) * random.unitVector();
  const Mesh b = offsetMesh(transformedMesh(c.b, c.poseB), otherOffset);
  return meshPair(a, Pose(Eigen::Translation3d(-offset)), b, Pose(Eigen::Translation3d(-otherOffset)),
                  c.variant + ", separate offsets", c.penetrating);
}

/// A box, a plate or a prism lying on its side: shapes with flat faces along the axes.
Mesh flatFacedShape(SeededRandom& random, double s, std::string& name) {
  switch (random.below(3)) {
    case 0: {
      const Vec3 h = s * Vec3(random.uniform(0.2, 1), random.uniform(0.2, 1), random.uniform(0.2, 1));
      name = "grid box";
      return gridBox(-h, h, boxDivisions(random));
    }
    case 1: {
      const int n = 1 + int(random.below(6));
      name = "plate";
      return plate(Vec3(-s, -s, 0), Vec3(2 * s, 0, 0), Vec3(0, 2 * s, 0), n, n);
    }
    default: {
      // Along x, an even number of sides so that one side face is exactly horizontal... up to the
      // rounding of cos and sin, which is the point.
      name = "prism on its side";
      const Mesh p = polygonPrism(0.5 * s, 2 * (3 + int(random.below(14))), 2 * s, 1 + int(random.below(4)));
      return transformedMesh(p, Pose(Eigen::Translation3d(-s, 0, 0) * Eigen::AngleAxisd(M_PI / 2, Vec3::UnitY())));
    }
  }
}

/// B over A's top (+z side), B's lowest vertex at `gap` above the highest point of A's hull under
/// it... precisely: B turned by `rotation` is translated so that its lowest vertex sits at
/// (x, y, top of A + gap) for a random (x, y) over A's box.
Pose overTop(const Mesh& a, const Mesh& b, const Eigen::Matrix3d& rotation, double gap, SeededRandom& random) {
  const Eigen::AlignedBox3d box = a.bounds();
  const Vec3 target(random.uniform(box.min().x(), box.max().x()), random.uniform(box.min().y(), box.max().y()),
                    box.max().z() + gap);
  return placeSupportAt(b, rotation, Vec3::UnitZ(), target);
}

/// Issue 3: rotations near identity: flat faces over flat faces with B turned by 1e-16 ... 1e-3 rad
/// (about a random or a coordinate axis), so faces are nearly parallel and supports nearly tied.
Generated rotationNearIdentity(SeededRandom& random, double s) {
  std::string nameA, nameB, gapName;
  const Mesh a = flatFacedShape(random, s, nameA), b = flatFacedShape(random, s, nameB);
  const double gap = contactGap(random, s, gapName);
  const Vec3 axis = random.below(2) ? random.unitVector() : Vec3(Vec3::Unit(int(random.below(3))));
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(random.logUniform(-16, -3), axis).toRotationMatrix();
  const Pose world = rigid(random.below(2) ? randomRotation(random) : axisRotation(random), s * random.inCube(1));
  return meshPair(a, world, b, world * overTop(a, b, turn, gap, random), nameA + " under " + nameB + ", " + gapName);
}

/// Issue 3: rotations near 180 degrees: B turned by pi - delta (delta 0 or 1e-16 ... 1e-3) about a
/// coordinate axis, a diagonal or a random axis (quaternion w near 0), over A's flat top or over a
/// random surface point of a random shape; sometimes A's pose is near 180 degrees too.
Generated rotationNear180(SeededRandom& random, double s) {
  auto near180 = [&random]() -> Eigen::Matrix3d {
    Vec3 axis;
    switch (random.below(3)) {
      case 0: axis = Vec3::Unit(int(random.below(3))); break;
      case 1: axis = Vec3(1, random.below(2) ? 1 : -1, random.below(3) ? 0 : 1).normalized(); break;
      default: axis = random.unitVector(); break;
    }
    const double delta = random.below(4) == 0 ? 0.0 : random.logUniform(-16, -3);
    return Eigen::AngleAxisd(M_PI - delta, axis).toRotationMatrix();
  };
  std::string gapName, nameA, nameB;
  const double gap = contactGap(random, s, gapName);
  const Pose world = rigid(random.below(2) ? near180() : Eigen::Matrix3d::Identity(), s * random.inCube(1));
  if (random.below(2)) {
    const Mesh a = flatFacedShape(random, s, nameA), b = flatFacedShape(random, s, nameB);
    return meshPair(a, world, b, world * overTop(a, b, near180(), gap, random), nameA + " under " + nameB + ", " + gapName);
  }
  const Mesh a = randomShape(random, s, false, &nameA), b = randomShape(random, s, false, &nameB);
  return meshPair(a, world, b, world * overSurface(a, Pose::Identity(), b, near180(), gap, random),
                  nameA + " and " + nameB + ", " + gapName);
}

/// A fan of triangles (centre, p_k, p_k+1) over a regular n-gon: n + 1 coplanar vertices, n of
/// them on one circle.
Mesh polygonFan(double radius, int sides) {
  std::vector<Vec3> vertices{Vec3::Zero()};
  std::vector<TriangleIndices> triangles;
  for (int k = 0; k < sides; ++k) {
    const double angle = 2.0 * M_PI * k / sides;
    vertices.emplace_back(radius * std::cos(angle), radius * std::sin(angle), 0.0);
    triangles.push_back({0u, std::uint32_t(1 + k), std::uint32_t(1 + (k + 1) % sides)});
  }
  return Mesh(std::move(vertices), std::move(triangles), "polygon fan");
}

/// A comb: triangles (p_i, p_i+1, apex_i) with all p_i on one line segment (collinear supports).
Mesh collinearComb(double length, int teeth, double height) {
  std::vector<Vec3> vertices;
  std::vector<TriangleIndices> triangles;
  for (int i = 0; i <= teeth; ++i) vertices.emplace_back(-0.5 * length + length * (double(i) / teeth), 0.0, 0.0);
  for (int i = 0; i < teeth; ++i) {
    vertices.emplace_back(-0.5 * length + length * ((i + 0.5) / teeth), 0.3 * height * ((i % 3) - 1), height);
    triangles.push_back({std::uint32_t(i), std::uint32_t(i + 1), std::uint32_t(teeth + 1 + i)});
  }
  return Mesh(std::move(vertices), std::move(triangles), "comb");
}

/// Issue 3: GJK-hostile sets: many coplanar vertices on the support plane (parallel and coplanar
/// grid plates, regular polygon fans), collinear support points (prisms on their side, combs),
/// duplicate support points (every vertex stored several times), facing each other at 0 or
/// 1e-14 ... 1e-1 x the scene, exactly axis-aligned or under one common random rotation.
Generated gjkHostile(SeededRandom& random, double s) {
  std::string gapName;
  double gap = contactGap(random, s, gapName);
  const Pose world = rigid(random.below(2) ? randomRotation(random) : axisRotation(random), s * random.inCube(1));
  switch (random.below(5)) {
    case 0: {
      const int na = 1 + int(random.below(8)), nb = 1 + int(random.below(8));
      const Mesh a = plate(Vec3(-s, -s, 0), Vec3(2 * s, 0, 0), Vec3(0, 2 * s, 0), na, na);
      if (random.below(4) == 0) gap = 0.0, gapName = "coplanar";  // the same plane
      const Vec3 shift(s * random.uniform(-1.5, 1.5), s * random.uniform(-1.5, 1.5), gap);
      const Mesh b = plate(Vec3(-s, -s, 0), Vec3(2 * s, 0, 0), Vec3(0, 2 * s, 0), nb, nb);
      const Eigen::Matrix3d turn = random.below(2) ? Eigen::Matrix3d::Identity() : Eigen::Matrix3d(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ()));
      return meshPair(a, world, b, world * rigid(turn, shift), "parallel plates, " + gapName);
    }
    case 1: {
      std::string name;
      const Mesh a = flatFacedShape(random, s, name);
      const Mesh prism = polygonPrism(0.3 * s, 8 * (2 + int(random.below(7))), 1.5 * s, 2 + int(random.below(5)));
      const Eigen::Matrix3d onSide = Eigen::AngleAxisd(M_PI / 2, Vec3::UnitY()).toRotationMatrix();
      return meshPair(a, world, prism, world * overTop(a, prism, onSide, gap, random), "prism on its side over a " + name + ", " + gapName);
    }
    case 2: {
      const Vec3 hA = s * Vec3(random.uniform(0.3, 1), random.uniform(0.3, 1), random.uniform(0.3, 1));
      const Vec3 hB = s * Vec3(random.uniform(0.3, 1), random.uniform(0.3, 1), random.uniform(0.3, 1));
      const Mesh a = withRepeatedVertices(gridBox(-hA, hA, boxDivisions(random)), 2 + int(random.below(3)), random);
      const Mesh b = withRepeatedVertices(gridBox(-hB, hB, boxDivisions(random)), 2 + int(random.below(3)), random);
      return meshPair(a, world, b, world * overTop(a, b, Eigen::Matrix3d::Identity(), gap, random), "repeated vertices, " + gapName);
    }
    case 3: {
      const Mesh a = polygonFan(s, 8 + int(random.below(57)));
      const Mesh b = polygonFan(s * random.uniform(0.3, 1.2), 8 + int(random.below(57)));
      // Face to face (parallel planes) or edge-on (B's plane vertical, its rim towards A).
      const Eigen::Matrix3d turn = random.below(2) ? Eigen::Matrix3d::Identity() : Eigen::Matrix3d(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitX()));
      return meshPair(a, world, b, world * overTop(a, b, turn, gap, random), "polygon fans, " + gapName);
    }
    default: {
      const Mesh comb = collinearComb(2 * s, 4 + int(random.below(29)), 0.5 * s);
      const Mesh a = plate(Vec3(-s, -s, 0), Vec3(2 * s, 0, 0), Vec3(0, 2 * s, 0), 2, 2);
      // The comb's line of collinear vertices lies flat, parallel to the plate.
      return meshPair(a, world, comb, world * overTop(a, comb, Eigen::Matrix3d::Identity(), gap, random), "comb over a plate, " + gapName);
    }
  }
}

/// A soup of n triangles in the cube of half side h around centre: regular ones, slivers,
/// needles, repeated-corner segments, points and collinear triples, often sharing vertices.
Mesh degenerateSoup(SeededRandom& random, int n, double h, const Vec3& centre) {
  std::vector<Vec3> vertices;
  std::vector<TriangleIndices> triangles;
  auto add = [&](const Vec3& p) {
    vertices.push_back(p);
    return static_cast<std::uint32_t>(vertices.size() - 1);
  };
  auto anyVertex = [&]() -> std::uint32_t {
    if (!vertices.empty() && random.below(3) == 0) return static_cast<std::uint32_t>(random.below(vertices.size()));
    return add(centre + random.inCube(h));
  };
  for (int i = 0; i < n; ++i) {
    const std::uint32_t p = anyVertex(), q = anyVertex();
    switch (random.below(6)) {
      case 0: triangles.push_back({p, q, anyVertex()}); break;  // regular (or sharing corners)
      case 1: {  // sliver: third corner 1e-16 ... 1e-6 x h off the line pq
        const Vec3 d = vertices[q] - vertices[p];
        const Vec3 off = d.norm() > 0 ? perpendicularTo(d.normalized(), random) : random.unitVector();
        triangles.push_back({p, q, add(vertices[p] + random.uniform(-0.5, 1.5) * d + h * random.logUniform(-16, -6) * off)});
        break;
      }
      case 2: triangles.push_back({p, add(vertices[p] + h * random.logUniform(-12, -4) * random.unitVector()), q}); break;  // needle
      case 3: triangles.push_back({p, q, q}); break;  // repeated corner: a segment
      case 4: triangles.push_back({p, p, p}); break;  // a point
      default: triangles.push_back({p, q, add(vertices[p] + random.uniform(-0.5, 1.5) * (vertices[q] - vertices[p]))});  // collinear
    }
  }
  return Mesh(std::move(vertices), std::move(triangles), "degenerate soup");
}

/// A closed shape whose edges are also present as zero-area triangles (i, j, j): what CAD exports
/// and decimators leave behind.
Mesh withZeroAreaEdges(const Mesh& mesh, SeededRandom& random) {
  std::vector<TriangleIndices> triangles = mesh.triangles();
  for (const TriangleIndices& t : mesh.triangles()) {
    if (random.below(3) == 0) triangles.push_back({t[0], t[1], t[1]});
  }
  return Mesh(mesh.vertices(), std::move(triangles), mesh.name() + " with zero-area edges");
}

/// Issue 3: slivers, needles and zero-area triangles, repeated vertices, at the mesh level: two
/// soups whose boxes overlap, or closed shapes carrying zero-area edge triangles near contact.
Generated degenerateMeshes(SeededRandom& random, double s) {
  const Pose world = rigid(randomRotation(random), s * random.inCube(1));
  if (random.below(2)) {
    const Mesh a = degenerateSoup(random, 8 + int(random.below(33)), s, Vec3::Zero());
    const Mesh b = degenerateSoup(random, 8 + int(random.below(33)), s, s * random.uniform(0.5, 2.0) * random.unitVector());
    return meshPair(a, world, b, world, "soups");
  }
  std::string nameA, nameB, gapName;
  const Mesh a = withZeroAreaEdges(randomShape(random, s, false, &nameA), random);
  const Mesh b = withZeroAreaEdges(randomShape(random, s, false, &nameB), random);
  const double gap = contactGap(random, s, gapName);
  return meshPair(a, world, b, world * overSurface(a, Pose::Identity(), b, randomRotation(random), gap, random),
                  nameA + " and " + nameB + " with zero-area edges, " + gapName);
}

/// Issue 3: tiny features (1e-8 ... 1e-6 x the scene) next to large ones: a spike on a box's top,
/// or a tiny triangle floating over it, with a shape coming down onto the tiny feature at 0 or
/// 1e-14 ... 1e-4 x the scene.
Generated tinyFeatures(SeededRandom& random, double s) {
  const double tiny = s * random.logUniform(-8, -6);
  const Vec3 h = s * Vec3(random.uniform(0.3, 1), random.uniform(0.3, 1), random.uniform(0.2, 0.5));
  const Mesh box = gridBox(-h, h, boxDivisions(random));
  const Vec3 spot(random.uniform(-0.8, 0.8) * h.x(), random.uniform(-0.8, 0.8) * h.y(), h.z());
  Vec3 apex;
  Mesh feature = box;
  std::string variant;
  if (random.below(2)) {
    // A spike: a thin tetrahedron standing on the top face, apex `tiny` above it.
    apex = spot + Vec3(0, 0, tiny);
    const Vec3 e = 0.3 * tiny * random.unitVector().cross(Vec3::UnitZ()).normalized(), f = Vec3::UnitZ().cross(e);
    feature = Mesh({spot + e, spot - 0.5 * e + f, spot - 0.5 * e - f, apex}, {{0, 1, 3}, {1, 2, 3}, {2, 0, 3}, {0, 2, 1}}, "spike");
    variant = "spike";
  } else {
    // A tiny triangle floating 1e-4 ... 1e-1 x the scene over the top face.
    const Vec3 base = spot + Vec3(0, 0, s * random.logUniform(-4, -1));
    apex = base + Vec3(0, 0, 0.5 * tiny);
    feature = Mesh({base + tiny * random.unitVector().cwiseProduct(Vec3(1, 1, 0)), base - 0.5 * tiny * Vec3(1, 1, 0), apex},
                   {{0, 1, 2}}, "tiny triangle");
    variant = "floating tiny triangle";
  }
  const Mesh a = mergedMesh(box, feature, "box with a tiny feature");
  std::string name;
  const Mesh b = randomShape(random, s * random.uniform(0.3, 1.0), true, &name);
  const double gap = random.below(6) == 0 ? 0.0 : s * random.logUniform(-14, -4);
  const Pose world = rigid(randomRotation(random), s * random.inCube(1));
  const Pose local = placeSupportAt(b, randomRotation(random), Vec3::UnitZ(), apex + Vec3(0, 0, gap));
  if (random.below(2)) return meshPair(a, world, b, world * local, variant + " under a " + name);
  return meshPair(b, world * local, a, world, name + " over a " + variant);
}

/// Issue 3: touching and near contact of generic shapes (convex or not, random rotations): a vertex
/// of B over a random surface point of A at 0 or 1e-14 ... 1e-6 x the scene.
Generated nearContact(SeededRandom& random, double s) {
  std::string nameA, nameB;
  const Mesh a = randomShape(random, s, false, &nameA), b = randomShape(random, s * random.uniform(0.3, 1.5), false, &nameB);
  const double gap = random.below(5) == 0 ? 0.0 : s * random.logUniform(-14, -6);
  const Pose poseA = rigid(randomRotation(random), s * random.inCube(1));
  return meshPair(a, poseA, b, overSurface(a, poseA, b, randomRotation(random), gap, random),
                  nameA + " and " + nameB + (gap == 0 ? ", touching" : ", near"));
}

/// Issue 3: scales: a large shape and one 1e-6 ... 1e-2 of its size, at 0 or 1e-10 ... 1 of the
/// small one's size apart, or 0.3 of it deep.
Generated mixedScales(SeededRandom& random, double s) {
  std::string nameA, nameB;
  const double small = s * random.logUniform(-6, -2);
  const Mesh a = randomShape(random, s, false, &nameA), b = randomShape(random, small, false, &nameB);
  double gap = random.below(5) == 0 ? 0.0 : small * random.logUniform(-10, 0);
  if (random.below(6) == 0) gap = -0.3 * small;
  const Pose poseA = rigid(randomRotation(random), s * random.inCube(1));
  const Pose poseB = overSurface(a, poseA, b, randomRotation(random), gap, random);
  if (random.below(2)) return meshPair(b, poseB, a, poseA, "small " + nameB + " and large " + nameA);
  return meshPair(a, poseA, b, poseB, "large " + nameA + " and small " + nameB);
}

}  // namespace

std::vector<Family> meshFamilies() {
  std::vector<Family> f;
  f.push_back({"mesh/boxes-touching", "axis-aligned grid boxes exactly touching face/edge/corner, exact poses or vertices, offsets to 1e8",
               -6, 6, {0.6, 0.0, 0.05}, boxesTouching});
  f.push_back({"mesh/boxes-near", "axis-aligned grid boxes 1e-14..1e-6 x scene apart, exactly parallel faces",
               -6, 6, {0.0, 0.6, 0.05}, boxesNear});
  f.push_back({"mesh/interpenetrating", "closed shapes, a vertex 1e-3..1e-1 x scene deep: must be exactly 0",
               -6, 6, {0.95, 0.0, 0.0}, interpenetrating});
  f.push_back({"mesh/nested", "a shape inside a room, inside a larger shape, in a C's ring: 0..1e-1 x scene from the wall",
               -6, 6, {0.05, 0.2, 0.07}, nested});
  f.push_back({"mesh/coincident", "identical meshes at one pose, permuted or baked copies, nudged by 1e-16..1e-8",
               -6, 6, {0.7, 0.0, 0.0}, coincident});
  f.push_back({"mesh/offset-poses", "close pairs moved 1e3..1e8 x scene by a common rigid motion (poses)",
               -6, 6, {0.1, 0.2, 0.08}, offsetPoses});
  f.push_back({"mesh/offset-vertices", "close pairs baked into vertices 1e3..1e8 x scene out, frames related exactly",
               -6, 6, {0.1, 0.1, 0.07}, offsetVertices});
  f.push_back({"mesh/offset-frames", "the same with one common rotation, or separate offsets translated back",
               -6, 6, {0.1, 0.1, 0.07}, offsetFrames});
  f.push_back({"mesh/rotation-near-identity", "flat faces over flat faces turned by 1e-16..1e-3 rad",
               -6, 6, {0.05, 0.2, 0.2}, rotationNearIdentity});
  f.push_back({"mesh/rotation-near-180", "B (and sometimes A) turned by pi - (0 or 1e-16..1e-3) rad",
               -6, 6, {0.05, 0.2, 0.2}, rotationNear180});
  f.push_back({"mesh/gjk-hostile", "coplanar grids and fans, collinear prisms and combs, repeated vertices, facing",
               -6, 6, {0.1, 0.2, 0.2}, gjkHostile});
  f.push_back({"mesh/degenerate", "soups of slivers, needles, segments, points; shapes with zero-area edge triangles",
               -6, 6, {0.1, 0.0, 0.1}, degenerateMeshes});
  f.push_back({"mesh/tiny-features", "a 1e-8..1e-6 x scene spike or floating triangle, a shape 0..1e-4 x scene above it",
               -6, 6, {0.02, 0.3, 0.06}, tinyFeatures});
  f.push_back({"mesh/near-contact", "generic shapes (convex or not), a vertex 0 or 1e-14..1e-6 x scene over a face",
               -6, 6, {0.05, 0.5, 0.0}, nearContact});
  f.push_back({"mesh/mixed-scales", "a shape next to one 1e-6..1e-2 of its size, touching, near, apart or pierced",
               -6, 6, {0.05, 0.2, 0.06}, mixedScales});
  return f;
}

}  // namespace adsd::stress
