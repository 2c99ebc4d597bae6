#include "adsd/mesh_hierarchy.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>

#include <Eigen/Eigenvalues>

#include "adsd/tolerances.h"

namespace adsd {

namespace {

/// Widens a box by a few units of roundoff of its coordinates, so that rounding in the
/// projections never leaves a vertex outside it (its bounds prune with the query's own roundoff
/// allowance on top).
void pad(OrientedBox& box) {
  const double slack = 8.0 * tolerance::kEpsilon * (box.center.cwiseAbs().maxCoeff() + box.half.maxCoeff());
  box.half.array() += slack;
  box.radius = box.half.norm();
}

/// The extents of `points` along fixed axes.
template <class Points>
void fitExtents(OrientedBox& box, const Points& points) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 hi = -lo;
  for (const Vec3& p : points) {
    const Vec3 q = box.axes.transpose() * p;
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  box.center = box.axes * (0.5 * (lo + hi));
  box.half = 0.5 * (hi - lo);
  pad(box);
}

/// The box of a point set along its principal axes (eigenvectors of the covariance).
OrientedBox principalBox(const std::vector<Vec3>& points) {
  OrientedBox box;
  Vec3 mean = Vec3::Zero();
  for (const Vec3& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const Vec3& p : points) covariance += (p - mean) * (p - mean).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(covariance);
  // The closed-form solver's eigenvectors are orthonormal only to ~1e-9 at times, and a box on
  // skewed axes does not hold what its support formula says (tests/stress: "tree node boxes
  // contain their vertices"). Re-orthonormalize (Gram-Schmidt, the third axis a cross product),
  // so the axes are a rotation to roundoff and pad() covers the rest.
  const Eigen::Matrix3d raw = solver.eigenvectors();
  Vec3 x = raw.col(0);
  Vec3 y = raw.col(1);
  if (raw.allFinite() && x.norm() > 0.5) {
    x.normalize();
    y -= x.dot(y) * x;
  }
  if (raw.allFinite() && x.norm() > 0.5 && y.norm() > 0.5) {
    y.normalize();
    box.axes.col(0) = x;
    box.axes.col(1) = y;
    box.axes.col(2) = x.cross(y);
  } else {
    // Degenerate spreads (a point, a segment) can leave the solver's axes unusable: the mesh
    // axes bound just as correctly.
    box.axes.setIdentity();
  }
  fitExtents(box, points);
  return box;
}

/// Whether two of triangles order[t0, t1) face directions more than MeshHierarchy::kFoldCosine
/// apart (Node::folded). Triangles without area have no direction and fold nothing.
bool isFolded(const Mesh& mesh, const std::uint32_t* order, std::uint32_t t0, std::uint32_t t1) {
  std::array<Vec3, MeshHierarchy::kLeafTriangles> normals;
  std::uint32_t count = 0;
  for (std::uint32_t i = t0; i < t1; ++i) {
    const std::uint32_t t = order[i];
    const Vec3 n = (mesh.corner(t, 1) - mesh.corner(t, 0)).cross(mesh.corner(t, 2) - mesh.corner(t, 0));
    const double length = n.norm();
    if (length > 0.0 && std::isfinite(length)) normals[count++] = n / length;
  }
  for (std::uint32_t i = 0; i < count; ++i) {
    for (std::uint32_t j = i + 1; j < count; ++j) {
      if (normals[i].dot(normals[j]) < MeshHierarchy::kFoldCosine) return true;
    }
  }
  return false;
}

/// Whether every edge of triangles order[0, count) of \p mesh (by vertex index) belongs to
/// exactly two of them: no hole.
bool isClosed(const Mesh& mesh, const std::uint32_t* order, std::size_t count) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  edges.reserve(3 * count);
  for (std::size_t i = 0; i < count; ++i) {
    const TriangleIndices& t = mesh.triangles()[order[i]];
    for (int k = 0; k < 3; ++k) edges.emplace_back(std::minmax(t[k], t[(k + 1) % 3]));
  }
  std::sort(edges.begin(), edges.end());
  for (std::size_t i = 0; i < edges.size(); i += 2) {
    if (i + 1 >= edges.size() || edges[i] != edges[i + 1] || (i + 2 < edges.size() && edges[i + 2] == edges[i])) {
      return false;
    }
  }
  return !edges.empty();
}

/// Triangle t's plane as its unit normal and offset (unit.x = offset on it); false when it has
/// none (no area), and then it constrains nothing.
bool trianglePlane(const Mesh& mesh, std::uint32_t t, Vec3& unit, double& offset) {
  const Vec3 a = mesh.corner(t, 0);
  const Vec3 n = (mesh.corner(t, 1) - a).cross(mesh.corner(t, 2) - a);
  const double length = n.norm();
  if (!(length > 0.0) || !std::isfinite(length)) return false;
  unit = n / length;
  offset = unit.dot(a);
  return true;
}

/// Whether every triangle of order[0, count) with an area has all of \p points on one side of its
/// plane. A point within 1e-9 of \p extent of a plane is on it: only the hull's own faces pass,
/// and a vertex that rounding left on the wrong side by a hair keeps a real convex part in.
template <class Points>
bool pointsOnOneSideOfEveryFace(const Mesh& mesh, const std::uint32_t* order, std::size_t count, const Points& points,
                                double extent) {
  if (!(extent > 0.0) || !std::isfinite(extent)) return false;
  const double onPlane = 1e-9 * extent;
  for (std::size_t i = 0; i < count; ++i) {
    Vec3 unit;
    double offset = 0.0;
    if (!trianglePlane(mesh, order[i], unit, offset)) continue;
    bool above = false, below = false;
    for (const Vec3& v : points) {
      const double h = unit.dot(v) - offset;
      above = above || h > onPlane;
      below = below || h < -onPlane;
    }
    if (above && below) return false;
  }
  return true;
}

/// Connected components of a mesh's triangles (sharing a vertex index, transitively): union-find
/// over the vertices, each triangle labelled by its first corner's root, then numbered densely.
std::vector<std::uint32_t> triangleComponents(const Mesh& mesh, std::uint32_t& count) {
  std::vector<std::uint32_t> parent(mesh.vertices().size());
  std::iota(parent.begin(), parent.end(), 0u);
  auto root = [&](std::uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const TriangleIndices& t : mesh.triangles()) {
    for (int k = 1; k < 3; ++k) {
      const std::uint32_t x = root(t[0]), y = root(t[k]);
      if (x != y) parent[std::max(x, y)] = std::min(x, y);
    }
  }
  std::vector<std::uint32_t> label(mesh.vertices().size(), UINT32_MAX), component(mesh.triangleCount());
  count = 0;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const std::uint32_t r = root(mesh.triangles()[t][0]);
    if (label[r] == UINT32_MAX) label[r] = count++;
    component[t] = label[r];
  }
  return component;
}

}  // namespace

// O(triangles x vertices), hence only for small meshes. Closed, because a hole where the hull is
// nearest (a wall cut in two by a planner's scene splitter, an open box) leaves the hulls nearer
// than the surfaces, and a query's try of GJK on the vertices (convex_pair.cpp) would be lost.
bool isClosedConvex(const Mesh& mesh) {
  const std::vector<Vec3>& vertices = mesh.vertices();
  if (vertices.empty() || vertices.size() > MeshHierarchy::kConvexCheckVertices) return false;
  std::vector<std::uint32_t> all(mesh.triangleCount());
  std::iota(all.begin(), all.end(), 0u);
  return isClosed(mesh, all.data(), all.size()) &&
         pointsOnOneSideOfEveryFace(mesh, all.data(), all.size(), vertices, mesh.bounds().sizes().maxCoeff());
}

MeshHierarchy::MeshHierarchy(const Mesh& mesh) {
  order_.resize(mesh.triangleCount());
  std::iota(order_.begin(), order_.end(), 0u);
  nodes_.reserve(2 * (mesh.triangleCount() / kLeafTriangles + 1));
  Components components;
  std::uint32_t count = 0;
  components.ofTriangle = triangleComponents(mesh, count);
  components.size.assign(count, 0);
  components.centroid.assign(count, Vec3::Zero());
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const std::uint32_t c = components.ofTriangle[t];
    ++components.size[c];
    components.centroid[c] += mesh.corner(t, 0) + mesh.corner(t, 1) + mesh.corner(t, 2);
  }
  for (std::uint32_t c = 0; c < count; ++c) components.centroid[c] /= 3.0 * components.size[c];
  std::vector<std::uint32_t> marks(mesh.vertices().size(), UINT32_MAX);
  build(mesh, components, 0, static_cast<std::uint32_t>(mesh.triangleCount()), 1, marks);
  positionInOrder_.resize(order_.size());
  for (std::uint32_t i = 0; i < order_.size(); ++i) positionInOrder_[order_[i]] = i;
  onHullBoundary_ = wholeMeshConvex(mesh);
}

bool MeshHierarchy::wholeMeshConvex(const Mesh& mesh) const {
  // The root's flag is isClosedConvex(mesh) on a connected mesh (a mesh of several components is
  // not its hull's boundary), but over the vertices the triangles use. settleConvexPair scans
  // every vertex of the mesh per support and offers the closest support points as a distance
  // between the surfaces, so a vertex no triangle uses must not exist: off the surface, it would
  // be offered as a surface point (a box with one stray vertex above it answered 4.24 for 8).
  if (nodes_.empty() || mesh.vertices().size() > kConvexCheckVertices) return false;
  if (nodes_[0].span != ComponentSpan::whole || !nodes_[0].convexSolid) return false;
  std::vector<bool> used(mesh.vertices().size(), false);
  for (const TriangleIndices& t : mesh.triangles()) {
    for (std::uint32_t v : t) used[v] = true;
  }
  return std::all_of(used.begin(), used.end(), [](bool u) { return u; });
}

MeshHierarchy::ComponentSpan MeshHierarchy::spanOf(const Components& components, const Node& node) const {
  const std::uint32_t c = components.ofTriangle[order_[node.t0]];
  for (std::uint32_t i = node.t0; i < node.t1; ++i) {
    if (components.ofTriangle[order_[i]] != c) return ComponentSpan::several;
  }
  return components.size[c] == node.t1 - node.t0 ? ComponentSpan::whole : ComponentSpan::part;
}

bool MeshHierarchy::nothingBeyond(const Mesh& mesh, std::int32_t index, const Vec3& d, double level) const {
  // Depth first; each node opened pushes its two children, so the stack holds at most one more
  // entry than the tree has levels.
  std::int32_t stack[kMaxTreeLevels + 2];
  int size = 0;
  stack[size++] = index;
  while (size > 0) {
    const Node& node = nodes_[stack[--size]];
    if (node.box.support(d) <= level) continue;
    if (!node.isLeaf()) {
      stack[size++] = node.left;
      stack[size++] = node.right;
      continue;
    }
    for (std::uint32_t k = node.v0; k < node.v1; ++k) {
      if (d.dot(mesh.vertices()[leafVertices_[k]]) > level) return false;
    }
  }
  return true;
}

bool MeshHierarchy::isConvexSolid(const Mesh& mesh, std::int32_t index) const {
  // A closed mesh of V vertices and genus 0 has 2V - 4 triangles: the vertex limit, by triangles.
  const Node& node = nodes_[index];
  const std::size_t count = node.t1 - node.t0;
  if (count > 2 * kConvexCheckVertices) return false;
  const std::uint32_t* range = order_.data() + node.t0;
  const double extent = 2.0 * node.box.half.maxCoeff();
  if (!(extent > 0.0) || !std::isfinite(extent)) return false;
  // Every triangle's plane with all the node's vertices on one side, as pointsOnOneSideOfEveryFace
  // checks, but each side by a search down the node's subtree that skips boxes within the side:
  // near a face of a convex solid only the boxes around it reach past its plane, so a face costs
  // a few leaves instead of every vertex (a capsule of 970 vertices, built and refitted in a
  // timing loop: 6 and 4.6 ms with the scan over every vertex, 3.2 and 2.6 ms with this).
  const double onPlane = 1e-9 * extent;
  for (std::size_t i = 0; i < count; ++i) {
    Vec3 unit;
    double offset = 0.0;
    if (!trianglePlane(mesh, range[i], unit, offset)) continue;
    if (!nothingBeyond(mesh, index, unit, offset + onPlane) && !nothingBeyond(mesh, index, -unit, onPlane - offset)) {
      return false;
    }
  }
  // Closed last: refit checks every whole component again, and a part that is not convex fails
  // above at its first folding face, before the edges are sorted.
  return isClosed(mesh, range, count);
}

std::uint32_t MeshHierarchy::splitBetweenComponents(const Components& components, std::uint32_t t0, std::uint32_t t1,
                                                    const Vec3& axis) {
  const std::vector<std::uint32_t>& component = components.ofTriangle;
  const std::uint32_t first = component[order_[t0]];
  if (std::all_of(order_.begin() + t0, order_.begin() + t1, [&](std::uint32_t t) { return component[t] == first; })) {
    return t0;
  }
  // Components by their centroids along the axis (ties by number, so each is contiguous).
  auto key = [&](std::uint32_t t) { return std::make_pair(axis.dot(components.centroid[component[t]]), component[t]); };
  auto before = [&](std::uint32_t s, std::uint32_t t) { return key(s) < key(t); };
  const std::uint32_t mid = t0 + (t1 - t0) / 2;
  std::nth_element(order_.begin() + t0, order_.begin() + mid, order_.begin() + t1, before);
  // The component at the middle goes whole to the smaller side.
  const auto middle = key(order_[mid]);
  const auto lowEnd = std::partition(order_.begin() + t0, order_.begin() + t1, [&](std::uint32_t t) { return key(t) < middle; });
  const auto middleEnd = std::partition(lowEnd, order_.begin() + t1, [&](std::uint32_t t) { return key(t) == middle; });
  const auto low = static_cast<std::uint32_t>(lowEnd - order_.begin());
  const auto high = static_cast<std::uint32_t>(middleEnd - order_.begin());
  std::uint32_t split = (low - t0 <= t1 - high) ? high : low;
  if (split == t0 || split == t1) split = split == low ? high : low;
  return split;
}

std::int32_t MeshHierarchy::build(const Mesh& mesh, const Components& components, std::uint32_t t0, std::uint32_t t1,
                                  int level, std::vector<std::uint32_t>& marks) {
  const std::int32_t index = static_cast<std::int32_t>(nodes_.size());
  nodes_.emplace_back();
  Node node;
  node.t0 = t0;
  node.t1 = t1;
  std::vector<Vec3> points;
  points.reserve(3 * (t1 - t0));
  for (std::uint32_t i = t0; i < t1; ++i) {
    for (int k = 0; k < 3; ++k) points.push_back(mesh.corner(order_[i], k));
  }
  node.box = principalBox(points);
  double nearest2 = std::numeric_limits<double>::infinity();
  for (std::uint32_t i = t0; i < t1; ++i) {
    for (std::uint32_t k = 0; k < 3; ++k) {
      const double d2 = (mesh.corner(order_[i], static_cast<int>(k)) - node.box.center).squaredNorm();
      if (d2 < nearest2) {
        nearest2 = d2;
        node.repTriangle = order_[i];
        node.repCorner = static_cast<std::uint16_t>(k);
      }
    }
  }
  node.repPoint = mesh.corner(node.repTriangle, static_cast<int>(node.repCorner));
  node.span = spanOf(components, node);
  if (t1 - t0 <= kLeafTriangles) {
    node.folded = isFolded(mesh, order_.data(), t0, t1);
    node.v0 = static_cast<std::uint32_t>(leafVertices_.size());
    for (std::uint32_t i = t0; i < t1; ++i) {
      for (std::uint32_t v : mesh.triangles()[order_[i]]) {
        if (marks[v] != static_cast<std::uint32_t>(index)) {
          marks[v] = static_cast<std::uint32_t>(index);
          leafVertices_.push_back(v);
        }
      }
    }
    node.v1 = static_cast<std::uint32_t>(leafVertices_.size());
    nodes_[index] = node;
    nodes_[index].convexSolid = node.span == ComponentSpan::whole && isConvexSolid(mesh, index);
    return index;
  }
  // Near the root, a node of several components is split between them, so that each component
  // below becomes one node (a closed convex one is then settled whole by GJK, Node::convexSolid);
  // else, and within a component, halve at the median centroid along the box's longest axis.
  int longest = 0;
  node.box.half.maxCoeff(&longest);
  const Vec3 axis = node.box.axes.col(longest);
  std::uint32_t mid = level <= kComponentSplitLevels ? splitBetweenComponents(components, t0, t1, axis) : t0;
  if (mid == t0) {
    auto key = [&](std::uint32_t t) { return axis.dot(mesh.corner(t, 0) + mesh.corner(t, 1) + mesh.corner(t, 2)); };
    mid = t0 + (t1 - t0) / 2;
    std::nth_element(order_.begin() + t0, order_.begin() + mid, order_.begin() + t1,
                     [&](std::uint32_t s, std::uint32_t t) { return key(s) < key(t); });
  }
  node.left = build(mesh, components, t0, mid, level + 1, marks);
  node.right = build(mesh, components, mid, t1, level + 1, marks);
  nodes_[index] = node;
  // After the subtree, whose boxes the check searches.
  nodes_[index].convexSolid = node.span == ComponentSpan::whole && isConvexSolid(mesh, index);
  return index;
}

void MeshHierarchy::refit(const Mesh& mesh) {
  // The axes stay; each node's extents are fitted anew to its own vertices, those of the leaves
  // below it, exactly as build fits them, so a refit to unmoved vertices gives the built boxes
  // back. Fitted to the corners of its children's refitted boxes instead, every level loosened
  // its box: an outside review's setVertices of the vertices a mesh already had made exact
  // queries 1.6-4.6 times slower (cow against bunny: 10 140 node pairs per 40 queries before,
  // 62 074 after), and a deforming mesh's refitted tree slower than no tree at all.
  // build makes the leaves depth first, so the leaves under a node hold one run of
  // leafVertices_, from its first leaf's v0 to its last leaf's v1; children come after their
  // parent in nodes_, so a backward sweep sees those runs before it needs them.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> run(nodes_.size());
  std::vector<Vec3> points;
  for (std::size_t i = nodes_.size(); i-- > 0;) {
    Node& n = nodes_[i];
    n.repPoint = mesh.corner(n.repTriangle, static_cast<int>(n.repCorner));
    if (n.isLeaf()) {
      n.folded = isFolded(mesh, order_.data(), n.t0, n.t1);  // a deformation may fold or flatten it
      run[i] = {n.v0, n.v1};
    } else {
      run[i] = {run[static_cast<std::size_t>(n.left)].first, run[static_cast<std::size_t>(n.right)].second};
    }
    points.clear();
    for (std::uint32_t k = run[i].first; k < run[i].second; ++k) points.push_back(mesh.vertices()[leafVertices_[k]]);
    fitExtents(n.box, points);
    // A deformation may dent it; the subtree's boxes are refitted already.
    if (n.span == ComponentSpan::whole) n.convexSolid = isConvexSolid(mesh, static_cast<std::int32_t>(i));
  }
  onHullBoundary_ = wholeMeshConvex(mesh);  // a deformation may dent a convex mesh
}

std::size_t MeshHierarchy::bytes() const {
  return sizeof(*this) + nodes_.capacity() * sizeof(Node) + order_.capacity() * sizeof(std::uint32_t) +
         leafVertices_.capacity() * sizeof(std::uint32_t) + positionInOrder_.capacity() * sizeof(std::uint32_t);
}

}  // namespace adsd
