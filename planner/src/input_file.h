#pragma once
/// \file
/// \brief Internal: the whole text of an input file the user names (URDF, SRDF, scene, request,
/// problem), with one InputError for each way it can be missing. Not installed.

#include <string>

namespace adsd::planner {

/// \brief The whole of the file at \p path; a missing file, a directory, a device or a pipe, or an
/// unreadable file is an InputError naming it as \p what ("scene file").
std::string readInputFile(const std::string& path, const std::string& what);

/// \brief Removes a UTF-8 byte-order mark, which Windows editors write, from the start of \p text:
/// it is no part of the first line.
void dropByteOrderMark(std::string& text);

/// \brief Throws InputError "SOURCE: not a text file ..." when \p text holds a NUL byte, naming
/// the encoding when a byte-order mark shows a wide one (UTF-16 or UTF-32, as Windows Notepad may
/// save): "contains a NUL byte" alone left the user to guess.
void requireNarrowText(const std::string& text, const std::string& sourceName);

/// \brief Makes the line ends of a file of classic Mac OS text (CR alone, and no LF anywhere) LF,
/// as the mesh readers take them (adsd/io/src/text_scan.h); elsewhere a CR stays what it is.
void takeLoneCarriageReturnsAsLineEnds(std::string& text);

}  // namespace adsd::planner
