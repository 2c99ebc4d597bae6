#pragma once
/// \file
/// \brief Running a third-party mesh reader (assimp) in a child process, so that what it does on a
/// damaged file (a crash, an abort, an endless loop, a runaway allocation) ends as an InputError
/// naming the file instead of ending or stalling the program that asked for the mesh.
///
/// Our own readers and checks are fuzzed and run under the sanitizers in CI; assimp's dozens of
/// format readers are not ours to fix, and adversarial sweeps found mutated .x, .md5mesh, .smd,
/// .cob, .lwo, .blend, .ase, .sib and 3MF files that crash or hang them (docs/reliability.md).

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "adsd/io/load_mesh.h"
#include "adsd/mesh.h"

namespace adsd::io::detail {

/// \brief The triangles a reader made of a file, with the counts of the line and point elements it
/// dropped (for the message when no triangle is left).
struct ReadTriangles {
  std::vector<Vec3> vertices;
  std::vector<TriangleIndices> triangles;
  std::uint64_t lines = 0;
  std::uint64_t points = 0;
};

/// \brief The limits ReaderLimits' zeros stand for, for a file of \p fileBytes bytes: 30 s plus
/// 1 s per MB (assimp parses tens of MB per second), and 4 GiB or 64 bytes per byte of the file,
/// whichever is more.
ReaderLimits effectiveLimits(const ReaderLimits& limits, std::uint64_t fileBytes);

/// \brief Runs \p read in a child process (fork) and returns what it read.
///
/// Throws InputError whose message starts with \p path when \p read throws (its message, or "out
/// of memory" for std::bad_alloc: the child's address space is capped at memoryBytes more than the
/// parent's, except in sanitizer builds, whose shadow memory cannot live under such a cap), when the
/// child is stopped by a signal (a crash or an abort in the reader), and when it has not finished
/// after \p limits' seconds (it is then killed). Where the system cannot make a process (fork
/// fails), \p read runs in this one instead, unguarded. \p read must not start threads.
ReadTriangles readInChildProcess(const std::string& path, const std::function<ReadTriangles()>& read,
                                 const ReaderLimits& limits);

}  // namespace adsd::io::detail
