#pragma once
/// \file
/// \brief What a rigid motion does not change, kept between queries: a binary tree of sub-meshes.
///
/// The paper's algorithm needs no preprocessing, and deforming meshes use it as it is. A rigid
/// mesh queried thousands of times (a robot and its environment in a planner) pays for the same
/// splits and vertex scans on every query; this tree keeps them. Each node is a sub-mesh (a range
/// of a fixed triangle permutation) with its box in the mesh frame; leaves also list their
/// distinct vertices. Queries then (1) evaluate support mappings (eq. 4-5) by branch and bound
/// over the boxes instead of scanning every vertex, (2) split overlapping sub-mesh pairs (sec. 6)
/// along the tree instead of re-partitioning, and (3) gather the slab of stage two (sec. 5.3) by
/// descending only into boxes that reach it.

#include <cstdint>
#include <vector>

#include <Eigen/Geometry>

#include "adsd/mesh.h"

namespace adsd {

/// \brief A box of any orientation: axes (columns, unit, mesh frame), centre, half extents.
struct OrientedBox {
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  Vec3 center = Vec3::Zero();
  Vec3 half = Vec3::Zero();
  /// |half|: the radius of the circumscribed sphere, kept so that the traversal's first and
  /// cheapest test (box_separation.h) needs one square root instead of three.
  double radius = 0.0;
  /// \brief Largest d.x over the box (eq. 4 for a box).
  double support(const Vec3& d) const { return d.dot(center) + (axes.transpose() * d).cwiseAbs().dot(half); }
};

class MeshHierarchy {
 public:
  /// Leaves hold at most this many triangles: between two nodes this small a GJK run costs more
  /// than direct tests (a leaf may still meet a larger node by GJK, tree_traversal.cpp).
  static constexpr std::uint32_t kLeafTriangles = 4;
  /// Splits between whole components (Node::span) happen only this near the root;
  /// deeper, every split halves a node's triangles (the median).
  static constexpr int kComponentSplitLevels = 24;
  /// No path from the root to a leaf has more nodes than this: at most kComponentSplitLevels
  /// component splits, then halvings, of which a mesh of fewer than 2^32 triangles needs at most
  /// 31 to reach kLeafTriangles. Searches down the tree keep a fixed stack of this size.
  static constexpr int kMaxTreeLevels = kComponentSplitLevels + 32;
  /// A leaf is folded when two of its triangles' normals are more than this apart (cosine 0.5,
  /// 60 degrees): the faces of a box meet at 90, a plate's sides at 180, while a capsule of 32
  /// segments turns 11.25 degrees per strip and a fine scanned mesh less still.
  static constexpr double kFoldCosine = 0.5;
  /// Meshes and components of at most this many vertices (by triangles: twice as many, for a
  /// closed mesh) are checked for lying on their convex hull's boundary (onHullBoundary,
  /// Node::convexSolid): a box obstacle or robot part (8), the bug trap's round robot (130), a
  /// capsule of 32 segments (546), a convex part of a decomposed model or a primitive link of an
  /// arm. The check searches the subtree's boxes once per triangle when the tree is built or
  /// refitted (a capsule of 970 vertices: about 3 ms, timed by building it in a loop); GJK on
  /// the whole mesh scans every vertex per support (convex_pair.cpp).
  static constexpr std::size_t kConvexCheckVertices = 1024;

  /// Where a node stands among the mesh's connected components.
  enum class ComponentSpan : std::uint8_t {
    part,    ///< within one component, not all of it
    whole,   ///< exactly one whole component
    several  ///< more than one component, each whole
  };

  struct Node {
    /// Bounds of the node's vertices, mesh frame: oriented along their principal axes, which fit
    /// thin and slanted parts far more tightly than axis-aligned boxes (the reason FCL's OBB
    /// trees answer collision queries fast).
    OrientedBox box;
    std::uint32_t t0 = 0, t1 = 0; ///< triangles order()[t0, t1)
    std::uint32_t v0 = 0, v1 = 0; ///< leaves: distinct vertices leafVertices()[v0, v1)
    /// A point of the node's own surface, corner `repCorner` of triangle `repTriangle` (the
    /// corner nearest the box centre): two nodes' points are a real distance between the meshes,
    /// the traversal's cheap upper bound and ordering estimate for a node pair (sec. 4's upper
    /// bound from support points, taken from the tree instead of GJK).
    std::uint32_t repTriangle = 0;
    std::uint8_t repCorner = 0;
    /// Leaves: whether two of the leaf's triangles face directions more than 60 degrees apart (kFoldCosine)
    /// (a fold: a box's edge or corner, a thin plate's two sides). A node near one face of a fold
    /// is far from the others, so the traversal bounds a folded leaf's triangles one by one
    /// (tree_traversal.cpp, worthNarrowing); a flat or gently curved leaf is bounded by its box.
    std::uint8_t folded = 0;
    /// How the node's triangles lie among the mesh's connected components (by shared vertices: a
    /// box obstacle of an environment given as one mesh, a separate part of a model). The tree
    /// keeps components whole near the root (build), so each is one node.
    ComponentSpan span = ComponentSpan::part;
    /// Whether the node is a whole component that is closed and convex (isClosedConvex on its
    /// triangles): the distance between two such nodes is their hulls' while these are apart,
    /// and queries settle such a pair by GJK on the two nodes (tree_traversal.cpp) instead of
    /// opening it.
    std::uint8_t convexSolid = 0;
    /// That corner's position (mesh frame), kept beside the box: the traversal reads it for every
    /// node pair it tests, and through the triangle and vertex arrays that is two dependent loads
    /// from memory the box did not bring into cache.
    Vec3 repPoint = Vec3::Zero();
    std::int32_t left = -1, right = -1;  ///< children, -1 for a leaf
    bool isLeaf() const { return left < 0; }
  };

  /// \brief Builds the tree: median splits of triangle centroids along the longest box axis.
  /// Throws nothing but std::bad_alloc.
  explicit MeshHierarchy(const Mesh& mesh);

  /// \brief New boxes for moved vertices (same mesh topology); the tree itself is kept.
  void refit(const Mesh& mesh);

  const std::vector<Node>& nodes() const { return nodes_; }
  const std::vector<std::uint32_t>& order() const { return order_; }
  const std::vector<std::uint32_t>& leafVertices() const { return leafVertices_; }
  /// \brief Where each triangle stands in order(): triangle t belongs to node n exactly when
  /// n.t0 <= positionInOrder()[t] < n.t1 (the traversal asks whether a node pair holds the nearest
  /// triangle pair found so far).
  const std::vector<std::uint32_t>& positionInOrder() const { return positionInOrder_; }
  /// \brief Bytes kept between queries (for the memory figure of issue 6).
  std::size_t bytes() const;
  /// \brief Whether the mesh is small (kConvexCheckVertices), closed (every edge in two
  /// triangles) and every triangle's plane has all its vertices on one side: it is then its
  /// convex hull's boundary (a box, a convex part). Between two such meshes the distance is their
  /// hulls' while the hulls are apart (GJK on the vertices), and queries try that first
  /// (convex_pair.cpp), which proves it or leaves the query to the traversal.
  bool onHullBoundary() const { return onHullBoundary_; }  // wholeMeshConvex

 private:
  /// The mesh's connected components (triangles sharing a vertex, transitively), needed only
  /// while the tree is built: per triangle its component, per component its triangle count and
  /// centroid. Refit needs none of it (a node's span cannot change with the vertices).
  struct Components {
    std::vector<std::uint32_t> ofTriangle;
    std::vector<std::uint32_t> size;
    std::vector<Vec3> centroid;
  };

  std::int32_t build(const Mesh& mesh, const Components& components, std::uint32_t t0, std::uint32_t t1, int level,
                     std::vector<std::uint32_t>& marks);
  /// Where to split order_[t0, t1), which holds more than one component, between whole components
  /// (reordering the range): the components ordered along \p axis by their centroids, cut near
  /// the middle triangle. Returns t0 when the range is one component.
  std::uint32_t splitBetweenComponents(const Components& components, std::uint32_t t0, std::uint32_t t1,
                                       const Vec3& axis);
  /// Where triangles order_[node.t0, node.t1) stand among the components.
  ComponentSpan spanOf(const Components& components, const Node& node) const;
  /// Whether a whole component's node (its subtree built or refitted) is closed and convex
  /// (Node::convexSolid).
  bool isConvexSolid(const Mesh& mesh, std::int32_t index) const;
  /// onHullBoundary's value once the tree is built or refitted.
  bool wholeMeshConvex(const Mesh& mesh) const;
  /// Whether no vertex under node \p index has d.x above \p level.
  bool nothingBeyond(const Mesh& mesh, std::int32_t index, const Vec3& d, double level) const;

  std::vector<Node> nodes_;
  std::vector<std::uint32_t> order_;
  std::vector<std::uint32_t> leafVertices_;
  std::vector<std::uint32_t> positionInOrder_;
  bool onHullBoundary_ = false;
};

/// \brief Whether \p mesh has at most MeshHierarchy::kConvexCheckVertices vertices, is closed
/// (every edge, by vertex index, in exactly two triangles) and every triangle with an area has all
/// vertices on one side of its plane (up to 1e-9 of the mesh's extent): the boundary of a convex
/// solid, such as a box or a primitive cylinder. False for larger meshes, which are not checked.
bool isClosedConvex(const Mesh& mesh);

}  // namespace adsd
