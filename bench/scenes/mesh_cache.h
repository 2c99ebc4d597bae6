#pragma once
/// \file
/// \brief Where the benchmarks find the real meshes: the cache that
/// problems/data/fetch_meshes.sh fills.

#include <cstdlib>
#include <string>

namespace adsd::bench {

/// \brief The mesh cache directory: $ADSD_DATA_DIR if set, else $HOME/.cache/adsd/meshes (the
/// same rule as fetch_meshes.sh).
inline std::string meshCacheDir() {
  if (const char* dir = std::getenv("ADSD_DATA_DIR"); dir && *dir) return dir;
  const char* home = std::getenv("HOME");
  return std::string(home && *home ? home : ".") + "/.cache/adsd/meshes";
}

/// \brief Path of a cached mesh file by name (e.g. "cow.off").
inline std::string cachedMesh(const std::string& fileName) { return meshCacheDir() + "/" + fileName; }

/// \brief The hint printed when a cached mesh is missing.
inline std::string fetchHint() {
  return "fetch the real meshes first: problems/data/fetch_meshes.sh (cache: " + meshCacheDir() + ")";
}

}  // namespace adsd::bench
