#pragma once
/// \file
/// \brief Telling a text file saved in a wide encoding (Windows Notepad may save UTF-16) from the
/// ASCII or UTF-8 every reader of adsd takes, so that the error can name it.

#include <string>
#include <string_view>

namespace adsd::io {

/// \brief The encoding a byte-order mark at the start of \p bytes names when it is a wide one
/// ("UTF-16LE", "UTF-16BE", "UTF-32LE", "UTF-32BE"), else empty: text the readers take for ASCII
/// or UTF-8 reads as NUL bytes between the characters, in which no keyword is found.
std::string wideTextEncoding(std::string_view bytes);

}  // namespace adsd::io
