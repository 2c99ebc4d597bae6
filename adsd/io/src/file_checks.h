#pragma once
/// \file
/// \brief Checks on a mesh file made before assimp sees it: the commonest bad inputs get a precise
/// message instead of a parser's guess, and the inputs on which assimp 5.2 would hang, abort or
/// silently repair the data are stopped here.

#include <cstdint>
#include <string>
#include <string_view>

namespace adsd::io::detail {

/// \brief Everything below that applies to \p path (by its extension); throws InputError.
void checkBeforeAssimp(const std::string& path);

/// \brief Returns the size in bytes of \p path; throws InputError "PATH: ..." unless it is an
/// existing, regular, readable, non-empty file.
std::uintmax_t requireReadableFile(const std::string& path);

/// \brief For STL that is not ASCII (judged from \p head, the first bytes of the file): throws
/// InputError "PATH: ..." when the file is shorter than its 84-byte header or than the 50 bytes per
/// triangle the header promises.
///
/// Assimp only says "failed to determine STL storage representation" for such a file; a cut-off
/// download or copy is the usual cause, and the message should say so.
void requireCompleteBinaryStl(const std::string& path, std::string_view head, std::uintmax_t sizeInBytes);

/// \brief OFF read the way assimp reads it; throws InputError "PATH:LINE: ..." for anything its
/// reader would silently repair (see off_check.cpp).
void requireConsistentOff(const std::string& path, std::string_view text);

/// \brief PLY header and data walked; throws InputError "PATH:LINE: ..." (ASCII) or "PATH: ..."
/// (binary) for what assimp's reader would hang on, abort on, or misread (see ply_check.cpp).
void requireConsistentPly(const std::string& path, std::string_view bytes);

/// \brief COLLADA: every `<p>` index list holds integers and whitespace only, up to its `</p>`;
/// throws InputError "PATH:LINE: ..." otherwise (assimp would read such a list forever, growing
/// it until memory runs out; see collada_check.cpp).
void requireIntegerIndexLists(const std::string& path, std::string_view text);

}  // namespace adsd::io::detail
