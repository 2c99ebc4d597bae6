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

/// \brief COLLADA: every `<p>` index list holds integers and whitespace only, up to its `</p>`;
/// throws InputError "PATH:LINE: ..." otherwise (assimp would read such a list forever, growing
/// it until memory runs out; see collada_check.cpp).
void requireIntegerIndexLists(const std::string& path, std::string_view text);

/// \brief The readers: exact into double, InputError "PATH:LINE: ..." on anything malformed.
PolygonSoup readObj(const std::string& path, std::string_view text);  ///< obj_reader.cpp
PolygonSoup readOff(const std::string& path, std::string_view text);  ///< off_reader.cpp
PolygonSoup readStl(const std::string& path, std::string_view bytes);  ///< stl_reader.cpp, after requireCompleteBinaryStl
PolygonSoup readPly(const std::string& path, std::string_view bytes);  ///< ply_reader.cpp, ASCII and binary

}  // namespace adsd::io::detail
