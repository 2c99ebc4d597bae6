#include "adsd/planner/rigid_body_scene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>

#include "adsd/mesh_hierarchy.h"
#include "mesh_components.h"

namespace adsd::planner {

double robotRadius(const RigidBodyScene& scene) {
  double radius = 0.0;
  for (const Mesh& part : scene.robot) {
    for (const TriangleIndices& t : part.triangles()) {
      for (std::uint32_t v : t) radius = std::max(radius, part.vertices()[v].norm());
    }
  }
  return radius;
}

Eigen::AlignedBox3d environmentBounds(const RigidBodyScene& scene) {
  Eigen::AlignedBox3d box;
  for (const Mesh& part : scene.environment) box.extend(part.bounds());
  return box;
}

double sceneScale(const RigidBodyScene& scene) {
  Eigen::AlignedBox3d box = environmentBounds(scene);
  const double reach = robotRadius(scene);
  if (box.isEmpty()) return 2.0 * reach;
  box.min().array() -= reach;
  box.max().array() += reach;
  return box.diagonal().norm();
}

namespace {

using TriangleList = std::vector<std::size_t>;

Vec3 centroid(const Mesh& mesh, std::size_t t) {
  return (mesh.corner(t, 0) + mesh.corner(t, 1) + mesh.corner(t, 2)) / 3.0;
}

Eigen::AlignedBox3d boxOf(const Mesh& mesh, const TriangleList& triangles) {
  Eigen::AlignedBox3d box;
  for (std::size_t t : triangles) {
    for (int k = 0; k < 3; ++k) box.extend(mesh.corner(t, k));
  }
  return box;
}

/// Splits \p items (each with a point) at the median along the longest axis of their points' box,
/// the first part holding \p firstShare of them (0 < firstShare < 1).
template <typename Item, typename PointOf>
std::pair<std::vector<Item>, std::vector<Item>> medianSplit(std::vector<Item> items, double firstShare,
                                                            const PointOf& pointOf) {
  Eigen::AlignedBox3d box;
  for (const Item& i : items) box.extend(pointOf(i));
  Eigen::Index axis = 0;
  box.sizes().maxCoeff(&axis);
  const auto middle = items.begin() + static_cast<std::ptrdiff_t>(firstShare * static_cast<double>(items.size()));
  std::nth_element(items.begin(), middle, items.end(),
                   [&](const Item& a, const Item& b) { return pointOf(a)[axis] < pointOf(b)[axis]; });
  return {std::vector<Item>(items.begin(), middle), std::vector<Item>(middle, items.end())};
}

/// Cuts \p triangles into pieces whose boxes have a diagonal of at most \p maxDiagonal (or that
/// hold too few triangles to cut further), appending them to \p pieces.
void cutIntoPieces(const Mesh& mesh, TriangleList triangles, double maxDiagonal, std::vector<TriangleList>& pieces) {
  if (triangles.size() <= kMinPieceTriangles || !(boxOf(mesh, triangles).diagonal().norm() > maxDiagonal)) {
    pieces.push_back(std::move(triangles));
    return;
  }
  auto [first, second] =
      medianSplit(std::move(triangles), 0.5, [&mesh](std::size_t t) { return centroid(mesh, t); });
  cutIntoPieces(mesh, std::move(first), maxDiagonal, pieces);
  cutIntoPieces(mesh, std::move(second), maxDiagonal, pieces);
}

/// Makes meshes of some of a mesh's triangles, each keeping only the vertices its triangles use
/// (a vertex shared by two of them is copied into each). One per split: its vertex map, one
/// entry per vertex of the whole mesh, is made once.
class PartBuilder {
 public:
  explicit PartBuilder(const Mesh& mesh) : mesh_(mesh), remap_(mesh.vertices().size(), -1) {}

  void add(const TriangleList& triangles) {
    for (std::size_t t : triangles) {
      TriangleIndices out{};
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t v = mesh_.triangles()[t][k];
        if (remap_[v] < 0) {
          remap_[v] = static_cast<std::int64_t>(vertices_.size());
          vertices_.push_back(mesh_.vertices()[v]);
          used_.push_back(v);
        }
        out[k] = static_cast<std::uint32_t>(remap_[v]);
      }
      triangles_.push_back(out);
    }
  }

  /// The mesh of everything added since the last take().
  Mesh take(std::string name) {
    for (std::uint32_t v : used_) remap_[v] = -1;
    used_.clear();
    return Mesh(std::exchange(vertices_, {}), std::exchange(triangles_, {}), std::move(name));
  }

 private:
  const Mesh& mesh_;
  std::vector<std::int64_t> remap_;
  std::vector<std::uint32_t> used_;
  std::vector<Vec3> vertices_;
  std::vector<TriangleIndices> triangles_;
};

/// Whether the component \p triangles of \p mesh is kept whole: a small convex solid's boundary
/// (adsd::isClosedConvex: a box obstacle, a wall, a primitive cylinder) too thin for the robot
/// to fit inside (its width across some face, the largest height of a vertex above that face's
/// plane, is at most \p maxDiagonal, the robot's size). Such a component's hull holds no valid
/// robot pose, which is what cutting is for; cut, its pieces would be open, and the distance
/// query's answer for two convex meshes (GJK on their vertices, adsd/src/convex_pair.cpp) would
/// no longer hold for them. A room's shell, convex too, is as wide as the room: it is cut.
bool keptWhole(const TriangleList& triangles, double maxDiagonal, PartBuilder& builder) {
  // A closed convex polyhedron of V vertices has at most 2V - 4 triangles.
  if (triangles.size() > 2 * MeshHierarchy::kConvexCheckVertices) return false;
  builder.add(triangles);
  const Mesh component = builder.take("component");
  if (!isClosedConvex(component)) return false;
  double width = std::numeric_limits<double>::infinity();
  for (std::size_t t = 0; t < component.triangleCount(); ++t) {
    const Vec3 a = component.corner(t, 0);
    const Vec3 n = (component.corner(t, 1) - a).cross(component.corner(t, 2) - a);
    const double length = n.norm();
    if (!(length > 0.0)) continue;
    double height = 0.0;
    for (const Vec3& v : component.vertices()) height = std::max(height, std::abs(n.dot(v - a)) / length);
    width = std::min(width, height);
  }
  return width <= maxDiagonal;
}

/// \p triangles (a component of \p mesh) in patches joined only through edges that exactly two
/// triangles share. Boxes that touch at a corner, an edge or a face, which a loader merging
/// identical vertices joined into one component (the office's desks), come apart into boxes:
/// the edges where they meet belong to four triangles.
std::vector<TriangleList> manifoldPatches(const Mesh& mesh, const TriangleList& triangles) {
  std::vector<std::size_t> parent(triangles.size());
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  auto root = [&parent](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  // (edge, triangle) sorted by edge: the triangles of one edge are neighbours in the list.
  std::vector<std::pair<std::pair<std::uint32_t, std::uint32_t>, std::size_t>> edges;
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const TriangleIndices& t = mesh.triangles()[triangles[i]];
    for (int k = 0; k < 3; ++k) edges.push_back({std::minmax(t[k], t[(k + 1) % 3]), i});
  }
  std::sort(edges.begin(), edges.end());
  for (std::size_t first = 0; first < edges.size();) {
    std::size_t last = first;
    while (last < edges.size() && edges[last].first == edges[first].first) ++last;
    if (last - first == 2) parent[root(edges[first].second)] = root(edges[first + 1].second);
    first = last;
  }
  std::vector<std::int64_t> patchOfRoot(triangles.size(), -1);
  std::vector<TriangleList> patches;
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const std::size_t r = root(i);
    if (patchOfRoot[r] < 0) {
      patchOfRoot[r] = static_cast<std::int64_t>(patches.size());
      patches.emplace_back();
    }
    patches[static_cast<std::size_t>(patchOfRoot[r])].push_back(triangles[i]);
  }
  return patches;
}

/// Appends \p component's pieces: itself when it is kept whole (keptWhole), its patches when it
/// is such solids touching (manifoldPatches), else cutIntoPieces' pieces.
void piecesOfComponent(const Mesh& mesh, TriangleList component, double maxDiagonal, PartBuilder& builder,
                       std::vector<TriangleList>& pieces) {
  if (keptWhole(component, maxDiagonal, builder)) {
    pieces.push_back(std::move(component));
    return;
  }
  std::vector<TriangleList> patches = manifoldPatches(mesh, component);
  if (patches.size() > 1 && std::all_of(patches.begin(), patches.end(), [&](const TriangleList& patch) {
        return keptWhole(patch, maxDiagonal, builder);
      })) {
    for (TriangleList& patch : patches) pieces.push_back(std::move(patch));
    return;
  }
  cutIntoPieces(mesh, std::move(component), maxDiagonal, pieces);
}

/// Groups \p pieces (indices into \p centres) into exactly min(groups, pieces) spatially compact
/// groups, by median splits of their centres.
void groupPieces(std::vector<std::size_t> pieces, std::size_t groups, const std::vector<Vec3>& centres,
                 std::vector<std::vector<std::size_t>>& out) {
  if (groups <= 1 || pieces.size() <= 1) {
    out.push_back(std::move(pieces));
    return;
  }
  const std::size_t firstGroups = groups / 2;
  auto [first, second] = medianSplit(std::move(pieces), static_cast<double>(firstGroups) / static_cast<double>(groups),
                                     [&centres](std::size_t p) { return centres[p]; });
  groupPieces(std::move(first), firstGroups, centres, out);
  groupPieces(std::move(second), groups - firstGroups, centres, out);
}

}  // namespace

std::vector<Mesh> splitIntoParts(const Mesh& mesh, std::size_t maxParts, double maxPieceDiagonal) {
  std::vector<TriangleList> components = connectedComponents(mesh);
  // Large components cut into pieces: a room, a maze or a box the robot sits in has a convex hull
  // that holds the robot, so no hull-based bound can separate them; its pieces' hulls can.
  std::vector<TriangleList> pieces;
  PartBuilder builder(mesh);
  for (TriangleList& c : components) piecesOfComponent(mesh, std::move(c), maxPieceDiagonal, builder, pieces);
  if (pieces.size() <= 1) return {mesh};

  // Too many pieces: spatially compact groups of them (median splits of the pieces' centres).
  std::vector<std::vector<std::size_t>> groups;
  std::vector<std::size_t> all(pieces.size());
  std::iota(all.begin(), all.end(), 0);
  if (maxParts > 0 && pieces.size() > maxParts) {
    std::vector<Vec3> centres;
    for (const TriangleList& p : pieces) centres.push_back(boxOf(mesh, p).center());
    groupPieces(std::move(all), maxParts, centres, groups);
  } else {
    for (std::size_t p : all) groups.push_back({p});
  }

  std::vector<Mesh> parts;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    for (std::size_t p : groups[g]) builder.add(pieces[p]);
    parts.push_back(builder.take(mesh.name() + " part " + std::to_string(g)));
  }
  return parts;
}

std::string nameBeforeSplit(const std::string& partName) {
  const std::size_t part = partName.rfind(" part ");
  const bool numbered = part != std::string::npos && part + 6 < partName.size() &&
                        partName.find_first_not_of("0123456789", part + 6) == std::string::npos;
  return numbered ? partName.substr(0, part) : partName;
}

std::vector<Mesh> splitForRobot(const Mesh& environment, const std::vector<Mesh>& robot) {
  RigidBodyScene robotOnly;
  robotOnly.robot = robot;
  const double diameter = 2.0 * robotRadius(robotOnly);
  return splitIntoParts(environment, kMaxEnvironmentParts, kPieceDiagonalPerRobotDiameter * diameter);
}

Mesh recentreRobot(const Mesh& robot, RigidBodySpace space) {
  // OMPL.app takes the mean of all the (joined) vertices, not of the triangles' area: the classic
  // start poses were written against that mean (shared/OMPLAPP-CFG.md).
  Vec3 mean = Vec3::Zero();
  for (const Vec3& v : robot.vertices()) mean += v;
  mean /= static_cast<double>(robot.vertices().size());
  if (space == RigidBodySpace::se2) mean.z() = 0.0;
  std::vector<Vec3> moved = robot.vertices();
  for (Vec3& v : moved) v -= mean;
  return Mesh(std::move(moved), robot.triangles(), robot.name());
}

}  // namespace adsd::planner
