// Binary PLY through CGAL's polygon-soup reader: both byte orders, float or double vertex
// properties, read into double without loss (a float property becomes the double of the same
// value, a double property the double as stored). Measured against assimp on the Stanford dragon
// written as binary PLY: exact where assimp rounds to float, and faster (docs/numerics.md).
//
// ASCII PLY is read by the check that walks the file first (ply_check.cpp): it parses every value
// already, through std::from_chars, while CGAL's ASCII path parses a "float" property with strtof,
// rounding the text to float, and took longer than assimp on the dragon. CGAL says only "false"
// when it cannot read a file and accepts a face index beyond the vertex count; checkPly has named
// the line or record of anything malformed before this runs.

#include <vector>

#include <CGAL/IO/PLY.h>
#include <CGAL/Simple_cartesian.h>

#include "adsd/error.h"
#include "file_checks.h"

namespace adsd::io::detail {

PolygonSoup readPly(const std::string& path) {
  using Point = CGAL::Simple_cartesian<double>::Point_3;
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  if (!CGAL::IO::read_PLY(path, points, polygons)) {
    throw InputError(path + ": CGAL's PLY reader could not read the file (its header and data looked well formed)");
  }
  if (points.size() >= UINT32_MAX) throw InputError(path + ": more than 2^32 - 1 vertices");
  PolygonSoup soup;
  soup.points.reserve(points.size());
  for (const Point& p : points) soup.points.emplace_back(p.x(), p.y(), p.z());
  soup.starts.reserve(polygons.size() + 1);
  for (const std::vector<std::size_t>& polygon : polygons) {
    for (const std::size_t corner : polygon) {
      // ply_check.cpp has checked every index against the vertex count; this guards the cast.
      if (corner >= soup.points.size()) throw InputError(path + ": a face refers to a vertex that does not exist");
      soup.addCorner(static_cast<std::uint32_t>(corner));
    }
    soup.closePolygon();
  }
  requireRepresentablePoints(soup, path);
  return soup;
}

}  // namespace adsd::io::detail
