/// \file
/// \brief bench_mesh_info MESH...: what adsd::io::loadMesh (assimp) makes of each file: triangle and
/// vertex counts and the bounding-box diagonal. problems/data/fetch_meshes.sh --check uses it to
/// prove that every fetched mesh loads.

#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "adsd/cli/command_line.h"
#include "adsd/error.h"
#include "adsd/io/load_mesh.h"

namespace {

int run(const adsd::cli::Arguments& given) {
  const std::vector<std::string> paths = given.texts("mesh");
  if (paths.empty()) throw adsd::cli::UsageError("expected one or more mesh files");
  int status = 0;
  for (const std::string& path : paths) {
    try {
      const adsd::Mesh mesh = adsd::io::loadMesh(path);
      std::printf("%s%s%zu triangles, %zu vertices, bbox diagonal %.6g\n", paths.size() > 1 ? path.c_str() : "",
                  paths.size() > 1 ? ": " : "", mesh.triangleCount(), mesh.vertices().size(),
                  mesh.bounds().diagonal().norm());
    } catch (const adsd::InputError& e) {
      std::fprintf(stderr, "bench_mesh_info: %s\n", e.what());
      status = 2;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "bench_mesh_info: %s: %s\n", path.c_str(), e.what());
      status = 1;
    }
  }
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  adsd::cli::CommandLine line("bench_mesh_info", "bench_mesh_info MESH...",
                              "What assimp makes of each mesh file: triangles, vertices, bounding-box diagonal.",
                              "Exit status 0; 2 when a file cannot be read as a mesh; 1 on other failures.");
  line.positional("mesh");
  return adsd::cli::runProgram(line, argc, argv, run);
}
