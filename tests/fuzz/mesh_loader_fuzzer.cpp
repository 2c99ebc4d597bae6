// Fuzz target: adsd::io::loadMesh on a file of each documented format (OBJ, STL, PLY, OFF,
// COLLADA). The first byte picks the format (its value modulo 5 indexes kExtensions), the rest is
// the file. Properties: loadMesh returns a mesh of at least one triangle with finite coordinates
// and indices in range, or throws one adsd::InputError whose one-line message starts with the
// path; nothing else, no crash, no hang (libFuzzer's -timeout), no leak in our code.
#include <cmath>
#include <string>

#include "adsd/io/load_mesh.h"
#include "fuzz_support.h"

namespace {

/// The formats the loader documents, by the extension assimp picks its importer by.
const char* const kExtensions[] = {"obj", "stl", "ply", "off", "dae"};
constexpr std::size_t kFormatCount = sizeof(kExtensions) / sizeof(kExtensions[0]);

void requireUsableMesh(const adsd::Mesh& mesh) {
  if (mesh.triangleCount() == 0) adsd::fuzz::violation("loadMesh returned a mesh without triangles");
  for (const adsd::Vec3& v : mesh.vertices()) {
    if (!v.allFinite()) adsd::fuzz::violation("loadMesh returned a non-finite vertex");
  }
  for (const adsd::TriangleIndices& t : mesh.triangles()) {
    for (std::uint32_t i : t) {
      if (i >= mesh.vertices().size()) adsd::fuzz::violation("loadMesh returned an index out of range");
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const adsd::fuzz::ScratchDirectory scratch;
  if (size == 0) return 0;
  const char* extension = kExtensions[data[0] % kFormatCount];
  const std::string path = scratch.write(std::string("input.") + extension, data + 1, size - 1);
  // Assimp's child process gets less time than libFuzzer's -timeout (10 s), so that a reader
  // that loops is stopped and reported by the loader, as the property asks, not by libFuzzer.
  adsd::io::ReaderLimits limits;
  limits.seconds = 5;
  adsd::fuzz::acceptingOnlyInputError(path, [&] { requireUsableMesh(adsd::io::loadMesh(path, limits)); });
  return 0;
}
