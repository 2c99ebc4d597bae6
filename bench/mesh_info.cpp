/// \file
/// \brief bench_mesh_info MESH...: what adsd::io::loadMesh (assimp) makes of each file: triangle and
/// vertex counts and the bounding-box diagonal. problems/data/fetch_meshes.sh --check uses it to
/// prove that every fetched mesh loads.

#include <cstdio>
#include <exception>

#include "adsd/error.h"
#include "adsd/io/load_mesh.h"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: bench_mesh_info MESH...\n");
    return 2;
  }
  int status = 0;
  for (int i = 1; i < argc; ++i) {
    try {
      const adsd::Mesh mesh = adsd::io::loadMesh(argv[i]);
      std::printf("%s%s%zu triangles, %zu vertices, bbox diagonal %.6g\n", argc > 2 ? argv[i] : "", argc > 2 ? ": " : "",
                  mesh.triangleCount(), mesh.vertices().size(), mesh.bounds().diagonal().norm());
    } catch (const adsd::InputError& e) {
      std::fprintf(stderr, "bench_mesh_info: %s\n", e.what());
      status = 2;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "bench_mesh_info: %s: %s\n", argv[i], e.what());
      status = 1;
    }
  }
  return status;
}
