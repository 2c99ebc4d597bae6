#pragma once
/// \file
/// \brief Reading meshes from files: OBJ, OFF, PLY and STL into double without loss; COLLADA and
/// every other format assimp reads through assimp, in float.

#include <cstdint>
#include <string>

#include "adsd/mesh.h"

namespace adsd::io {

/// \brief Bounds on assimp while it reads a file. Assimp runs in a child process (see loadMesh),
/// and one that passes either bound is stopped and the file refused with a message that says
/// which. A zero (or any value that is not a positive finite number) picks the default, sized by
/// the file.
struct ReaderLimits {
  /// Wall-clock seconds assimp may take; 0: 10 s plus 1 s per MB of the file (a 13-byte SMD file
  /// makes one of its readers loop; the 1.1 MB COLLADA torso of the Atlas robot takes 50 ms).
  double seconds = 0;
  /// Bytes of address space assimp may add to the process's; 0: 4 GiB or 64 times the file's
  /// size, whichever is more. Not applied in builds with a sanitizer (its shadow memory).
  std::uint64_t memoryBytes = 0;
};

/// \brief Which way up a COLLADA file's coordinates are read (no other format has an up axis).
enum class ColladaUpAxis {
  /// Assimp's default: a file whose <up_axis> is Z_UP (most exporters' choice) or X_UP is turned
  /// so that its up is +y. OMPL.app's problem meshes are loaded so, and mean the same to us.
  turnedToYUp,
  /// The coordinates as written, whatever <up_axis> says: how the ROS tools (RViz, MoveIt's
  /// geometric_shapes, Tesseract) read a URDF's meshes, in a link frame that is z up.
  asWritten,
};

/// \brief Loads every triangle of the file as one mesh.
///
/// The reader: .obj, .off, .ply and .stl (any case) go to ours; a file of any other name goes by
/// its first word ("ply", an OFF keyword, "solid"), else to assimp. Before assimp reads a file,
/// COLLADA (named .dae or holding "<COLLADA", or zipped: .zae or a zip holding a .dae, unzipped
/// with zlib first) has its index lists checked, so that no malformed file reaches assimp's
/// readers we know to crash or hang.
///
/// Precision, by format (docs/numerics.md has the measurement):
/// - OBJ, OFF, ASCII PLY, ASCII STL: every coordinate as the double nearest its decimal text
///   (std::from_chars), so 17 significant digits come back bit for bit; binary PLY with double
///   properties: the doubles as stored.
/// - binary STL, binary PLY with float properties: the file's float32 values, exactly.
/// - anything else (COLLADA .dae, glTF, 3DS, ...): through assimp, which stores coordinates in
///   float; node transforms are composed in double from assimp's float matrices. COLLADA <unit>
///   is applied; <up_axis> as \p up says.
///
/// Polygons become triangles (OBJ, OFF, PLY: fanned from the first corner; assimp: its own
/// triangulation); line and point elements are dropped; bit-identical vertices are shared and
/// unreferenced ones dropped, so counts match what assimp made of the same files; no coordinate
/// is changed. Zero-area triangles are kept, but a triangle that repeats another's three vertices
/// (in any order), or lies on a single vertex that another triangle has, is dropped: it adds no
/// point, and every tree query visited each copy (100,000 copies of one triangle: over a minute
/// for 20 queries). Through assimp, vertices are shared within each of its meshes only, so a
/// repeat across two of them stays. Triangle numbers (`adsd distance`'s witnesses) index the
/// loaded mesh.
///
/// Assimp runs in a child process of its own (fork), so that a reader of its that crashes,
/// aborts, loops or allocates without end on a damaged file (some do: docs/reliability.md) costs
/// an error message, not the calling program; \p limits bounds its time and memory. (Loading
/// while other threads run is safe as far as the C library's allocator goes; a lock of another
/// library held by another thread at that moment would stall the child until the time limit.)
///
/// Throws adsd::InputError, one line starting with the path (and ":LINE" where the format has
/// lines), for: a missing, unreadable, empty or non-regular file; a malformed line; a truncated
/// binary STL or PLY; a file assimp cannot parse, crashes on or does not finish within
/// \p limits; no triangles (only lines or points, say); a
/// vertex index out of range; a non-finite coordinate or one beyond +-tolerance::kMaxCoordinate
/// (1e75). Running out of memory is reported the same way.
Mesh loadMesh(const std::string& path, const ReaderLimits& limits = {},
              ColladaUpAxis up = ColladaUpAxis::turnedToYUp);

}  // namespace adsd::io
