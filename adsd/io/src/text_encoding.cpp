#include "adsd/io/text_encoding.h"

namespace adsd::io {

std::string wideTextEncoding(std::string_view bytes) {
  const auto startsWith = [&](std::string_view mark) { return bytes.substr(0, mark.size()) == mark; };
  // UTF-32LE's mark begins with UTF-16LE's, so it is asked first.
  if (startsWith(std::string_view("\xFF\xFE\0\0", 4))) return "UTF-32LE";
  if (startsWith(std::string_view("\0\0\xFE\xFF", 4))) return "UTF-32BE";
  if (startsWith("\xFF\xFE")) return "UTF-16LE";
  if (startsWith("\xFE\xFF")) return "UTF-16BE";
  return {};
}

}  // namespace adsd::io
