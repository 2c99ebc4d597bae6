#include "box_surface.h"

#include <array>
#include <map>

namespace adsd::shapes::detail {

Mesh boxSurface(const Vec3& halfExtents, int divisions, const std::string& name) {
  // Vertices live on the integer lattice {0..divisions}^3 scaled onto the box; keying them by
  // lattice point shares the vertices of neighbouring faces exactly (no welding tolerance).
  std::map<std::array<int, 3>, std::uint32_t> indexOf;
  std::vector<Vec3> vertices;
  auto vertex = [&](const std::array<int, 3>& lattice) {
    auto [it, inserted] = indexOf.emplace(lattice, static_cast<std::uint32_t>(vertices.size()));
    if (inserted) {
      Vec3 p;
      for (int axis = 0; axis < 3; ++axis) {
        p[axis] = halfExtents[axis] * (2.0 * lattice[axis] / divisions - 1.0);
      }
      vertices.push_back(p);
    }
    return it->second;
  };

  std::vector<TriangleIndices> triangles;
  for (int axis = 0; axis < 3; ++axis) {
    // (u, v, axis) is a cyclic permutation of (x, y, z), so e_u x e_v = e_axis: a square walked
    // u then v is counter-clockwise seen from +axis.
    const int u = (axis + 1) % 3;
    const int v = (axis + 2) % 3;
    for (int side : {0, divisions}) {
      const bool outwardIsPlus = side == divisions;
      for (int i = 0; i < divisions; ++i) {
        for (int j = 0; j < divisions; ++j) {
          auto corner = [&](int di, int dj) {
            std::array<int, 3> lattice{};
            lattice[axis] = side;
            lattice[u] = i + di;
            lattice[v] = j + dj;
            return vertex(lattice);
          };
          const std::uint32_t c00 = corner(0, 0), c10 = corner(1, 0), c11 = corner(1, 1), c01 = corner(0, 1);
          if (outwardIsPlus) {
            triangles.push_back({c00, c10, c11});
            triangles.push_back({c00, c11, c01});
          } else {
            triangles.push_back({c00, c11, c10});
            triangles.push_back({c00, c01, c11});
          }
        }
      }
    }
  }
  return Mesh(std::move(vertices), std::move(triangles), name);
}

}  // namespace adsd::shapes::detail
