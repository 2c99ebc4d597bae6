#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>

#include "adsd/error.h"
#include "adsd/problem_scenes.h"

namespace adsd::shapes {

Mesh centredOnVertexMean(const Mesh& mesh) {
  Vec3 mean = Vec3::Zero();
  for (const Vec3& v : mesh.vertices()) mean += v;
  mean /= static_cast<double>(mesh.vertices().size());
  std::vector<Vec3> moved = mesh.vertices();
  for (Vec3& v : moved) v -= mean;
  return Mesh(std::move(moved), mesh.triangles(), mesh.name());
}

void writeObj(const Mesh& mesh, const std::string& path) {
  const std::string temporary = path + ".partial";
  {
    std::ofstream out(temporary);
    if (!out) throw InputError(path + ": cannot write the mesh file");
    // 17 significant digits: the file holds the generator's doubles exactly.
    out << std::setprecision(17) << "# adsd problem mesh: " << mesh.triangleCount() << " triangles\n";
    for (const Vec3& v : mesh.vertices()) out << "v " << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
    for (const TriangleIndices& t : mesh.triangles()) out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
    out.flush();
    if (!out) {
      out.close();
      std::remove(temporary.c_str());
      throw InputError(path + ": writing the mesh file failed");
    }
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) {
    std::remove(temporary.c_str());
    throw InputError(path + ": cannot move the finished mesh file into place: " + ec.message());
  }
}

std::vector<ProblemScene> allProblemScenes() {
  return {officeScene(), mazeScene(), thinWallScene(), bugTrapScene(), twistedPassageScene(), alphaPuzzleScene(),
          cowDoorwayScene()};
}

}  // namespace adsd::shapes
