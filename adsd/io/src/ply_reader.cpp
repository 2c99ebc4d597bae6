// PLY through CGAL's polygon-soup reader: ASCII and both binary byte orders, float or double
// vertex properties, read into double without loss (a float property becomes the double of the
// same value; ASCII numbers are read by the C++ library's stream extraction, correctly rounded,
// so 17 significant digits come back bit for bit). Measured against assimp (tests/io, docs/
// numerics.md): exact where assimp rounds to float, and faster on the Stanford dragon.
//
// CGAL says only "false" when it cannot read a file, and it accepts a face index beyond the
// vertex count; requireConsistentPly (ply_check.cpp) has walked the file first and named the line
// of anything malformed, so a failure here is a file that check let through.

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
