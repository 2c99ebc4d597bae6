#pragma once
/// \file
/// \brief The mesh readers of adsd::io (one per format read without assimp) and the checks on a
/// file made before a reader or assimp sees it: each names the file, and the line where the
/// format has lines.

#include <cstdint>
#include <string>
#include <string_view>

#include "polygon_soup.h"

namespace adsd::io::detail {

/// \brief Returns the size in bytes of \p path; throws InputError "PATH: ..." unless it is an
/// existing, regular, readable, non-empty file.
std::uintmax_t requireReadableFile(const std::string& path);

/// \brief The whole file, after requireReadableFile.
std::string readWholeFile(const std::string& path);

/// \brief Whether an STL file whose first bytes are \p head is binary: it does not start with
/// "solid", or it does but has control bytes in its first 512 (some exporters write "solid" into
/// the free-form header of a binary file, whose count and floats then show control bytes).
bool isBinaryStl(std::string_view head);

/// \brief For binary STL (judged from \p head, the first bytes of the file): throws InputError
/// "PATH: ..." when the file is not exactly its 84-byte header plus the 50 bytes per triangle the
/// header promises (a cut-off download or copy is the usual cause, and the message says so).
void requireCompleteBinaryStl(const std::string& path, std::string_view head, std::uintmax_t sizeInBytes);

/// \brief The extension of \p path in lower case, with its dot (".obj"); empty if it has none.
std::string lowerCaseExtension(const std::string& path);

/// \brief The reader a mesh file goes to: one of ours, or assimp.
enum class MeshReader { obj, off, ply, stl, assimp };

/// \brief The reader for \p path, whose content is \p bytes. The extension decides for .obj, .off,
/// .ply and .stl (any case). Any other file goes by its first bytes where they are a signature:
/// "ply" (any case: all assimp's PLY reader asks of a file), an OFF keyword, "solid" (ASCII STL).
/// Only what has none of these goes to assimp: above all no PLY, which assimp's reader can
/// crash, hang or abort on (the fuzz findings in ply_reader.cpp) whatever the file is called.
MeshReader chooseReader(const std::string& path, std::string_view bytes);

/// \brief Throws InputError "PATH: ..." naming the encoding and how to convert the file when
/// \p bytes, to be read by \p reader, start with a wide byte-order mark (a binary STL of the
/// exact size its header promises is binary, whatever its first bytes).
void requireNarrowText(const std::string& path, std::string_view bytes, MeshReader reader);

/// \brief Whether the first word of \p text, past blank and comment lines, is an OFF keyword
/// (OFF, COFF, NOFF, STOFF, 4OFF, ...). In off_reader.cpp.
bool startsWithOffKeyword(std::string_view text);

/// \brief Whether assimp could read \p path as COLLADA: it is named .dae, or its text holds
/// "<collada" in any case (with NUL bytes dropped, so UTF-16 text counts), which is what assimp
/// looks for in a file of any other name.
bool readAsCollada(const std::string& path, std::string_view bytes);

/// \brief For a zip archive of any name (assimp unzips .zae and 3MF, whatever the file is called):
/// every member unzipped (zip_archive.h) and matched against its checksum, and each member that is
/// COLLADA by name or content checked by requireIntegerIndexLists, its errors naming
/// "PATH (MEMBER):LINE". Throws InputError naming \p path for an archive whose members cannot be
/// read back, and for a .zae or a zip naming a .dae whose directory cannot be found.
void checkZippedCollada(const std::string& path, std::string_view bytes);

/// \brief COLLADA: every `<p>` index list holds integers and whitespace only, up to its `</p>`;
/// throws InputError "PATH:LINE: ..." otherwise (assimp would read such a list forever, growing
/// it until memory runs out; see collada_check.cpp). UTF-16 text is checked with its NUL bytes
/// dropped, which leaves the ASCII that matters here and every line where it was.
void requireIntegerIndexLists(const std::string& path, std::string_view text);

/// \brief The readers: exact into double, InputError "PATH:LINE: ..." on anything malformed.
PolygonSoup readObj(const std::string& path, std::string_view text);  ///< obj_reader.cpp
PolygonSoup readOff(const std::string& path, std::string_view text);  ///< off_reader.cpp
PolygonSoup readStl(const std::string& path, std::string_view bytes);  ///< stl_reader.cpp, after requireCompleteBinaryStl
PolygonSoup readPly(const std::string& path, std::string_view bytes);  ///< ply_reader.cpp, ASCII and binary

}  // namespace adsd::io::detail
